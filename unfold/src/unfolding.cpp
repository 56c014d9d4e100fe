#include "foldkit/unfold/unfolding.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <queue>
#include <sstream>

#include "foldkit/unfold/disjoint_sets.hpp"
#include "foldkit/unfold/overlap.hpp"

namespace foldkit::unfold {
namespace {

// Where the third corner of a triangle lies relative to its edge p->q: distance along the edge and
// (positive) distance to its left, taken from the 3D corners so that lengths are exact.
Vec2 apex_in_edge_frame(Vec3 p, Vec3 q, Vec3 r) {
  Vec3 u = normalized(q - p);
  Vec3 pr = r - p;
  return {dot(pr, u), norm(cross(u, pr))};
}

}  // namespace

std::vector<std::vector<int>> Unfolding::piece_faces() const {
  std::vector<std::vector<int>> pieces(static_cast<std::size_t>(piece_count));
  for (int f = 0; f < num_faces(); ++f)
    pieces[piece_of_face[f]].push_back(f);
  return pieces;
}

EdgeStates edge_states(const Unfolding& unfolding) {
  EdgeStates state(static_cast<int>(unfolding.edges.size()), EdgeState::Fold);
  for (EdgeId e : all_ids<EdgeId>(state.size()))
    if (unfolding.edges[e.index()].cut) state[e] = EdgeState::Cut;
  return state;
}

int Unfolding::seam_count() const {
  return static_cast<int>(
      std::count_if(edges.begin(), edges.end(), [](const UnfoldEdge& e) { return e.glued_seam(); }));
}

Unfolding flatten(const Mesh& mesh, const EdgeStates& state) {
  const int nf = mesh.num_faces();
  Unfolding u;
  u.flat.assign(nf, Triangle2{});
  u.piece_of_face.assign(nf, -1);
  u.face_edges = mesh.face_edges;
  u.edges.resize(mesh.edges.size());
  for (int e = 0; e < mesh.num_edges(); ++e) {
    const MeshEdge& me = mesh.edges[e];
    UnfoldEdge& ue = u.edges[e];
    ue.face = me.face;
    ue.corner = me.corner;
    ue.cut = me.boundary() || (e < state.size() && state[EdgeId(e)] == EdgeState::Cut);
    ue.fold_angle = fold_angle(mesh, e);
    ue.length = edge_length(mesh, e);
  }
  if (!mesh.vertices.empty()) u.model_extent = bounds_of(mesh).largest_dimension();

  std::vector<int> parent_edge(nf, -1);
  std::queue<int> queue;
  for (int root = 0; root < nf; ++root) {
    if (u.piece_of_face[root] >= 0) continue;
    const int piece = u.piece_count++;
    auto c = mesh.corners(root);
    Vec2 apex = apex_in_edge_frame(c[0], c[1], c[2]);
    u.flat[root] = {Vec2{0, 0}, Vec2{norm(c[1] - c[0]), 0}, apex};
    u.piece_of_face[root] = piece;
    queue.push(root);
    while (!queue.empty()) {
      const int f = queue.front();
      queue.pop();
      for (int i = 0; i < 3; ++i) {
        const int e = mesh.face_edges[f][i];
        UnfoldEdge& ue = u.edges[e];
        if (ue.cut || e == parent_edge[f]) continue;
        const int side = ue.face[0] == f ? 1 : 0;
        const int g = ue.face[side];
        if (u.piece_of_face[g] >= 0) {
          ue.cut = true;  // closes a cycle of folds: a forest is what can lie flat
          continue;
        }
        // g traverses the edge the other way: its corner j starts where f's edge ends.
        const int j = ue.corner[side];
        const Vec2 a = u.flat[f][(i + 1) % 3], b = u.flat[f][i];
        auto gc = mesh.corners(g);
        Vec2 local = apex_in_edge_frame(gc[j], gc[(j + 1) % 3], gc[(j + 2) % 3]);
        Vec2 d = normalized(b - a);
        Triangle2& t = u.flat[g];
        t[j] = a;
        t[(j + 1) % 3] = b;
        t[(j + 2) % 3] = a + d * local.x + perp_ccw(d) * local.y;
        u.piece_of_face[g] = piece;
        parent_edge[g] = e;
        queue.push(g);
      }
    }
  }
  return u;
}

Unfolding flatten_like(const Mesh& mesh, const EdgeStates& state, const Unfolding& like) {
  Unfolding u = flatten(mesh, state);
  for (std::size_t e = 0; e < like.edges.size() && e < u.edges.size(); ++e)
    u.edges[e].inside_face = like.edges[e].inside_face && !u.edges[e].cut;
  return u;
}

std::vector<std::string> check_unfolding(const Mesh& mesh, const Unfolding& u, double rel_tol) {
  std::vector<std::string> problems;
  auto report = [&](const std::string& s) {
    if (problems.size() < 50) problems.push_back(s);
  };
  const int nf = mesh.num_faces();
  if (u.num_faces() != nf || static_cast<int>(u.piece_of_face.size()) != nf ||
      u.edges.size() != mesh.edges.size()) {
    report("sizes differ from the mesh");
    return problems;
  }
  for (int f = 0; f < nf; ++f) {
    if (u.piece_of_face[f] < 0 || u.piece_of_face[f] >= u.piece_count) {
      report("face " + std::to_string(f) + " is in no piece");
      continue;
    }
    auto c = mesh.corners(f);
    const Triangle2& t = u.flat[f];
    for (int i = 0; i < 3; ++i) {
      double l3 = norm(c[(i + 1) % 3] - c[i]);
      double l2 = norm(t[(i + 1) % 3] - t[i]);
      if (!(std::abs(l2 - l3) <= rel_tol * std::max(l3, 1e-300)))
        report("face " + std::to_string(f) + " edge " + std::to_string(i) + " has flat length " +
               std::to_string(l2) + " but 3D length " + std::to_string(l3));
    }
    if (!(signed_area(t) > 0))
      report("face " + std::to_string(f) + " is mirrored or degenerate in the plane");
  }
  // Fold edges: both copies coincide and join faces of one piece; folds form a forest per piece.
  DisjointSets folded(nf);
  std::vector<int> folds_in_piece(u.piece_count, 0), faces_in_piece(u.piece_count, 0);
  for (int f = 0; f < nf; ++f)
    if (u.piece_of_face[f] >= 0 && u.piece_of_face[f] < u.piece_count) ++faces_in_piece[u.piece_of_face[f]];
  double tol = rel_tol * std::max(u.model_extent, 1e-300) * 1e3;
  for (int e = 0; e < mesh.num_edges(); ++e) {
    const UnfoldEdge& ue = u.edges[e];
    if (ue.face != mesh.edges[e].face || ue.corner != mesh.edges[e].corner)
      report("edge " + std::to_string(e) + " does not match the mesh");
    if (ue.boundary()) {
      if (!ue.cut) report("boundary edge " + std::to_string(e) + " is not cut");
      continue;
    }
    if (ue.cut) continue;
    int f = ue.face[0], g = ue.face[1];
    if (u.piece_of_face[f] != u.piece_of_face[g]) {
      report("fold edge " + std::to_string(e) + " joins two pieces");
      continue;
    }
    int i = ue.corner[0], j = ue.corner[1];
    Vec2 fa = u.flat[f][i], fb = u.flat[f][(i + 1) % 3];
    Vec2 ga = u.flat[g][(j + 1) % 3], gb = u.flat[g][j];
    if (norm(fa - ga) > tol || norm(fb - gb) > tol)
      report("the two sides of fold edge " + std::to_string(e) + " do not coincide");
    if (!folded.join(f, g)) report("fold edge " + std::to_string(e) + " closes a cycle of folds");
    ++folds_in_piece[u.piece_of_face[f]];
  }
  for (int p = 0; p < u.piece_count; ++p)
    if (faces_in_piece[p] == 0 || folds_in_piece[p] != faces_in_piece[p] - 1)
      report("piece " + std::to_string(p) + " is not one connected tree of folds");
  for (const FacePair& pair : overlapping_pairs(u.flat, u.piece_of_face))
    report("faces " + std::to_string(pair.a) + " and " + std::to_string(pair.b) + " of piece " +
           std::to_string(u.piece_of_face[pair.a]) + " overlap");
  return problems;
}

}  // namespace foldkit::unfold
