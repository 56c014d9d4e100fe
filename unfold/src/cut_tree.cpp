// Incremental cut-tree state. Faces are placed by rigid motions of their canonical flat triangles, so
// every flat triangle stays congruent to its 3D face; moving a subtree or a piece applies one rigid
// motion to its faces and re-tests only those faces against the overlap index.
#include "foldkit/unfold/cut_tree.hpp"

#include <algorithm>
#include <cmath>

#include "foldkit/unfold/curvature.hpp"
#include "foldkit/unfold/dual_graph.hpp"
#include "foldkit/unfold/overlap.hpp"

namespace foldkit::unfold {

UnfoldContext make_context(const Mesh& mesh, const CutOptions& cuts) {
  UnfoldContext ctx;
  ctx.mesh = &mesh;
  const int nf = mesh.num_faces();
  ctx.canonical.resize(nf);
  for (int f = 0; f < nf; ++f) {
    auto p = mesh.corners(f);
    Vec3 d1 = p[1] - p[0], d2 = p[2] - p[0];
    double a = norm(d1);
    Vec3 u = a > 0 ? d1 / a : Vec3{1, 0, 0};
    double x2 = dot(d2, u);
    double y2 = norm(cross(u, d2));
    ctx.canonical[f] = {Vec2{0, 0}, Vec2{a, 0}, Vec2{x2, y2}};
  }
  auto classes = classify_vertices(mesh);
  ctx.required_cuts.resize(classes.size());
  for (std::size_t v = 0; v < classes.size(); ++v) {
    switch (classes[v]) {
      case VertexClass::Hyperbolic:
        ctx.required_cuts[v] = 2;
        break;
      case VertexClass::Elliptic:
      case VertexClass::Flat:
        ctx.required_cuts[v] = 1;
        break;
      case VertexClass::Boundary:
        ctx.required_cuts[v] = 0;
        break;
    }
  }
  ctx.weight = cut_weights(mesh, cuts);
  ctx.eps = 0.5 * overlap_tolerance(ctx.canonical);
  ctx.cell_size = suggested_cell_size(ctx.canonical);
  return ctx;
}

CutTree::CutTree(const UnfoldContext& context, EdgeStates state)
    : ctx_(&context),
      state_(std::move(state)),
      index_(context.mesh->num_faces(), context.cell_size, context.eps) {
  const Mesh& m = *ctx_->mesh;
  const int nf = m.num_faces(), ne = m.num_edges();
  state_.resize(ne, EdgeState::Cut);
  for (EdgeId e : all_ids<EdgeId>(ne))
    if (m.edge(e).boundary()) state_[e] = EdgeState::Cut;
  piece_.assign(nf, -1);
  partners_.assign(nf, {});
  hot_pos_.assign(nf, -1);
  side_mark_.assign(nf, 0);
  parent_.assign(nf, -1);
  parent_edge_.assign(nf, -1);
  depth_.assign(nf, 0);
  const std::vector<Triangle2> tri = lay_out_pieces();
  count_cuts();
  index_all(tri);
}

std::vector<Triangle2> CutTree::lay_out_pieces() {
  const int nf = num_faces();
  std::vector<Triangle2> tri(nf);
  std::vector<int> queue;
  queue.reserve(nf);
  for (int root = 0; root < nf; ++root) {
    if (piece_[root] >= 0) continue;
    int id = new_piece_id();
    ++piece_count_;
    piece_[root] = id;
    tri[root] = ctx_->canonical[root];
    queue.assign(1, root);
    parent_edge_[root] = -1;
    for (std::size_t head = 0; head < queue.size(); ++head)
      place_fold_neighbours(queue[head], id, tri, queue);
    piece_size_[id] = static_cast<int>(queue.size());
  }
  return tri;
}

void CutTree::place_fold_neighbours(int f, int id, std::vector<Triangle2>& tri, std::vector<int>& queue) {
  const Mesh& m = *ctx_->mesh;
  auto pos = [](const Triangle2& t, const std::array<int, 3>& face, int v) {
    for (int i = 0; i < 3; ++i)
      if (face[i] == v) return t[i];
    return t[0];
  };
  for (int e : m.face_edges[f]) {
    if (!folded(e) || e == parent_edge_[f]) continue;
    int g = across(e, f);
    if (piece_[g] >= 0) {
      state_[EdgeId(e)] = EdgeState::Cut;  // closes a cycle: a forest cannot fold it
      continue;
    }
    piece_[g] = id;
    parent_edge_[g] = e;
    // Place g by the motion taking its canonical copy of e onto f's placed copy.
    const auto& fg = m.faces[g];
    int v0 = m.edges[e].v[0], v1 = m.edges[e].v[1];
    const RigidMotion r = motion_onto(pos(ctx_->canonical[g], fg, v0), pos(ctx_->canonical[g], fg, v1),
                                      pos(tri[f], m.faces[f], v0), pos(tri[f], m.faces[f], v1));
    for (int i = 0; i < 3; ++i)
      tri[g][i] = r(ctx_->canonical[g][i]);
    queue.push_back(g);
  }
}

void CutTree::count_cuts() {
  const Mesh& m = *ctx_->mesh;
  cut_count_.assign(m.num_vertices(), 0);
  for (int e = 0; e < m.num_edges(); ++e) {
    if (folded(e)) continue;
    ++cut_count_[m.edges[e].v[0]];
    ++cut_count_[m.edges[e].v[1]];
  }
}

void CutTree::index_all(const std::vector<Triangle2>& tri) {
  for (int f = 0; f < num_faces(); ++f) {
    index_.query(
        tri[f], piece_[f], [](int) { return false; },
        [&](int g) {
          add_pair(f, g);
          return true;
        });
    index_.insert(f, piece_[f], tri[f]);
  }
}

FaceId CutTree::across(EdgeId e, FaceId f) const {
  const auto& edge = ctx_->mesh->edge(e);
  return edge.face_id(0) == f ? edge.face_id(1) : edge.face_id(0);
}

bool CutTree::curvature_allows_fold(EdgeId e) const {
  const auto& edge = ctx_->mesh->edge(e);
  if (edge.boundary()) return false;
  for (int v : edge.v)
    if (cut_count_[v] - 1 < ctx_->required_cuts[v]) return false;
  return true;
}

bool CutTree::curvature_allows_move(EdgeId cut, EdgeId fold) const {
  const auto& ends = ctx_->mesh->edge(cut).v;
  for (int v : ctx_->mesh->edge(fold).v) {
    const int after = cut_count_[v] - 1 + ((v == ends[0] || v == ends[1]) ? 1 : 0);
    if (after < ctx_->required_cuts[v]) return false;
  }
  return true;
}

Vec2 CutTree::corner_position(int f, int v) const {
  const auto& face = ctx_->mesh->faces[f];
  const Triangle2& t = index_.triangle(f);
  for (int i = 0; i < 3; ++i)
    if (face[i] == v) return t[i];
  return t[0];
}

RigidMotion CutTree::glue_motion(EdgeId e, int moving, int fixed) const {
  int v0 = ctx_->mesh->edge(e).v[0], v1 = ctx_->mesh->edge(e).v[1];
  RigidMotion r = motion_onto(corner_position(moving, v0), corner_position(moving, v1),
                              corner_position(fixed, v0), corner_position(fixed, v1));
  if (r.c != 1 || r.s != 0) {
    // Renormalise so the motion stays a rotation to the last bit, whatever the rounding above.
    double k = std::hypot(r.c, r.s);
    r.c /= k;
    r.s /= k;
  }
  return r;
}

void CutTree::add_pair(int f, int g) {
  for (int x : {f, g}) {
    int y = x == f ? g : f;
    partners_[x].push_back(y);
    if (partners_[x].size() == 1) {
      hot_pos_[x] = static_cast<int>(hot_.size());
      hot_.push_back(x);
    }
  }
  ++overlap_pairs_;
}

void CutTree::remove_pair(int f, int g) {
  for (int x : {f, g}) {
    int y = x == f ? g : f;
    auto& p = partners_[x];
    auto it = std::find(p.begin(), p.end(), y);
    if (it == p.end()) continue;
    *it = p.back();
    p.pop_back();
    if (p.empty()) {
      int pos = hot_pos_[x];
      hot_[pos] = hot_.back();
      hot_pos_[hot_[pos]] = pos;
      hot_.pop_back();
      hot_pos_[x] = -1;
    }
  }
  --overlap_pairs_;
}

int CutTree::new_piece_id() {
  if (!free_pieces_.empty()) {
    int id = free_pieces_.back();
    free_pieces_.pop_back();
    return id;
  }
  piece_size_.push_back(0);
  return static_cast<int>(piece_size_.size()) - 1;
}

void CutTree::collect_piece(int f, std::vector<int>& faces) {
  // A piece is a tree of fold edges, so remembering the edge each face was reached through is
  // enough to never walk back; side_mark_ is left alone so in_side stays valid.
  const Mesh& m = *ctx_->mesh;
  faces.assign(1, f);
  via_.assign(1, -1);
  for (std::size_t head = 0; head < faces.size(); ++head) {
    int x = faces[head], from = via_[head];
    for (int e : m.face_edges[x]) {
      if (!folded(e) || e == from) continue;
      faces.push_back(across(e, x));
      via_.push_back(e);
    }
  }
}

void CutTree::rebuild_parents() {
  const Mesh& m = *ctx_->mesh;
  const int nf = num_faces();
  std::fill(parent_.begin(), parent_.end(), -2);
  std::vector<int>& queue = queue_a_;
  for (int root = 0; root < nf; ++root) {
    if (parent_[root] != -2) continue;
    parent_[root] = -1;
    parent_edge_[root] = -1;
    depth_[root] = 0;
    queue.assign(1, root);
    for (std::size_t head = 0; head < queue.size(); ++head) {
      int f = queue[head];
      for (int e : m.face_edges[f]) {
        if (!folded(e) || e == parent_edge_[f]) continue;
        int g = across(e, f);
        if (parent_[g] != -2) continue;
        parent_[g] = f;
        parent_edge_[g] = e;
        depth_[g] = depth_[f] + 1;
        queue.push_back(g);
      }
    }
  }
  parents_dirty_ = false;
}

std::vector<EdgeId> CutTree::path(FaceId face_f, FaceId face_g) {
  if (parents_dirty_) rebuild_parents();
  int f = face_f.index(), g = face_g.index();
  std::vector<EdgeId> up_f, up_g;
  while (depth_[f] > depth_[g]) {
    up_f.emplace_back(parent_edge_[f]);
    f = parent_[f];
  }
  while (depth_[g] > depth_[f]) {
    up_g.emplace_back(parent_edge_[g]);
    g = parent_[g];
  }
  while (f != g && f >= 0 && g >= 0) {
    up_f.emplace_back(parent_edge_[f]);
    f = parent_[f];
    up_g.emplace_back(parent_edge_[g]);
    g = parent_[g];
  }
  up_f.insert(up_f.end(), up_g.rbegin(), up_g.rend());
  return up_f;
}

void CutTree::smaller_side(EdgeId edge, std::vector<int>& side) {
  const int e = edge.index();
  const Mesh& m = *ctx_->mesh;
  if (mark_counter_ >= 0xFFFFFFF0u) {
    std::fill(side_mark_.begin(), side_mark_.end(), 0);
    mark_counter_ = 0;
  }
  const std::uint32_t sa = mark_counter_ + 1, sb = mark_counter_ + 2;
  mark_counter_ += 2;
  int a = m.edges[e].face[0], b = m.edges[e].face[1];
  queue_a_.assign(1, a);
  queue_b_.assign(1, b);
  side_mark_[a] = sa;
  side_mark_[b] = sb;
  std::size_t ha = 0, hb = 0;
  // Grow both sides one face at a time: the first to run out is the smaller, found in time
  // proportional to its size rather than the piece's.
  auto step = [&](std::vector<int>& q, std::size_t& h, std::uint32_t s) {
    int f = q[h++];
    for (int x : m.face_edges[f]) {
      if (!folded(x) || x == e) continue;
      int g = across(x, f);
      if (side_mark_[g] == s) continue;
      side_mark_[g] = s;
      q.push_back(g);
    }
  };
  while (true) {
    if (ha == queue_a_.size()) {
      side.assign(queue_a_.begin(), queue_a_.end());
      side_stamp_ = sa;
      break;
    }
    if (hb == queue_b_.size()) {
      side.assign(queue_b_.begin(), queue_b_.end());
      side_stamp_ = sb;
      break;
    }
    step(queue_a_, ha, sa);
    step(queue_b_, hb, sb);
  }
}

int CutTree::cross_overlaps(const std::vector<int>& side) const {
  int n = 0;
  for (int f : side)
    for (int g : partners_[f])
      if (!in_side(g)) ++n;
  return n;
}

int CutTree::reattach_cost(const std::vector<int>& side, EdgeId attach, int limit) {
  const auto& edge = ctx_->mesh->edge(attach);
  int moving = in_side(edge.face[0]) ? edge.face[0] : edge.face[1];
  int fixed = moving == edge.face[0] ? edge.face[1] : edge.face[0];
  RigidMotion r = glue_motion(attach, moving, fixed);
  int count = 0;
  for (int f : side) {
    const Triangle2& t = index_.triangle(f);
    Triangle2 moved{r(t[0]), r(t[1]), r(t[2])};
    index_.query(
        moved, piece_[f], [this](int g) { return in_side(g); }, [&](int) { return ++count <= limit; });
    if (count > limit) break;
  }
  return count;
}

void CutTree::move_faces(const std::vector<int>& faces, const RigidMotion& r, int new_piece) {
  std::vector<Triangle2> moved(faces.size());
  for (std::size_t i = 0; i < faces.size(); ++i) {
    const Triangle2& t = index_.triangle(faces[i]);
    moved[i] = {r(t[0]), r(t[1]), r(t[2])};
  }
  for (int f : faces)
    index_.remove(f);
  for (std::size_t i = 0; i < faces.size(); ++i) {
    int f = faces[i];
    index_.query(
        moved[i], new_piece, [](int) { return false; },
        [&](int g) {
          add_pair(f, g);
          return true;
        });
  }
  for (std::size_t i = 0; i < faces.size(); ++i) {
    piece_[faces[i]] = new_piece;
    index_.insert(faces[i], new_piece, moved[i]);
  }
}

void CutTree::reattach(const std::vector<int>& side, EdgeId cut_edge, EdgeId attach) {
  const Mesh& m = *ctx_->mesh;
  const auto& edge = m.edge(attach);
  int moving = in_side(edge.face[0]) ? edge.face[0] : edge.face[1];
  int fixed = moving == edge.face[0] ? edge.face[1] : edge.face[0];
  RigidMotion r = glue_motion(attach, moving, fixed);
  for (int f : side) {
    for (std::size_t i = partners_[f].size(); i-- > 0;) {
      int g = partners_[f][i];
      if (!in_side(g)) remove_pair(f, g);
    }
  }
  move_faces(side, r, piece_[fixed]);
  state_[cut_edge] = EdgeState::Cut;
  for (int v : m.edge(cut_edge).v)
    ++cut_count_[v];
  state_[attach] = EdgeState::Fold;
  for (int v : edge.v)
    --cut_count_[v];
  parents_dirty_ = true;
}

void CutTree::cut(EdgeId e) {
  const Mesh& m = *ctx_->mesh;
  smaller_side(e, moved_);
  int old_piece = piece_[moved_[0]];
  for (int f : moved_) {
    for (std::size_t i = partners_[f].size(); i-- > 0;) {
      int g = partners_[f][i];
      if (!in_side(g)) remove_pair(f, g);
    }
  }
  int id = new_piece_id();
  for (int f : moved_) {
    Triangle2 t = index_.triangle(f);
    index_.remove(f);
    piece_[f] = id;
    index_.insert(f, id, t);
  }
  piece_size_[id] = static_cast<int>(moved_.size());
  piece_size_[old_piece] -= static_cast<int>(moved_.size());
  ++piece_count_;
  state_[e] = EdgeState::Cut;
  for (int v : m.edge(e).v)
    ++cut_count_[v];
  parents_dirty_ = true;
}

int CutTree::stitch_cost(EdgeId e, int limit) {
  const auto& edge = ctx_->mesh->edge(e);
  int a = edge.face[0], b = edge.face[1];
  int moving = piece_size_[piece_[a]] <= piece_size_[piece_[b]] ? a : b;
  int fixed = moving == a ? b : a;
  collect_piece(moving, moved_);
  RigidMotion r = glue_motion(e, moving, fixed);
  const int target = piece_[fixed];
  int count = 0;
  for (int f : moved_) {
    const Triangle2& t = index_.triangle(f);
    Triangle2 moved{r(t[0]), r(t[1]), r(t[2])};
    index_.query(
        moved, target, [](int) { return false; }, [&](int) { return ++count <= limit; });
    if (count > limit) break;
  }
  return count;
}

void CutTree::stitch(EdgeId e) {
  const Mesh& m = *ctx_->mesh;
  const auto& edge = m.edge(e);
  int a = edge.face[0], b = edge.face[1];
  int moving = piece_size_[piece_[a]] <= piece_size_[piece_[b]] ? a : b;
  int fixed = moving == a ? b : a;
  collect_piece(moving, moved_);
  RigidMotion r = glue_motion(e, moving, fixed);
  int from = piece_[moving], to = piece_[fixed];
  move_faces(moved_, r, to);
  piece_size_[to] += piece_size_[from];
  piece_size_[from] = 0;
  free_pieces_.push_back(from);
  --piece_count_;
  state_[e] = EdgeState::Fold;
  for (int v : edge.v)
    --cut_count_[v];
  parents_dirty_ = true;
}

}  // namespace foldkit::unfold
