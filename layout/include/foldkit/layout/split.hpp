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

/// How parts grow over a piece's folds: breadth-first along the fold tree from the piece's first face,
/// or round (from one end of the piece's long axis, nearest faces first: compact parts that nest), or
/// whichever of the two gives fewer parts.
enum class SplitGrowth { Fewest, Tree, Round };

/// Cuts every piece that does not fit piece_room_mm(options) at options.size_mm into parts that fit
/// that room scaled by `part_room_fraction` (1: as large as the sheet allows), growing each part over
/// the piece's folds for as long as it fits, then merging neighbouring parts that fit together. Without a
/// size (fit mode) or with options.split_oversized off nothing is split. A single face larger than the room
/// stays whole (layout_sheets then reports the largest size that fits).
SplitResult split_to_fit(const unfold::Mesh& mesh, const unfold::Unfolding& unfolding,
                         const LayoutOptions& options, double part_room_fraction = 1.0,
                         SplitGrowth growth = SplitGrowth::Fewest);

struct SplitLayout {
  SplitResult split;
  LayoutResult layout;
};

/// split_to_fit then layout_sheets; when a piece had to be split, round growth and smaller parts (0.7
/// and 0.5 of the room) are tried as well, until the sheet count reaches what the parts' area makes
/// likely, and the layout with the lowest 8 x sheets + parts is kept (a sheet saved is worth up to 8
/// more parts; ties: the first try, with the fewest parts).
/// Throws LayoutError as layout_sheets does.
SplitLayout split_and_layout(const unfold::Mesh& mesh, const unfold::Unfolding& unfolding,
                             const LayoutOptions& options);

}  // namespace foldkit::layout
