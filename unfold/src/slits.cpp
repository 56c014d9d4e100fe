// Closing slits by tree moves. A move cuts fold edge e and folds cut edge a: in the dual, the side of e
// is cut off and glued back along a, one rigid motion. Only the seams between that side and the rest
// of its piece move relative to each other, so a move's effect on the slits is known from those few
// seams before the (costly) overlap test, and only moves that lower the slits' cost are tested.
#include "foldkit/unfold/slits.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

#include "foldkit/geom/rigid.hpp"

namespace foldkit::unfold {
namespace {

// Moves must lower the total slit cost by at least this: no walking in circles on rounding.
constexpr double kMinGain = 1e-3;

Vec2 corner_of(const CutTree& tree, int f, int v) {
  const auto& face = tree.mesh().faces[f];
  const Triangle2& t = tree.flat(FaceId(f));
  for (int i = 0; i < 3; ++i)
    if (face[i] == v) return t[i];
  return t[0];
}

// The motion that takes face `moving`'s copy of edge e onto face `fixed`'s (as CutTree glues them).
RigidMotion glue_motion(const CutTree& tree, int e, int moving, int fixed) {
  const auto& v = tree.mesh().edges[e].v;
  return motion_onto(corner_of(tree, moving, v[0]), corner_of(tree, moving, v[1]),
                     corner_of(tree, fixed, v[0]), corner_of(tree, fixed, v[1]));
}

// Gap per length of cut edge e between face `moved` (placed by `motion`) and face `other`.
double gap_per_length(const CutTree& tree, int e, int moved, const RigidMotion& motion, int other) {
  const auto& v = tree.mesh().edges[e].v;
  const Vec2 a0 = motion(corner_of(tree, moved, v[0])), a1 = motion(corner_of(tree, moved, v[1]));
  const Vec2 b0 = corner_of(tree, other, v[0]), b1 = corner_of(tree, other, v[1]);
  const double length = norm(b1 - b0);
  if (length <= 0) return std::numeric_limits<double>::infinity();
  return std::max(norm(a0 - b0), norm(a1 - b1)) / length;
}

// What a slit costs: 1, plus up to 1 more the tighter it is (a wider slit is progress: from there it
// may close).
double slit_cost(double gap, double limit) {
  return gap < limit ? 2 - gap / limit : 0;
}

struct Move {
  double gain = 0;  // cost removed (positive is better)
  EdgeId cut, fold;
};

class Closer {
 public:
  Closer(CutTree& tree, const EdgeConstraints& cons, const SlitOptions& options)
      : tree_(tree), m_(tree.mesh()), cons_(cons), limit_(options.min_gap_per_length) {
    edges_at_.resize(m_.num_vertices());
    for (int e = 0; e < m_.num_edges(); ++e)
      for (int v : m_.edges[e].v)
        edges_at_[v].push_back(e);
  }

  double cost(int e) const { return slit_cost(seam_gap_per_length(tree_, EdgeId(e)), limit_); }

  // The best move that makes slit c cheaper: over the fold edges at its ends, the largest gain that
  // adds no overlap. Nothing when out of time.
  template <class OutOfTime>
  Move best_move(int c, const OutOfTime& out_of_time) {
    Move best;
    for (int v : m_.edges[c].v)
      for (int e : edges_at_[v]) {
        if (!tree_.folded(EdgeId(e)) || cons_.fold(EdgeId(e))) continue;
        if (!try_cut(e, best, out_of_time)) return {};
      }
    return best;
  }

  void apply(const Move& move) {
    tree_.smaller_side(move.cut, side_);
    tree_.reattach(side_, move.cut, move.fold);
  }

 private:
  // Candidate folds for cutting e: the cut edges between its smaller side and the rest of the piece.
  // Improves `best` with the best of them; false when out of time.
  template <class OutOfTime>
  bool try_cut(int e, Move& best, const OutOfTime& out_of_time) {
    tree_.smaller_side(EdgeId(e), side_);
    boundary_.clear();
    for (int x : side_)
      for (int a : m_.face_edges[x]) {
        if (a == e || tree_.folded(EdgeId(a)) || m_.edges[a].boundary()) continue;
        const FaceId y = tree_.across(EdgeId(a), FaceId(x));
        if (!tree_.in_side(y) && tree_.piece(y) == tree_.piece(FaceId(x)))
          boundary_.push_back({a, x, y.index()});
      }
    double before = 0;
    for (const Link& l : boundary_)
      before += cost(l.edge);
    candidates_.clear();
    for (const Link& l : boundary_) {
      if (cons_.cut(EdgeId(l.edge)) || !curvature_allows(e, l.edge)) continue;
      const RigidMotion motion = glue_motion(tree_, l.edge, l.inside, l.outside);
      // After the move: e is a seam, l.edge is folded, the other links moved with the side.
      const auto& ef = m_.edges[e].face;
      const int e_in = tree_.in_side(FaceId(ef[0])) ? ef[0] : ef[1], e_out = e_in == ef[0] ? ef[1] : ef[0];
      double after = slit_cost(gap_per_length(tree_, e, e_in, motion, e_out), limit_);
      for (const Link& o : boundary_)
        if (o.edge != l.edge)
          after += slit_cost(gap_per_length(tree_, o.edge, o.inside, motion, o.outside), limit_);
      const double gain = before - after;
      if (gain > best.gain + kMinGain) candidates_.push_back({gain, EdgeId(e), EdgeId(l.edge)});
    }
    std::stable_sort(candidates_.begin(), candidates_.end(),
                     [](const Move& p, const Move& q) { return p.gain > q.gain; });
    for (const Move& c : candidates_) {
      if (out_of_time()) return false;
      if (tree_.reattach_cost(side_, c.fold, 0) == 0) {
        best = c;
        break;
      }
    }
    return true;
  }

  // Cutting e and folding a keeps every vertex at the cut count its curvature needs.
  bool curvature_allows(int e, int a) const {
    for (int v : m_.edges[a].v) {
      const auto& ev = m_.edges[e].v;
      const int after = tree_.cut_count(VertexId(v)) - 1 + (v == ev[0] || v == ev[1]);
      if (after < tree_.context().required_cuts[v]) return false;
    }
    return true;
  }

  struct Link {
    int edge, inside, outside;  // a cut edge between the side (face `inside`) and the rest
  };
  CutTree& tree_;
  const Mesh& m_;
  const EdgeConstraints& cons_;
  double limit_;
  std::vector<std::vector<int>> edges_at_;
  std::vector<int> side_;
  std::vector<Link> boundary_;
  std::vector<Move> candidates_;
};

}  // namespace

double seam_gap_per_length(const CutTree& tree, EdgeId e) {
  const auto& edge = tree.mesh().edge(e);
  if (edge.boundary() || tree.folded(e) || tree.piece(edge.face_id(0)) != tree.piece(edge.face_id(1)))
    return std::numeric_limits<double>::infinity();
  return gap_per_length(tree, e.index(), edge.face[0], RigidMotion{}, edge.face[1]);
}

int count_slits(const CutTree& tree, double min_gap_per_length) {
  int n = 0;
  for (EdgeId e : all_ids<EdgeId>(tree.mesh().num_edges()))
    n += seam_gap_per_length(tree, e) < min_gap_per_length;
  return n;
}

SlitResult close_slits(CutTree& tree, const EdgeConstraints& constraints, const SlitOptions& options) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  auto out_of_time = [&] {
    return std::chrono::duration<double>(Clock::now() - start).count() >= options.time_limit_s;
  };
  Closer closer(tree, constraints, options);
  SlitResult result;
  result.slits_before = count_slits(tree, options.min_gap_per_length);
  for (int pass = 0; pass < options.max_passes && !out_of_time(); ++pass) {
    int moves_this_pass = 0;
    const int edges = tree.mesh().num_edges();
    for (int c = 0; c < edges && !out_of_time(); ++c) {
      if (closer.cost(c) <= 0) continue;
      if (options.progress)
        options.progress(static_cast<long>(pass) * edges + c, static_cast<long>(options.max_passes) * edges);
      const Move move = closer.best_move(c, out_of_time);
      if (!move.cut.valid()) continue;
      closer.apply(move);
      ++result.moves;
      ++moves_this_pass;
    }
    if (moves_this_pass == 0) break;
  }
  result.slits_after = count_slits(tree, options.min_gap_per_length);
  return result;
}

}  // namespace foldkit::unfold
