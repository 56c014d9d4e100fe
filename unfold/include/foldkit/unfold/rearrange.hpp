#pragma once
// The seed's rearrangement (§6, a Type II transformation): while more than one piece remains, stitch
// two pieces along the lightest edge between them whatever the overlaps, then cut the heaviest
// not-yet-visited edge on the path between overlapping faces. Bounded, so it always ends.
#include "foldkit/unfold/cut_tree.hpp"
#include "foldkit/unfold/dual_graph.hpp"

namespace foldkit::unfold {

/// Rearranges `tree` (overlap-free on entry) towards one piece per connected component, in at most
/// `max_operations` stitches and cuts. On return the tree is overlap-free again; returns true when it
/// reached one piece per component.
bool rearrange_pieces(CutTree& tree, int components, const EdgeConstraints& constraints, int max_operations);

}  // namespace foldkit::unfold
