#pragma once
// Tabs grown after packing. Tabs planned for labels (on the side whose face has no room for its label,
// with steep ends and the label's height, or split in two halves) take paper the part chooser's estimate
// did not see; where they would cost a sheet, the pieces are packed with plainer tabs. Packed sheets
// still have free paper around most pieces: seam by seam, the tabs the plan for labels wanted are taken
// wherever they stay clear of every other piece (by the packing's spacing), of their own piece's other
// tabs, and inside the packing area and out of its keep-out zones. No piece moves and no seam loses its
// tab, so the sheets stay as packed.
#include <span>
#include <vector>

#include "foldkit/layout/outline.hpp"
#include "foldkit/layout/pack.hpp"
#include "foldkit/layout/polygon.hpp"
#include "foldkit/layout/tabs.hpp"

namespace foldkit::layout {

/// The packed sheets as tabs_in_place sees them, all in the packing frame (mm, y up).
struct PackedRoom {
  /// Per piece, where packing put it (transform from the piece's frame to the packing frame).
  std::span<const PackPlacement> placements;
  /// Per piece, the convex shapes it covers besides its tabs, in its own frame: its triangles and any
  /// label box that sticks out of it.
  std::span<const std::vector<Polygon>> bodies_mm;
  /// Other convex shapes packed on a sheet (an assembly list's block), with their sheet.
  std::span<const std::pair<int, Polygon>> others_mm;
  Box2 area_mm;                       ///< where every shape must stay
  std::span<const Box2> keep_out_mm;  ///< what no shape may come within spacing_mm of
  double spacing_mm = 0;              ///< the least distance between two pieces (with their tabs)
};

/// `placed` with, seam by seam in seam order, the tabs of `wanted` where they differ and the packed room
/// holds all of them; a seam whose wanted tabs would leave it without one keeps its own. Returns the
/// mixed plan (its `dropped` brought up to date). Both plans are for the same pieces and seams.
TabPlan tabs_in_place(std::span<const Seam> seams, const TabPlan& placed, const TabPlan& wanted,
                      const PackedRoom& room);

/// Whether each of `shapes` (convex, each in the frame of its piece, the pair's first) stays inside the
/// area, out of the keep-out zones and clear by the spacing of every other piece, with its tabs in `plan`.
bool clear_in_place(std::span<const std::pair<int, Polygon>> shapes, std::span<const Seam> seams,
                    const TabPlan& plan, const PackedRoom& room);

}  // namespace foldkit::layout
