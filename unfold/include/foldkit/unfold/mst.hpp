#pragma once
// The baseline unfolder of [SP05], kept for comparison (`--method mst`): the minimum-perimeter
// spanning tree of the dual graph, laid flat, and every self-overlapping piece cut apart along the
// tree path between two overlapping faces until no piece overlaps.
#include <vector>

#include "foldkit/unfold/dual_graph.hpp"
#include "foldkit/unfold/mesh.hpp"
#include "foldkit/unfold/unfolding.hpp"

namespace foldkit::unfold {

/// Cuts fold edges of `state` until no piece of flatten(mesh, state) overlaps itself: for each overlapping
/// pair, one edge on the fold path between the two faces is cut (the one of largest weight, the most
/// preferred cut, in the middle half of the path, never a forced fold). Updates `state` and returns the final
/// unfolding. Throws Error (ExitCode::Usage) when forced folds alone make a piece overlap.
Unfolding cut_until_no_overlap(const Mesh& mesh, EdgeStates& state, const std::vector<double>& weight,
                               const EdgeConstraints& constraints = {});

/// [SP05]: the minimum spanning forest under cut_weights(mesh, cuts) (with SeamPreference::Short the
/// minimum-perimeter forest of the paper), then cut_until_no_overlap.
Unfolding unfold_mst(const Mesh& mesh, const EdgeConstraints& constraints = {}, const CutOptions& cuts = {});

/// Parent links of the fold forest of `state` (breadth first from the lowest face of each tree, as
/// flatten walks it): parent_face[f] / parent_edge[f] are -1 at roots; depth[f] counts folds to the root.
struct FoldForest {
  std::vector<int> parent_face, parent_edge, depth;
};
FoldForest fold_forest(const Mesh& mesh, const EdgeStates& state);

/// The fold edges on the forest path from face a to face b (empty if they are in different trees).
std::vector<EdgeId> fold_path(const FoldForest& forest, int a, int b);

}  // namespace foldkit::unfold
