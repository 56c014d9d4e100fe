#pragma once
// Splitting pieces too large for the paper. An unfolder that reaches one piece (the point of the
// seed) often gives a piece larger than a sheet at the size the user wants; rather than refuse, the
// piece is cut along fold edges into as few parts as a greedy growth finds, each fitting the sheet.
// The input unfolding is left alone: the result is a new unfolding of the same mesh whose cuts are the
// old cuts plus the new ones, so every part is a sub-tree of an old piece and overlaps nothing.
#include <string>

#include "foldkit/layout/layout.hpp"
#include "foldkit/unfold/mesh.hpp"
#include "foldkit/unfold/unfolding.hpp"

namespace foldkit::layout {

struct SplitResult {
  unfold::Unfolding unfolding;
  int split_pieces = 0;  ///< pieces that were too large
  int new_pieces = 0;    ///< parts they were cut into
};

/// Cuts every piece that does not fit piece_room_mm(options) at options.size_mm into parts that do,
/// growing each part breadth-first along the piece's folds from its lowest face for as long as it
/// fits. Without a size (fit mode) nothing is split. A single face larger than the room stays whole
/// (layout_sheets then reports the largest size that fits).
SplitResult split_to_fit(const unfold::Mesh& mesh, const unfold::Unfolding& unfolding,
                         const LayoutOptions& options);

}  // namespace foldkit::layout
