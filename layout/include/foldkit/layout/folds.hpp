#pragma once
// Fold lines: one per fold edge of a piece, mountain or valley by the sign of the dihedral angle,
// near-flat folds left out, both ends pulled back from the vertices so that a scoring blade does not
// run into the outline and tear the corner.
#include <vector>

#include "foldkit/layout/outline.hpp"
#include "foldkit/sheet/sheet.hpp"
#include "foldkit/unfold/flat_faces.hpp"

namespace foldkit::layout {

struct FoldOptions {
  /// Folds with |angle| below this are flat and not drawn: the unfolding's flat-face angle, so that a
  /// fold hidden inside a flat face is never drawn either.
  double flat_fold_rad = unfold::kDefaultFlatAngleRad;
  /// Each end stops this far short of its vertex (never more than a quarter of the fold's length).
  double inset_mm = 0.6;
};

/// A fold segment in the piece's frame (mm, y up).
struct FoldLine {
  PathRole role = PathRole::Valley;  ///< Mountain or Valley
  Vec2 a, b;
  int edge = -1;  ///< mesh edge
};

/// The fold lines of `piece` (scaled from `unfolding`).
std::vector<FoldLine> fold_lines(const unfold::Unfolding& unfolding, const ScaledPiece& piece,
                                 const FoldOptions& options = {});

/// The role of a fold of signed dihedral `angle_rad` (> 0 mountain, < 0 valley).
PathRole fold_role(double angle_rad);

}  // namespace foldkit::layout
