#pragma once
// Seam moves: after the search, cuts move to where the sheet needs them. A move cuts a fold edge and
// folds a cut edge of the cycle that makes, the cut-off side moving rigidly; it is taken when it lowers
// the seams' total cost and adds no overlap. A seam costs as a slit (slits.hpp: no glue tab fits) and
// by how well its two labels fit beside it (LabelFit, dual_graph.hpp): the pass closes slits and moves
// cuts off edges too tight for a label, never making the slits worse for a label.
#include <functional>
#include <vector>

#include "foldkit/unfold/cut_tree.hpp"
#include "foldkit/unfold/dual_graph.hpp"
#include "foldkit/unfold/slits.hpp"

namespace foldkit::unfold {

struct SeamMoveOptions {
  /// A seam within one piece narrower than this (gap per length) is a slit (slits.hpp).
  double min_gap_per_length = kSlitGapPerLength;
  /// What a cut edge costs by its LabelFit: Tight, OnTab (BothSides costs nothing). A slit costs 1 to 2,
  /// so closing one is worth more than any label; a label is worth more than narrowing a slit a little.
  double tight_label_cost = 0.5;
  double tab_label_cost = 0.2;
  /// Folds on the cycle of a cut edge with a label cost tried for cutting, from each of its two ends.
  int cycle_ends = 6;
  /// Also move seams that cost only by their labels (after the slits, each pass). Off: only slits are
  /// tried, their moves still judged by the labels too.
  bool label_moves = true;
  /// Passes over the seams; each pass tries every costly seam once and stops early when nothing improved.
  int max_passes = 6;
  /// Work budget, in faces and seams looked at (sides grown and re-tested for overlaps, cycles walked,
  /// links re-measured per candidate): the pass stops there, whatever the clock says, so the result is
  /// the same on a busy machine and an idle one. The tree is overlap-free after every move, so stopping
  /// early is safe. At 60-70 million units a second (measured on a busy 2-core machine) this is about
  /// 6 s there, reached only by the slowest 2,000-face meshes (rocker_arm_2000 needs 800 million to
  /// finish at 250 mm; the others 50-250 million).
  long work_limit = 400'000'000;
  /// When set, a move is taken only if this also accepts it: `side` (faces of one piece) moved rigidly by
  /// `motion`, the rest of the piece where it lies (e.g. the piece must still fit a sheet).
  std::function<bool(const CutTree& tree, const std::vector<int>& side, const RigidMotion& motion)> accept;
  /// Called for each seam tried, with the seams looked at over all passes and the most there can be;
  /// may be empty.
  std::function<void(long done, long total)> progress;
};

struct SeamMoveResult {
  int slits_before = 0;
  int slits_after = 0;
  int tight_before = 0;  ///< cut edges within one piece graded Tight
  int tight_after = 0;
  int moves = 0;
  long work = 0;  ///< in SeamMoveOptions::work_limit's units
};

/// Moves seams of `tree` (overlap-free on entry, and after every move): cuts a fold edge near a costly
/// seam and folds instead a cut edge on the cycle that makes, when that lowers the seams' total cost
/// (slit cost plus label cost by `label_fit`, one grade per edge, or empty: no label cost) without
/// raising the slits' cost, and adds no overlap. The number of pieces does not change; forced cuts and
/// folds are honoured; the curvature rule (cut edges a vertex needs) is kept. Deterministic: the same
/// tree and options give the same cuts, however long it takes.
SeamMoveResult move_seams(CutTree& tree, const EdgeConstraints& constraints,
                          const std::vector<LabelFit>& label_fit, const SeamMoveOptions& options);

}  // namespace foldkit::unfold
