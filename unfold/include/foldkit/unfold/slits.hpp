#pragma once
// Slits: cut-tree leaves at vertices with little angle defect. At a leaf the two sides of its one cut
// edge meet at an angle equal to the vertex's defect, so where the surface is nearly flat there the
// net has a narrow slit with no room for a glue tab on either side. On a 1,000-face mesh the average
// defect is about a degree and most leaves are slits. Moving the cuts so that the cut path runs on
// through such a vertex (two cut edges there: the free angles sum to 2 pi plus the defect) closes the
// slit; the leaves left are at the cone points (nose, ears, tips), where the wedge is wide.
#include <cstdint>
#include <vector>

#include "foldkit/unfold/cut_tree.hpp"
#include "foldkit/unfold/dual_graph.hpp"

namespace foldkit::unfold {

struct SlitOptions {
  /// A leaf whose vertex's defect is below this is a slit. About 30 degrees leaves a wedge in which a
  /// tab of a third of its edge's length fits (its slants within the wedge).
  double min_leaf_defect_rad = 30.0 * 3.14159265358979323846 / 180.0;
  /// Passes over the slits; each pass tries every slit once and stops early when nothing improved.
  int max_passes = 6;
  /// Wall-clock budget; the tree is overlap-free after every move, so stopping early is safe.
  double time_limit_s = 5;
};

struct SlitResult {
  int slits_before = 0;
  int slits_after = 0;
  int moves = 0;
};

/// True when vertex v is a slit of `tree`: exactly one cut edge there and a defect below the limit.
bool is_slit(const CutTree& tree, const std::vector<double>& defect_rad, int v, double min_leaf_defect_rad);

/// Number of slits of `tree`.
int count_slits(const CutTree& tree, const std::vector<double>& defect_rad, double min_leaf_defect_rad);

/// Closes slits of `tree` (overlap-free on entry, and after every move): for a slit vertex, cuts one of
/// its fold edges and folds instead a cut edge on the cycle that makes, moving the cut-off side rigidly,
/// when that lowers the number of slits and adds no overlap. The number of pieces does not change;
/// forced cuts and folds are honoured; the curvature rule (cut edges a vertex needs) is kept.
/// Deterministic unless stopped by the time limit.
SlitResult close_slits(CutTree& tree, const EdgeConstraints& constraints, const SlitOptions& options);

}  // namespace foldkit::unfold
