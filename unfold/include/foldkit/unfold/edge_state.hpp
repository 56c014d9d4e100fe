#pragma once
// The one per-edge state of an unfolding under construction: every mesh edge is folded or cut. A
// boundary edge is always Cut (it has no second face to fold onto). What the user or the flat faces
// demand of an edge is a separate thing, EdgeRule (dual_graph.hpp): a rule is an input, a state a result.
#include "foldkit/unfold/ids.hpp"

namespace foldkit::unfold {

/// What an edge is in an unfolding: a fold joins its two faces in one piece, a cut separates them.
enum class EdgeState : unsigned char { Fold, Cut };

/// One EdgeState per mesh edge: the form every unfolder takes and returns (CutTree, flatten, search, GA).
using EdgeStates = EdgeMap<EdgeState>;

/// Every edge in `state`.
inline EdgeStates all_edges(int num_edges, EdgeState state) {
  return EdgeStates(num_edges, state);
}

}  // namespace foldkit::unfold
