#pragma once
// The dual graph of a mesh (faces joined across interior edges) and its spanning forests. A dual edge
// is identified with its mesh edge: folding a mesh edge keeps the dual edge, cutting it drops it.
#include <limits>
#include <vector>

#include "foldkit/unfold/mesh.hpp"

namespace foldkit::unfold {

/// The seed's minimum-perimeter weights (§4.1, after [SP05]): w(e) = (l_max - l) / (l_max - l_min),
/// so the longest edges weigh 0 and are folded first and the seams add up to a short total length.
/// Boundary edges get weight 1. All 0 when every edge has the same length.
std::vector<double> min_perimeter_weights(const Mesh& mesh);

/// Per-edge flags for edges the user forces to be cut or to stay folded.
struct EdgeConstraints {
  std::vector<char> force_cut;   ///< empty or one flag per mesh edge
  std::vector<char> force_fold;  ///< empty or one flag per mesh edge
  bool cut(int e) const { return e < static_cast<int>(force_cut.size()) && force_cut[e]; }
  bool fold(int e) const { return e < static_cast<int>(force_fold.size()) && force_fold[e]; }
};

/// Kruskal over the dual edges in increasing weight (ties by edge index, so the result is
/// deterministic): forced folds first, then every interior edge whose weight is below `threshold` and
/// that joins two different trees. Returns one cut flag per mesh edge (1 = cut); boundary edges are
/// always cut. With the default threshold this is the minimum spanning forest (one tree per connected
/// component); a lower threshold leaves spanning subtrees (the seed's initial patches).
std::vector<char> spanning_forest_cuts(const Mesh& mesh, const std::vector<double>& weight,
                                       const EdgeConstraints& constraints = {},
                                       double threshold = std::numeric_limits<double>::infinity());

/// Number of connected components of the mesh (faces joined across interior edges).
int count_components(const Mesh& mesh);

}  // namespace foldkit::unfold
