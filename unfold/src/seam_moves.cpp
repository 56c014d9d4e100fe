// Seam moves. A move cuts fold edge e and folds cut edge a: in the dual, the side of e is cut off and
// glued back along a, one rigid motion. Only the seams between that side and the rest of its piece move
// relative to each other, so a move's effect on the seams' cost is known from those few seams before the
// (costly) overlap test, and only moves that lower the cost are tested.
//
// Which folds to cut: for a slit, those at its two ends (a leaf's wedge closes around its end vertex);
// for a seam with a label cost, also the first folds of its cycle from each end (the tree path between
// its two faces), since folding it means cutting some edge of that cycle.
#include "foldkit/unfold/seam_moves.hpp"

#include <algorithm>
#include <cstddef>

#include "foldkit/geom/rigid.hpp"

namespace foldkit::unfold {
namespace {

// Moves must lower the total cost by at least this: no walking in circles on rounding.
constexpr double kMinGain = 1e-3;

struct Move {
  double gain = 0;  // cost removed (positive is better)
  EdgeId cut, fold;
};

class Mover {
 public:
  Mover(CutTree& tree, const EdgeConstraints& cons, const std::vector<LabelFit>& fit,
        const SeamMoveOptions& options)
      : tree_(tree), m_(tree.mesh()), cons_(cons), fit_(fit), opt_(options) {
    edges_at_.resize(m_.num_vertices());
    for (int e = 0; e < m_.num_edges(); ++e)
      for (int v : m_.edges[e].v)
        edges_at_[v].push_back(e);
    tried_.assign(m_.num_edges(), -1);
  }

  double slit(int e) const {
    return slit_cost(seam_gap_per_length(tree_, EdgeId(e)), opt_.min_gap_per_length);
  }

  // What cut edge e's labels cost; 0 on a boundary edge (no labels) and without grades.
  double label(int e) const {
    if (fit_.empty() || m_.edges[e].boundary()) return 0;
    switch (fit_[e]) {
      case LabelFit::Tight:
        return opt_.tight_label_cost;
      case LabelFit::OnTab:
        return opt_.tab_label_cost;
      case LabelFit::BothSides:
        return 0;
    }
    return 0;
  }

  // A seam within one piece (the only kind a move can fold).
  bool inner_seam(int e) const {
    const auto& edge = m_.edges[e];
    return !edge.boundary() && !tree_.folded(EdgeId(e)) &&
           tree_.piece(edge.face_id(0)) == tree_.piece(edge.face_id(1));
  }

  bool out_of_work() const { return work_ >= opt_.work_limit; }
  long work() const { return work_; }

  // The best move that makes seam c cheaper: over the folds near it, the largest gain that adds no
  // overlap. Nothing when out of work.
  Move best_move(int c) {
    Move best;
    ++stamp_;
    for (int v : m_.edges[c].v)
      for (int e : edges_at_[v])
        if (!consider(e, best)) return {};
    if (label(c) > 0) {
      const auto& f = m_.edges[c].face;
      const std::vector<EdgeId> cycle = tree_.path(FaceId(f[0]), FaceId(f[1]));
      work_ += static_cast<long>(cycle.size());
      const std::size_t ends = static_cast<std::size_t>(std::max(opt_.cycle_ends, 0));
      for (std::size_t k = 0; k < cycle.size(); ++k)
        if (k < ends || k + ends >= cycle.size())
          if (!consider(cycle[k].index(), best)) return {};
    }
    return best;
  }

  void apply(const Move& move) {
    tree_.smaller_side(move.cut, side_);
    tree_.reattach(side_, move.cut, move.fold);
  }

 private:
  struct Link {
    int edge, inside, outside;  // a seam between the side (face `inside`) and the rest of its piece
  };

  // Tries cutting e (once per best_move) when it is a fold that may be cut; false when out of work.
  bool consider(int e, Move& best) {
    if (tried_[e] == stamp_ || !tree_.folded(EdgeId(e)) || cons_.fold(EdgeId(e))) return true;
    tried_[e] = stamp_;
    return try_cut(e, best);
  }

  // Candidate folds for cutting e: the seams between its smaller side and the rest of the piece.
  // Improves `best` with the best of them; false when out of work.
  bool try_cut(int e, Move& best) {
    tree_.smaller_side(EdgeId(e), side_);
    work_ += static_cast<long>(side_.size());
    find_links(e);
    double slits_before = 0, labels_before = 0;
    for (const Link& l : boundary_) {
      slits_before += slit(l.edge);
      labels_before += label(l.edge);
    }
    const auto& ef = m_.edges[e].face;
    const int e_in = tree_.in_side(FaceId(ef[0])) ? ef[0] : ef[1];
    candidates_.clear();
    // Each candidate re-measures every link: links squared.
    work_ += static_cast<long>(boundary_.size() * boundary_.size());
    for (const Link& l : boundary_) {
      if (cons_.cut(EdgeId(l.edge)) || !tree_.curvature_allows_move(EdgeId(e), EdgeId(l.edge))) continue;
      const RigidMotion motion = tree_.glue_motion(EdgeId(l.edge), l.inside, l.outside);
      // After the move: e is a seam, l.edge is folded, the other links moved with the side.
      double slits_after = moved_slit(e, e_in, motion);
      for (const Link& o : boundary_)
        if (o.edge != l.edge) slits_after += moved_slit(o.edge, o.inside, motion);
      if (slits_after > slits_before + kMinGain) continue;  // no label bought with a slit
      const double labels_after = labels_before - label(l.edge) + label(e);
      const double gain = slits_before + labels_before - slits_after - labels_after;
      if (gain > best.gain + kMinGain) candidates_.push_back({gain, EdgeId(e), EdgeId(l.edge)});
    }
    std::stable_sort(candidates_.begin(), candidates_.end(),
                     [](const Move& p, const Move& q) { return p.gain > q.gain; });
    for (const Move& c : candidates_) {
      if (out_of_work()) return false;
      work_ += static_cast<long>(side_.size());
      if (tree_.reattach_cost(side_, c.fold, 0) == 0 && accepted(c.fold)) {
        best = c;
        break;
      }
    }
    return true;
  }

  // The caller's own test of a move that folds `fold`, moving side_.
  bool accepted(EdgeId fold) const {
    if (!opt_.accept) return true;
    for (const Link& l : boundary_)
      if (l.edge == fold.index())
        return opt_.accept(tree_, side_, tree_.glue_motion(fold, l.inside, l.outside));
    return false;
  }

  void find_links(int e) {
    boundary_.clear();
    for (int x : side_)
      for (int a : m_.face_edges[x]) {
        if (a == e || tree_.folded(EdgeId(a)) || m_.edges[a].boundary()) continue;
        const FaceId y = tree_.across(EdgeId(a), FaceId(x));
        if (!tree_.in_side(y) && tree_.piece(y) == tree_.piece(FaceId(x)))
          boundary_.push_back({a, x, y.index()});
      }
  }

  double moved_slit(int e, int moved, const RigidMotion& motion) const {
    return slit_cost(seam_gap_per_length(tree_, EdgeId(e), FaceId(moved), motion), opt_.min_gap_per_length);
  }

  CutTree& tree_;
  const Mesh& m_;
  const EdgeConstraints& cons_;
  const std::vector<LabelFit>& fit_;
  const SeamMoveOptions& opt_;
  std::vector<std::vector<int>> edges_at_;
  std::vector<int> tried_;  // stamp_ of the best_move that last tried cutting the edge
  int stamp_ = 0;
  long work_ = 0;
  std::vector<int> side_;
  std::vector<Link> boundary_;
  std::vector<Move> candidates_;
};

int count_tight(const CutTree& tree, const std::vector<LabelFit>& fit) {
  if (fit.empty()) return 0;
  int n = 0;
  for (int e = 0; e < tree.mesh().num_edges(); ++e) {
    const auto& edge = tree.mesh().edges[e];
    n += fit[e] == LabelFit::Tight && !edge.boundary() && !tree.folded(EdgeId(e)) &&
         tree.piece(edge.face_id(0)) == tree.piece(edge.face_id(1));
  }
  return n;
}

}  // namespace

SeamMoveResult move_seams(CutTree& tree, const EdgeConstraints& constraints,
                          const std::vector<LabelFit>& label_fit, const SeamMoveOptions& options) {
  Mover mover(tree, constraints, label_fit, options);
  SeamMoveResult result;
  result.slits_before = count_slits(tree, options.min_gap_per_length);
  result.tight_before = count_tight(tree, label_fit);
  const long edges = tree.mesh().num_edges();
  // Each pass tries the slits first, then the seams that cost only by their labels: a slit is worth more.
  for (int pass = 0; pass < options.max_passes && !mover.out_of_work(); ++pass) {
    int moves_this_pass = 0;
    for (int phase = 0; phase < (options.label_moves ? 2 : 1); ++phase)
      for (int c = 0; c < edges && !mover.out_of_work(); ++c) {
        if (!mover.inner_seam(c)) continue;
        const bool is_slit = mover.slit(c) > 0;
        if (phase == 0 ? !is_slit : (is_slit || mover.label(c) <= 0)) continue;
        if (options.progress)
          options.progress((2L * pass + phase) * edges + c, 2L * options.max_passes * edges);
        const Move move = mover.best_move(c);
        if (!move.cut.valid()) continue;
        mover.apply(move);
        ++result.moves;
        ++moves_this_pass;
      }
    if (moves_this_pass == 0) break;
  }
  result.slits_after = count_slits(tree, options.min_gap_per_length);
  result.tight_after = count_tight(tree, label_fit);
  result.work = mover.work();
  return result;
}

}  // namespace foldkit::unfold
