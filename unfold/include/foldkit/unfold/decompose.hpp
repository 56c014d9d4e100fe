#pragma once
// The seed's initial decomposition (§4): small patches from spanning subtrees of the dual graph under
// a weight threshold, and self-overlaps inside a piece resolved by cutting along the path between
// the two overlapping faces (§4.2, after [SP05]).
#include "foldkit/unfold/cut_tree.hpp"
#include "foldkit/unfold/dual_graph.hpp"

namespace foldkit::unfold {

/// The spanning subtrees (Kruskal over the minimum-perimeter weights, forced folds first) that leave
/// about `disconnected_share` (e.g. 0.65) of the interior edges cut.
EdgeStates initial_patches(const UnfoldContext& context, double disconnected_share,
                           const EdgeConstraints& constraints);

/// Cuts edges of `tree` until no piece overlaps itself: for an overlapping pair, the heaviest
/// (shortest) fold edge on the path between them that is not a forced fold. Deterministic.
/// Throws Error (ExitCode::Usage) when only forced folds remain on such a path.
void cut_overlaps(CutTree& tree, const EdgeConstraints& constraints);

}  // namespace foldkit::unfold
