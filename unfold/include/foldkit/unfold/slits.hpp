#pragma once
// Slits: glued seams whose two sides lie against each other in one piece, so that no glue tab fits on
// either side. The common one is a cut-tree leaf at a nearly flat vertex: its two sides meet there at
// an angle equal to the vertex's defect, about a degree on a 1,000-face mesh. A cut path through flat
// vertices whose branch beyond turns by almost nothing makes a longer one, both sides touching along
// several edges. Moving the cuts (cut a fold edge at the slit, fold a cut edge of the cycle that makes)
// closes them; the leaves left are at the cone points (nose, ears, tips), where the wedge is wide.
#include <functional>
#include <vector>

#include "foldkit/unfold/cut_tree.hpp"
#include "foldkit/unfold/dual_graph.hpp"

namespace foldkit::unfold {

struct SlitOptions {
  /// A seam within one piece is a slit when the two copies of each of its ends are closer than this
  /// fraction of its length: the far end of a leaf's wedge then opens by less than about 40 degrees,
  /// too little for a tab of a third of the edge's length whose slants stay in the wedge.
  double min_gap_per_length = 0.7;
  /// Passes over the slits; each pass tries every slit once and stops early when nothing improved.
  int max_passes = 6;
  /// Wall-clock budget; the tree is overlap-free after every move, so stopping early is safe.
  double time_limit_s = 5;
  /// Called for each slit tried, with the edges looked at over all passes and the most there can be
  /// (passes times edges); may be empty.
  std::function<void(long done, long total)> progress;
};

struct SlitResult {
  int slits_before = 0;
  int slits_after = 0;
  int moves = 0;
};

/// How far apart the two sides of cut edge e lie, relative to its length: the larger of the distances
/// between the two copies of each end. Infinite for a boundary edge, a fold or a seam between pieces.
double seam_gap_per_length(const CutTree& tree, EdgeId e);

/// Number of slits of `tree` (seams whose gap per length is below `min_gap_per_length`).
int count_slits(const CutTree& tree, double min_gap_per_length);

/// Closes slits of `tree` (overlap-free on entry, and after every move): cuts a fold edge at an end of a
/// slit and folds instead a cut edge on the cycle that makes, moving the cut-off side rigidly, when that
/// lowers the slits' total cost (each slit costs more the tighter it is) and adds no overlap. The number
/// of pieces does not change; forced cuts and folds are honoured; the curvature rule (cut edges a vertex
/// needs) is kept. Deterministic unless stopped by the time limit.
SlitResult close_slits(CutTree& tree, const EdgeConstraints& constraints, const SlitOptions& options);

}  // namespace foldkit::unfold
