#pragma once
// Direction arrows (the seed's Figure 1(c)): on both sides of every seam pair an arrow along the edge,
// inside the piece, pointing the same way along the 3D edge and drawn in the pair's own colour, so the
// matching edge and the way round it goes are found at a glance.
#include <span>
#include <vector>

#include "foldkit/layout/ids.hpp"
#include "foldkit/layout/outline.hpp"

namespace foldkit::layout {

struct ArrowOptions {
  double inset_mm = 0.7;      ///< distance of the arrow from its edge, inside the piece
  double length_ratio = 0.5;  ///< arrow length over edge length
  double head_mm = 1.2;       ///< length of the arrowhead's barbs
};

/// One arrow in its piece's frame (mm, y up): a polyline tail -> tip -> barb, tip -> other barb.
struct Arrow {
  SeamId seam;
  int side = 0, piece = -1;
  std::vector<Vec2> points_mm;
  Vec2 tail_mm, tip_mm;
};

/// Two arrows per seam. Side 0 points along its outline edge, side 1 against it: the two sides of a
/// seam run opposite ways around their faces, so both arrows then point the same way in 3D.
std::vector<Arrow> seam_arrows(std::span<const ScaledPiece> pieces, std::span<const Seam> seams,
                               const ArrowOptions& options = {});

}  // namespace foldkit::layout
