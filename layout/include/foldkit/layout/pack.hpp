#pragma once
// Packing piece outlines (with their tabs) onto sheets: bottom-left fill ("top-left" on the page) of
// rasterised, rotated shapes. Each item is tried at several rotations on every open sheet; the first
// sheet where it fits takes it at the highest, then leftmost, free position; when none has room a new
// sheet is opened. Shapes are rasterised conservatively (every cell the grown shape touches is taken),
// so placed items never overlap and keep at least `spacing_mm` apart, and concave pieces can nest
// into each other's bays and holes.
#include <chrono>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "foldkit/layout/polygon.hpp"

namespace foldkit::layout {

/// What to pack: a set of polygons (non-zero fill) in the item's own frame, mm, y up.
struct PackItem {
  std::vector<Polygon> shape_mm;
  /// Rotations worth trying besides the evenly spaced ones (e.g. the one that fits the sheet best).
  std::vector<double> extra_angles_rad;
  bool rotate = true;  ///< false: only the item's own orientation (blocks of text)
};

/// Which packer: the raster bottom-left fill (below), or libnest2d's no-fit-polygon nester (compared on
/// the layout benchmark; it nests convex hulls only, so it cannot use the bays of concave parts).
enum class PackEngine { Raster, Nest2d };

struct PackOptions {
  PackEngine engine = PackEngine::Raster;
  Box2 area_mm{{0, 0}, {190, 277}};  ///< where items may go, sheet frame (mm, y up)
  std::vector<Box2> keep_out_mm;     ///< regions nothing may come within spacing_mm of
  double spacing_mm = 2;             ///< least gap between two items
  double cell_mm = 0.5;              ///< raster resolution: smaller packs tighter, costs more time
  /// Evenly spaced rotations tried (4: multiples of 90 degrees). 24 (15 degrees apart) against 8, over
  /// `bench --layout` up to 1,000 faces: 466 sheets instead of 472, 13 runs more than one sheet over the
  /// area bound instead of 16, for 22-30% more time.
  int rotations = 24;
  /// Each item is also turned so that each of its this many longest convex hull edges lies along the
  /// sheet's sides (four quarter turns each): a part lies flush against the sheet's edge or a
  /// neighbour's straight side along such an edge. 3 against 0 over `bench --layout` up to 1,000
  /// faces: 441 sheets instead of 442, 3,225 parts instead of 3,274, for 5-12% more CPU (session 46).
  int aligned_hull_edges = 3;
  /// Most shaken largest-first orders tried when the plain ones leave a sheet more than the area
  /// needs (fewer for many items); 0: none.
  int shaken_orders = 16;
  /// Most orders spent emptying sheets once packed: the emptiest sheet's items are packed again with
  /// those of one or two other sheets onto them and one more, keeping what leaves the last emptier;
  /// a sheet left empty is saved. 0: none.
  int sheet_search_orders = 60;
  /// Orders packed at once; 0: as many as the hardware has. The result does not depend on it.
  int threads = 0;
  /// When set, no more sheets than this are opened: items that do not fit are reported as unplaced.
  std::optional<int> max_sheets;
  /// When set, packing stops here with a LayoutError: no input makes it run unbounded.
  std::optional<std::chrono::steady_clock::time_point> deadline;
  /// Called after each order packed with the placements made and the most the packing can make (items
  /// times the orders it may try; it ends at that count, also when it stops trying orders early), on
  /// the calling thread.
  std::function<void(long done, long total)> progress;
};

/// Where an item went: sheet index and the motion from the item's frame to the sheet frame.
struct PackPlacement {
  int sheet = -1;  ///< -1 when unplaced
  Rigid2 transform;
};

struct PackResult {
  std::vector<PackPlacement> placements;  ///< one per item, in input order
  int sheet_count = 0;
  std::vector<int> unplaced;  ///< items that fit no sheet (too large, or max_sheets reached)
};

/// Packs `items` (largest first) onto as few sheets as the heuristic finds. Throws LayoutError when the
/// deadline passes.
PackResult pack_items(std::span<const PackItem> items, const PackOptions& options);

/// A lower bound on the sheets that items need, counting their shapes, not only their area: `cores_mm`
/// holds, for each item, a convex counter-clockwise polygon lying inside it (a flat face no packing
/// may cut). Items lie inside `area_mm` at any rotation and position and never overlap. For a point set
/// P in the area (a lattice), every placement of core i covers at least c_i points of P (found over
/// all rotations and positions); items on one sheet cover disjoint points, so no packing needs fewer
/// than ceil(sum c_i / |P|) sheets. The largest such count over a few lattices and grids that cut the
/// area into equal spans; 0 without items. A 150 mm square on A4 covers the centre wherever it lies, so
/// six of them need six sheets (area: three); a 104 mm square covers one of the two points at a third and
/// two thirds of the centre line, so eighteen need nine (area: four).
long shape_sheet_bound(std::span<const Polygon> cores_mm, const Box2& area_mm);

/// The same with libnest2d (options.engine is ignored; keep-outs are not supported).
PackResult pack_items_nest2d(std::span<const PackItem> items, const PackOptions& options);

}  // namespace foldkit::layout
