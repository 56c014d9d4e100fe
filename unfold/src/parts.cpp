#include "foldkit/unfold/parts.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <queue>
#include <string>
#include <utility>

#include "foldkit/error.hpp"
#include "foldkit/geom/hull.hpp"
#include "foldkit/geom/rigid.hpp"
#include "foldkit/unfold/cut_tree.hpp"
#include "foldkit/unfold/disjoint_sets.hpp"
#include "foldkit/unfold/slits.hpp"

namespace foldkit::unfold {
namespace {

Vec2 centroid(const Triangle2& t) {
  return (t[0] + t[1] + t[2]) * (1.0 / 3.0);
}

// A part as the hull of its points and the last rotation at which it was seen to fit: most faces that
// join a part fit at that rotation, which is a cheap test before the full search of fit_in_rect.
struct Hull {
  std::vector<Vec2> points;
  double angle_rad = 0;
};

class Fitter {
 public:
  Fitter(double scale, Vec2 room) : scale_(scale), room_(room) {}

  // Whether `hull` plus `extra` fits; on success `hull` becomes the grown hull.
  bool grow(Hull& hull, std::span<const Vec2> extra) const {
    std::vector<Vec2> points = hull.points;
    points.insert(points.end(), extra.begin(), extra.end());
    points = convex_hull(std::move(points));
    if (fits_at(points, hull.angle_rad)) {
      hull.points = std::move(points);
      return true;
    }
    const RectFit fit = fit_in_rect(points, room_);
    if (fit.scale < scale_) return false;
    hull = {std::move(points), fit.angle_rad};
    return true;
  }

  bool fits(std::span<const Vec2> points) const { return fit_in_rect(points, room_).scale >= scale_; }

 private:
  bool fits_at(const std::vector<Vec2>& points, double angle) const {
    const Rotation turn(angle);
    Box2 box;
    for (Vec2 p : points)
      box.add(turn(p));
    return box.width() * scale_ <= room_.x && box.height() * scale_ <= room_.y;
  }

  double scale_;
  Vec2 room_;
};

// Flat faces of one piece: faces per unit and each unit's flat corner points.
struct Units {
  std::vector<int> unit_of_face;  // indexed by face (whole mesh), -1 outside the piece
  std::vector<std::vector<int>> faces;
  std::vector<std::vector<Vec2>> points;
};

Units units_of(const Unfolding& u, const std::vector<int>& flat_face, const std::vector<int>& faces) {
  Units units;
  units.unit_of_face.assign(u.num_faces(), -1);
  std::vector<int> local(u.num_faces(), -1);
  for (int f : faces) {
    int& id = local[flat_face[f]];
    if (id < 0) {
      id = static_cast<int>(units.faces.size());
      units.faces.emplace_back();
      units.points.emplace_back();
    }
    units.unit_of_face[f] = id;
    units.faces[id].push_back(f);
    units.points[id].insert(units.points[id].end(), u.flat[f].begin(), u.flat[f].end());
  }
  for (int f : faces)
    local[flat_face[f]] = -1;
  return units;
}

// Pairs of faces of a piece across a narrow seam (narrow_seam_partners): in one part they make a slit
// that takes no glue tab, in two parts the seam gets one like any other between parts.
struct SlitPairs {
  std::vector<std::vector<int>> partners;  // per face

  // Whether any of `unit_faces` has a partner in part `id`.
  bool meets(const std::vector<int>& unit_faces, const std::vector<int>& part, int id) const {
    for (int f : unit_faces)
      for (int h : partners[f])
        if (part[h] == id) return true;
    return false;
  }
};

// Greedy growth leaves small leftovers where a part ran into the room's edge: merges every part into
// a neighbour (across a fold) whenever the two together still fit, smallest parts first. Renumbers the
// parts 0..n-1 and returns n.
int merge_parts(const Unfolding& u, const std::vector<int>& faces, const Fitter& fitter,
                const SlitPairs& slits, std::vector<int>& part, int parts) {
  std::vector<Hull> hull(parts);
  std::vector<int> size(parts, 0);
  for (int f : faces) {
    hull[part[f]].points.insert(hull[part[f]].points.end(), u.flat[f].begin(), u.flat[f].end());
    size[part[f]] += 1;
  }
  for (auto& h : hull)
    h.points = convex_hull(std::move(h.points));
  DisjointSets owner(parts);
  auto find = [&owner](int p) { return owner.find(p); };
  std::vector<int> slit_faces;  // of this piece
  for (int f : faces)
    if (!slits.partners[f].empty()) slit_faces.push_back(f);
  // Whether parts p and q (roots) together would hold both faces of a slit pair.
  auto would_close_slit = [&](int p, int q) {
    for (int f : slit_faces) {
      const int a = find(part[f]);
      if (a != p && a != q) continue;
      for (int h : slits.partners[f])
        if (find(part[h]) == (a == p ? q : p)) return true;
    }
    return false;
  };
  for (bool merged = true; merged;) {
    merged = false;
    std::vector<std::vector<int>> next(parts);
    for (int f : faces)
      for (int c = 0; c < 3; ++c) {
        const UnfoldEdge& edge = u.edges[u.face_edges[f][c]];
        if (edge.cut || edge.boundary()) continue;
        const int a = find(part[edge.face[0]]), b = find(part[edge.face[1]]);
        if (a != b) next[a].push_back(b);
      }
    std::vector<int> order;
    for (int p = 0; p < parts; ++p)
      if (find(p) == p) order.push_back(p);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return size[a] < size[b]; });
    for (int p : order) {
      if (find(p) != p) continue;
      std::vector<int> around;
      for (int q : next[p])
        if (find(q) != p) around.push_back(find(q));
      std::stable_sort(around.begin(), around.end(), [&](int a, int b) { return size[a] < size[b]; });
      for (int q : around) {
        if (would_close_slit(p, q)) continue;
        Hull both = hull[q];
        if (!fitter.grow(both, hull[p].points)) continue;
        owner.join(p, q);
        hull[q] = std::move(both);
        size[q] += size[p];
        for (int r : next[p])
          next[q].push_back(r);
        merged = true;
        break;
      }
    }
  }
  std::vector<int> renumber(parts, -1);
  int n = 0;
  for (int f : faces) {
    const int root = find(part[f]);
    if (renumber[root] < 0) renumber[root] = n++;
    part[f] = renumber[root];
  }
  return n;
}

// Grows parts over the folds of one piece, a whole flat face at a time; a flat face that would make its
// part too large waits for a later part. Round growth starts each part at the unassigned face lying
// furthest back along the piece's long axis and takes the faces nearest its start first, so parts come
// out roughly round (round parts nest; strips cut off a spindly net do not). Tree growth takes faces
// breadth-first along the folds from the first face of the piece, which often needs fewer parts.
int grow_parts(const Unfolding& u, const std::vector<int>& faces, const Units& units, const Fitter& fitter,
               const SlitPairs& slits, bool round, std::vector<int>& part) {
  std::vector<Vec2> points;
  for (int f : faces)
    points.insert(points.end(), u.flat[f].begin(), u.flat[f].end());
  const double axis_angle = min_area_rect_angle(points);
  const Rotation to_axis(axis_angle);
  Box2 box;
  for (Vec2 p : points)
    box.add(to_axis(p));
  const bool x_long = box.width() >= box.height();
  std::vector<int> sweep = faces;
  if (round) {
    // Each face's place along the axis, computed once rather than in every comparison.
    std::vector<double> along(u.num_faces());
    for (int f : faces) {
      const Vec2 c = to_axis(centroid(u.flat[f]));
      along[f] = x_long ? c.x : c.y;
    }
    std::stable_sort(sweep.begin(), sweep.end(), [&](int a, int b) { return along[a] < along[b]; });
  }
  long pushed = 0;  // tree growth: faces in the order they were reached

  int parts = 0;
  for (int seed : sweep) {
    if (part[seed] >= 0) continue;
    const int id = parts++;
    const Vec2 start = centroid(u.flat[seed]);
    using Entry = std::pair<double, int>;  // distance from the start, face
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> frontier;
    auto push_neighbours = [&](int unit) {
      for (int f : units.faces[unit])
        for (int c = 0; c < 3; ++c) {
          const UnfoldEdge& edge = u.edges[u.face_edges[f][c]];
          if (edge.cut || edge.boundary()) continue;
          const int g = edge.face[0] == f ? edge.face[1] : edge.face[0];
          if (part[g] < 0) frontier.push({round ? norm(centroid(u.flat[g]) - start) : double(pushed++), g});
        }
    };
    auto take = [&](int unit) {
      for (int f : units.faces[unit])
        part[f] = id;
      push_neighbours(unit);
    };
    const int seed_unit = units.unit_of_face[seed];
    Hull hull{convex_hull(units.points[seed_unit]), 0};
    take(seed_unit);
    while (!frontier.empty()) {
      const int g = frontier.top().second;
      frontier.pop();
      const int unit = units.unit_of_face[g];
      if (part[g] >= 0 || slits.meets(units.faces[unit], part, id) || !fitter.grow(hull, units.points[unit]))
        continue;
      take(unit);
    }
  }
  return merge_parts(u, faces, fitter, slits, part, parts);
}

std::string format_size(double mm) {
  return std::to_string(static_cast<long>(std::floor(mm)));
}

// A flat face larger than the room can be printed at no size the user asked for: say which size fits.
void check_flat_faces_fit(const Unfolding& u, const Units& units, const Fitter& fitter,
                          const PartOptions& o) {
  for (std::size_t k = 0; k < units.faces.size(); ++k) {
    if (fitter.fits(units.points[k])) continue;
    double best = 1e300;
    for (const auto& pts : units.points)
      best = std::min(best, fit_in_rect(pts, o.room_mm).scale);
    throw PartTooLarge(static_cast<int>(units.faces[k].size()), o.room_mm, o.mm_per_unit * u.model_extent,
                       std::min(best * u.model_extent, o.mm_per_unit * u.model_extent * 0.99));
  }
}

// Which room a part must keep when its seams move: the one it was grown to, or the sheet's for a
// piece that was not split.
enum class PartRoom : unsigned char { Sheet, Grown };

// Whether both labels of edge e fit beside it were it cut (every edge without grades).
bool labels_fit(const std::vector<LabelFit>& fit, EdgeId e) {
  return fit.empty() || fit[static_cast<std::size_t>(e.index())] == LabelFit::BothSides;
}

// Whether piece `piece` of `tree` fits the fitter's room.
bool piece_fits(const CutTree& tree, int piece, const Fitter& fitter) {
  std::vector<Vec2> points;
  for (int f = 0; f < tree.num_faces(); ++f)
    if (tree.piece(FaceId(f)) == piece)
      for (Vec2 p : tree.flat(FaceId(f)))
        points.push_back(p);
  return fitter.fits(convex_hull(std::move(points)));
}

// Trial folds between parts (close_slits_across_parts, boundary moves, join_parts): a fold is kept when
// the part it makes fits the room and the slits get no more, or fewer where asked.
class TrialFolds {
 public:
  TrialFolds(CutTree& tree, const Fitter& fitter, double min_gap)
      : t_(tree), fitter_(fitter), min_gap_(min_gap), slits_(count_slits(tree, min_gap)) {}

  enum class Slits : unsigned char { NoMore, Fewer };

  // Folds `link` where that overlaps nothing and the curvature allows; keeps it (true) when the slits
  // allow and the part then holding `face` fits, else cuts it again.
  bool keep(EdgeId link, FaceId face, Slits rule) {
    if (!t_.curvature_allows_fold(link) || t_.stitch_cost(link, 0) > 0) return false;
    t_.stitch(link);
    const int slits = count_slits(t_, min_gap_);
    if ((rule == Slits::Fewer ? slits < slits_ : slits <= slits_) &&
        piece_fits(t_, t_.piece(face), fitter_)) {
      slits_ = slits;
      return true;
    }
    t_.cut(link);
    return false;
  }

  double min_gap() const { return min_gap_; }

 private:
  CutTree& t_;
  const Fitter& fitter_;
  double min_gap_;
  int slits_;
};

// Moves of faces from one part to a neighbouring one: closing slits (close_slits_across_parts, parts.hpp)
// and moving the seams between patches off edges without room for their labels (patch_parts).
class AcrossParts {
 public:
  AcrossParts(CutTree& tree, const EdgeConstraints& cons, const std::vector<LabelFit>& fit,
              const Fitter& fitter, double min_gap)
      : t_(tree), m_(tree.mesh()), cons_(cons), fit_(fit), folds_(tree, fitter, min_gap) {
    edges_at_.resize(static_cast<std::size_t>(m_.num_vertices()));
    for (int e = 0; e < m_.num_edges(); ++e)
      for (int v : m_.edges[e].v)
        edges_at_[static_cast<std::size_t>(v)].push_back(e);
  }

  // Each slit once, the first join found that lowers the slits.
  void close_slits() {
    for (int c = 0; c < m_.num_edges(); ++c)
      if (is_slit(c))
        for (int v : m_.edges[c].v)
          if (close_at(v)) break;
  }

  // Seams between two parts moved off edges too tight for their labels: a small side of one part next to
  // such a seam (the faces beyond one of its fold edges, the seam's face among them) changes part, folded
  // along the seam and cut where it hung, when the new cut's labels fit better, the part it joins stays
  // overlap-free and fits the room, and the slits get no more. Forced cuts and folds (and so flat faces)
  // are kept.
  void move_off_tight_edges() {
    if (fit_.empty()) return;
    for (int pass = 0; pass < kPasses; ++pass) {
      int moved = 0;
      for (int c = 0; c < m_.num_edges(); ++c)
        if (between_parts(EdgeId(c)) && fit_[static_cast<std::size_t>(c)] != LabelFit::BothSides)
          moved += move_off(EdgeId(c)) ? 1 : 0;
      if (moved == 0) break;
    }
  }

 private:
  static constexpr int kPasses = 4;
  // A side larger than this is not moved: the move is a local correction of a boundary, not a repartition.
  static constexpr int kMostFacesMoved = 40;

  bool between_parts(EdgeId c) const {
    const auto& edge = m_.edge(c);
    return !edge.boundary() && !t_.folded(c) && !cons_.cut(c) &&
           t_.piece(edge.face_id(0)) != t_.piece(edge.face_id(1));
  }

  int grade(EdgeId e) const { return static_cast<int>(fit_[static_cast<std::size_t>(e.index())]); }

  // Tries each end face of seam c and each of its fold edges; true once a move is kept.
  bool move_off(EdgeId c) {
    for (int end = 0; end < 2; ++end) {
      const FaceId x = m_.edge(c).face_id(end);
      for (int a : m_.face_edges[x.index()]) {
        const EdgeId hang(a);
        if (!t_.folded(hang) || cons_.fold(hang) || grade(hang) >= grade(c)) continue;
        t_.smaller_side(hang, side_);
        if (!t_.in_side(x) || static_cast<int>(side_.size()) > kMostFacesMoved) continue;
        if (try_move(c, hang, m_.edge(c).face_id(1 - end))) return true;
      }
    }
    return false;
  }

  // Cuts `hang`, folds `c` (its side joins the part of face `across`); undone unless it is a gain.
  bool try_move(EdgeId c, EdgeId hang, FaceId across) {
    t_.cut(hang);
    if (folds_.keep(c, across, TrialFolds::Slits::NoMore)) return true;
    t_.stitch(hang);
    return false;
  }

  bool is_slit(int c) const {
    const auto& edge = m_.edges[c];
    return !edge.boundary() && !t_.folded(EdgeId(c)) &&
           t_.piece(edge.face_id(0)) == t_.piece(edge.face_id(1)) &&
           slit_cost(seam_gap_per_length(t_, EdgeId(c)), folds_.min_gap()) > 0;
  }

  // Tries each fold at v: cut it, give the side cut off to a neighbour. True once one is kept.
  bool close_at(int v) {
    for (int e : edges_at_[static_cast<std::size_t>(v)]) {
      const EdgeId cut(e);
      if (!t_.folded(cut) || cons_.fold(cut)) continue;
      // Only where both labels fit: cuts through flat regions of sliver faces left labels crossing lines.
      if (!labels_fit(fit_, cut)) continue;
      t_.smaller_side(cut, side_);
      const std::vector<int> side = side_;
      const auto& ef = m_.edges[e].face;
      const FaceId rest(t_.in_side(FaceId(ef[0])) ? ef[1] : ef[0]);
      t_.cut(cut);
      if (join_neighbour(side, rest)) return true;
      t_.stitch(cut);
    }
    return false;
  }

  bool join_neighbour(const std::vector<int>& side, FaceId rest) {
    for (int x : side)
      for (int a : m_.face_edges[x]) {
        const EdgeId link(a);
        if (t_.folded(link) || m_.edges[a].boundary() || cons_.cut(link)) continue;
        const FaceId y = t_.across(link, FaceId(x));
        // Piece ids change as trial joins are undone: asked afresh.
        if (t_.piece(y) == t_.piece(FaceId(x)) || t_.piece(y) == t_.piece(rest)) continue;
        if (folds_.keep(link, y, TrialFolds::Slits::Fewer)) return true;
      }
    return false;
  }

  CutTree& t_;
  const Mesh& m_;
  const EdgeConstraints& cons_;
  const std::vector<LabelFit>& fit_;
  TrialFolds folds_;
  std::vector<std::vector<int>> edges_at_;
  std::vector<int> side_;
};

// `state` (the parts) with seams moved inside each part (seam_moves.hpp) where the moved part still fits
// its room: `room` says per face which fitter judges its part.
EdgeStates with_seams_moved(const Mesh& mesh, const Unfolding& u, const EdgeStates& state,
                            const FaceMap<PartRoom>& room, const Fitter& sheet, const Fitter& grown,
                            const PartOptions& o) {
  const UnfoldContext ctx = make_context(mesh, o.cuts);
  CutTree tree(ctx, state);
  if (tree.overlap_count() > 0) return state;
  std::vector<Vec2> points;
  std::vector<bool> moving;
  SeamMoveOptions so = o.seam_moves;
  so.accept = [&](const CutTree& t, const std::vector<int>& side, const RigidMotion& motion) {
    moving.assign(static_cast<std::size_t>(t.num_faces()), false);
    for (int f : side)
      moving[static_cast<std::size_t>(f)] = true;
    const FaceId first(side.front());
    points.clear();
    for (int f = 0; f < t.num_faces(); ++f) {
      if (t.piece(FaceId(f)) != t.piece(first)) continue;
      for (Vec2 p : t.flat(FaceId(f)))
        points.push_back(moving[static_cast<std::size_t>(f)] ? motion(p) : p);
    }
    const Fitter& fitter = room[first] == PartRoom::Grown ? grown : sheet;
    return fitter.fits(convex_hull(std::move(points)));
  };
  const SeamMoveResult r =
      move_seams(tree, move_constraints(u, o.constraints), tight_edges(mesh, o.cuts), so);
  return r.moves > 0 ? tree.states() : state;
}

}  // namespace

std::string PartTooLarge::message(int triangles, Vec2 room_mm, double asked_mm, double largest_mm,
                                  const std::string& size_name) {
  return "a flat face (" + std::to_string(triangles) + (triangles == 1 ? " triangle" : " triangles") +
         ") is larger than the " + format_size(room_mm.x) + "x" + format_size(room_mm.y) +
         " mm room for a part at " + size_name + " " + format_size(asked_mm) + "mm; the largest " +
         size_name + " that fits is " + format_size(largest_mm) + "mm";
}

EdgeConstraints move_constraints(const Unfolding& u, const EdgeConstraints& given) {
  EdgeConstraints c = given;
  if (c.rule.empty()) c.rule.assign(static_cast<int>(u.edges.size()), EdgeRule::Free);
  for (std::size_t e = 0; e < u.edges.size(); ++e)
    if (u.edges[e].inside_face) c.rule[EdgeId(static_cast<int>(e))] = EdgeRule::MustFold;
  return c;
}

std::vector<int> flat_face_of(const Unfolding& u) {
  DisjointSets flat_faces(u.num_faces());
  for (const UnfoldEdge& e : u.edges)
    if (e.inside_face && !e.cut && !e.boundary()) flat_faces.join(e.face[0], e.face[1]);
  std::vector<int> id(u.num_faces(), -1), out(u.num_faces());
  int n = 0;
  for (int f = 0; f < u.num_faces(); ++f) {
    const int r = flat_faces.find(f);
    if (id[r] < 0) id[r] = n++;
    out[f] = id[r];
  }
  return out;
}

PartsResult split_into_parts(const Mesh& mesh, const Unfolding& u, const PartOptions& o) {
  PartsResult result{u, 0, 0};
  if (!(o.mm_per_unit > 0) || !(u.model_extent > 0)) return result;
  const Fitter whole(o.mm_per_unit, o.room_mm);
  const bool tile = o.grow_room_mm.x > 0 && o.grow_room_mm.y > 0;
  const Fitter fitter(o.mm_per_unit,
                      tile ? o.grow_room_mm : o.room_mm * std::clamp(o.room_fraction, 0.05, 1.0));
  const std::vector<int> flat_face = flat_face_of(u);
  const SlitPairs slits{narrow_seam_partners(u, o.slit_gap_mm / o.mm_per_unit)};

  EdgeStates state = edge_states(u);
  FaceMap<PartRoom> room(u.num_faces(), PartRoom::Sheet);
  bool changed = false;
  std::vector<int> part(u.num_faces(), -1);
  const std::vector<std::vector<int>> pieces = u.piece_faces();
  for (std::size_t piece = 0; piece < pieces.size(); ++piece) {
    const std::vector<int>& faces = pieces[piece];
    std::vector<Vec2> all;
    for (int f : faces)
      all.insert(all.end(), u.flat[f].begin(), u.flat[f].end());
    const bool asked =
        std::find(o.also_split.begin(), o.also_split.end(), static_cast<int>(piece)) != o.also_split.end();
    if (!asked && whole.fits(all)) continue;
    const Units units = units_of(u, flat_face, faces);
    check_flat_faces_fit(u, units, whole, o);
    result.split_pieces += 1;
    for (int f : faces)
      room[FaceId(f)] = PartRoom::Grown;
    std::vector<int> tree_part = part;
    const int tree =
        o.growth == PartGrowth::Round ? 0 : grow_parts(u, faces, units, fitter, slits, false, tree_part);
    const int round =
        o.growth == PartGrowth::Tree ? 0 : grow_parts(u, faces, units, fitter, slits, true, part);
    const bool use_tree = o.growth == PartGrowth::Tree || (o.growth == PartGrowth::Fewest && tree < round);
    if (use_tree) part = std::move(tree_part);
    result.new_pieces += use_tree ? tree : round;
    for (int f : faces)
      for (int c = 0; c < 3; ++c) {
        const int e = u.face_edges[f][c];
        const UnfoldEdge& edge = u.edges[e];
        if (edge.cut || edge.boundary()) continue;
        if (part[edge.face[0]] != part[edge.face[1]]) {
          state[EdgeId(static_cast<int>(e))] = EdgeState::Cut;
          changed = true;
        }
      }
  }
  if (changed) {
    if (o.move_seams) state = with_seams_moved(mesh, u, state, room, whole, fitter, o);
    result.unfolding = flatten_like(mesh, state, u);
  }
  return result;
}

namespace {

// join_parts (parts.hpp): passes over the seams between parts, smallest pairs first, until one joins none.
class PartJoiner {
 public:
  PartJoiner(CutTree& tree, const Unfolding& parts, const EdgeConstraints& cons, const Fitter& fitter,
             double min_gap, const std::function<bool(int, int)>& may_join, int most_joins)
      : t_(tree),
        parts_(parts),
        cons_(cons),
        folds_(tree, fitter, min_gap),
        may_join_(may_join),
        left_(most_joins) {}

  void run() {
    while (left_ > 0 && join_pass() > 0) {
    }
  }

 private:
  // The seams between two parts that may join, the smallest pair first, the longest seam of a pair first.
  std::vector<EdgeId> links() const {
    const Mesh& m = t_.mesh();
    std::vector<EdgeId> out;
    for (int e = 0; e < m.num_edges(); ++e) {
      const EdgeId link(e);
      if (t_.folded(link) || m.edges[e].boundary() || cons_.cut(link)) continue;
      const auto& f = m.edges[e].face;
      if (t_.piece(FaceId(f[0])) == t_.piece(FaceId(f[1]))) continue;
      if (!may_join_(parts_.piece_of_face[f[0]], parts_.piece_of_face[f[1]])) continue;
      out.push_back(link);
    }
    const auto pair_size = [&](EdgeId e) {
      const auto& f = m.edges[e.index()].face;
      return t_.piece_size(t_.piece(FaceId(f[0]))) + t_.piece_size(t_.piece(FaceId(f[1])));
    };
    std::stable_sort(out.begin(), out.end(), [&](EdgeId a, EdgeId b) {
      return std::pair(pair_size(a), -parts_.edges[a.index()].length) <
             std::pair(pair_size(b), -parts_.edges[b.index()].length);
    });
    return out;
  }

  int join_pass() {
    const Mesh& m = t_.mesh();
    int joined = 0;
    for (EdgeId link : links()) {
      if (left_ == 0) break;
      const auto& f = m.edges[link.index()].face;
      if (t_.piece(FaceId(f[0])) == t_.piece(FaceId(f[1]))) continue;
      if (folds_.keep(link, FaceId(f[0]), TrialFolds::Slits::NoMore)) {
        ++joined;
        --left_;
      }
    }
    return joined;
  }

  CutTree& t_;
  const Unfolding& parts_;
  const EdgeConstraints& cons_;
  TrialFolds folds_;
  const std::function<bool(int, int)>& may_join_;
  int left_;  // joins still allowed
};

// An unfolding of `tree`'s state that keeps `parts`' flat faces marked where they stay folded.
Unfolding flattened_like(const Mesh& mesh, const CutTree& tree, const Unfolding& parts) {
  return flatten_like(mesh, tree.states(), parts);
}

}  // namespace

Unfolding join_parts(const Mesh& mesh, const Unfolding& parts, const PartOptions& o,
                     const std::function<bool(int, int)>& may_join, int most_joins) {
  const UnfoldContext ctx = make_context(mesh, o.cuts);
  CutTree tree(ctx, edge_states(parts));
  if (tree.overlap_count() > 0) return parts;
  const Fitter sheet(o.mm_per_unit, o.room_mm * o.room_fraction);
  PartJoiner(tree, parts, move_constraints(parts, o.constraints), sheet, o.seam_moves.min_gap_per_length,
             may_join, most_joins)
      .run();
  if (tree.piece_count() == parts.piece_count) return parts;
  return flattened_like(mesh, tree, parts);
}

std::optional<Unfolding> patch_parts(const Mesh& mesh, const Unfolding& unfolding, const PartOptions& o) {
  // Every flat face a part of its own, the forced folds kept: the patches grow from there.
  EdgeStates faces_apart = edge_states(unfolding);
  for (std::size_t e = 0; e < unfolding.edges.size(); ++e) {
    const UnfoldEdge& edge = unfolding.edges[e];
    const EdgeId id(static_cast<int>(e));
    if (!edge.inside_face && !edge.boundary() && !o.constraints.fold(id)) faces_apart[id] = EdgeState::Cut;
  }
  const Unfolding apart = flatten_like(mesh, faces_apart, unfolding);
  if (CutTree(make_context(mesh, o.cuts), faces_apart).overlap_count() > 0) return std::nullopt;
  const Unfolding joined = join_parts(mesh, apart, o, [](int, int) { return true; });
  const UnfoldContext ctx = make_context(mesh, o.cuts);
  CutTree tree(ctx, edge_states(joined));
  const Fitter room(o.mm_per_unit, o.room_mm * o.room_fraction);
  AcrossParts(tree, move_constraints(joined, o.constraints), tight_edges(mesh, o.cuts), room,
              o.seam_moves.min_gap_per_length)
      .move_off_tight_edges();
  return flattened_like(mesh, tree, joined);
}

Unfolding close_slits_across_parts(const Mesh& mesh, const Unfolding& parts, const PartOptions& o) {
  const UnfoldContext ctx = make_context(mesh, o.cuts);
  CutTree tree(ctx, edge_states(parts));
  if (tree.overlap_count() > 0) return parts;
  const Fitter sheet(o.mm_per_unit, o.room_mm);
  AcrossParts(tree, move_constraints(parts, o.constraints), tight_edges(mesh, o.cuts), sheet,
              o.seam_moves.min_gap_per_length)
      .close_slits();
  return flattened_like(mesh, tree, parts);
}

}  // namespace foldkit::unfold
