#pragma once
// The dual graph of a mesh (faces joined across interior edges) and its spanning forests. A dual edge
// is identified with its mesh edge: folding a mesh edge keeps the dual edge, cutting it drops it.
#include <limits>
#include <vector>

#include "foldkit/unfold/edge_state.hpp"
#include "foldkit/unfold/mesh.hpp"

namespace foldkit::unfold {

/// The seed's minimum-perimeter weights (§4.1, after [SP05]): w(e) = (l_max - l) / (l_max - l_min),
/// so the longest edges weigh 0 and are folded first and the seams add up to a short total length.
/// Boundary edges get weight 1. All 0 when every edge has the same length.
std::vector<double> min_perimeter_weights(const Mesh& mesh);

/// What an edge must be, whatever an unfolder prefers: the user's --cut and --keep lists and the edges
/// inside flat faces (always folded).
enum class EdgeRule : unsigned char { Free, MustCut, MustFold };

/// One EdgeRule per mesh edge (or none at all: every edge free).
struct EdgeConstraints {
  EdgeMap<EdgeRule> rule;  ///< empty or one per mesh edge
  bool cut(EdgeId e) const { return e.index() < rule.size() && rule[e] == EdgeRule::MustCut; }
  bool fold(EdgeId e) const { return e.index() < rule.size() && rule[e] == EdgeRule::MustFold; }
};

/// Kruskal over the dual edges in increasing weight (ties by edge index, so the result is
/// deterministic): forced folds first, then every interior edge whose weight is below `threshold` and
/// that joins two different trees; every other edge is cut (boundary edges always). With the default
/// threshold this is the minimum spanning forest (one tree per connected component); a lower threshold
/// leaves spanning subtrees (the seed's initial patches).
EdgeStates spanning_forest(const Mesh& mesh, const std::vector<double>& weight,
                           const EdgeConstraints& constraints = {},
                           double threshold = std::numeric_limits<double>::infinity());

/// Number of connected components of the mesh (faces joined across interior edges).
int count_components(const Mesh& mesh);

}  // namespace foldkit::unfold
