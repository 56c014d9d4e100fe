#include "foldkit/layout/arrows.hpp"

#include <algorithm>

namespace foldkit::layout {

std::vector<Arrow> seam_arrows(std::span<const ScaledPiece> pieces, std::span<const Seam> seams,
                               const ArrowOptions& o) {
  std::vector<Arrow> arrows;
  for (std::size_t s = 0; s < seams.size(); ++s)
    for (int k = 0; k < 2; ++k) {
      const SeamSide& side = seams[s].sides[k];
      if (side.piece < 0) continue;
      const OutlineEdge& e = pieces[side.piece].outline_mm[side.loop][side.index];
      const double length = norm(e.b - e.a);
      if (length <= 0) continue;
      const Vec2 along = (e.b - e.a) / length;
      const Vec2 inward = perp_ccw(along);
      const Vec2 dir = k == 0 ? along : -along;
      const Vec2 mid = 0.5 * (e.a + e.b) + inward * std::min(o.inset_mm, 0.2 * length);
      const double half = 0.5 * o.length_ratio * length;
      const Vec2 tail = mid - dir * half, tip = mid + dir * half;
      const double head = std::min(o.head_mm, 0.6 * half);
      // Barbs at 30 degrees to the shaft.
      const Vec2 back = -dir * (head * 0.866);
      const Vec2 side_step = perp_ccw(dir) * (head * 0.5);
      arrows.push_back({SeamId(static_cast<int>(s)),
                        k,
                        side.piece,
                        {tail, tip, tip + back + side_step, tip, tip + back - side_step},
                        tail,
                        tip});
    }
  return arrows;
}

}  // namespace foldkit::layout
