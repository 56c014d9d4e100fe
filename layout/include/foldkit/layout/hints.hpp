#pragma once
// Assembly hints (§7.2 of the seed): an order in which to glue the seams so that sharp edges come
// first and flat ones last, preferring type-I stitching: closing a pair of matching edges that are
// neighbours along the current outline (a zipper), which needs no search for the partner.
#include <span>
#include <vector>

#include "foldkit/layout/outline.hpp"

namespace foldkit::layout {

/// The order (seam indices) in which to glue. `loops` are the boundary loops as sequences of seam
/// indices (-1 for mesh boundary edges that are never glued); every seam occurs exactly twice over all
/// loops. Gluing is simulated: at each step the sharpest (largest |fold_angle_rad|) seam whose two
/// sides are neighbours on a loop is glued, which removes both from the loop; when no such pair
/// exists, the sharpest seam left is glued, splitting its loop or joining two loops.
std::vector<int> assembly_order(std::vector<std::vector<int>> loops, std::span<const Seam> seams);

/// The loops of `pieces` as assembly_order wants them.
std::vector<std::vector<int>> seam_loops(std::span<const ScaledPiece> pieces, std::span<const Seam> seams);

}  // namespace foldkit::layout
