// The same packing problem handed to libnest2d (Cura's nester): no-fit-polygon placement with its
// subplex optimiser, first-fit selection. Kept to compare against the raster packer on the benchmark.
#include <algorithm>
#include <cmath>

#include <libnest2d/common.hpp>

namespace libnest2d {
// libnest2d is C++17: under C++20's rewritten comparisons Radians != Radians is ambiguous between
// its Degrees overloads; an exact match settles it.
inline bool operator!=(const Radians& a, const Radians& b) {
  return double(a) != double(b);
}
}  // namespace libnest2d

#include <libnest2d/libnest2d.hpp>

#include "foldkit/error.hpp"
#include "foldkit/layout/pack.hpp"

namespace foldkit::layout {
namespace {

constexpr double kUnitsPerMm = 1000.0;  // micrometres: Clipper's integer coordinates

ClipperLib::Path to_path(const Polygon& p, bool clockwise, double turn_rad) {
  ClipperLib::Path path;
  for (Vec2 v : p) {
    v = rotated(v, turn_rad);
    path.push_back({static_cast<ClipperLib::cInt>(std::llround(v.x * kUnitsPerMm)),
                    static_cast<ClipperLib::cInt>(std::llround(v.y * kUnitsPerMm))});
  }
  if (ClipperLib::Orientation(path) == clockwise) std::reverse(path.begin(), path.end());
  path.push_back(path.front());  // libnest2d's clipper backend wants closed contours
  return path;
}

// The item's largest outer loop with the holes inside it; other loops (rare: a label box apart from
// its face) are dropped by libnest2d's one-contour items, so the hull of everything stands in.
// libnest2d tries one set of rotations for all items: each item is turned first by its own best-fit
// angle (the one a part was cut to fit the sheet at), so the set is relative to that.
double pre_turn(const PackItem& item) {
  return item.rotate && !item.extra_angles_rad.empty() ? item.extra_angles_rad.front() : 0.0;
}

ClipperLib::Polygon to_shape(const PackItem& item) {
  const Polygon* outer = nullptr;
  for (const Polygon& p : item.shape_mm)
    if (signed_area(p) > 0 && (!outer || signed_area(p) > signed_area(*outer))) outer = &p;
  ClipperLib::Polygon shape;
  if (!outer) return shape;
  shape.Contour = to_path(*outer, true, pre_turn(item));
  return shape;
}

}  // namespace

PackResult pack_items_nest2d(std::span<const PackItem> items, const PackOptions& options) {
  using namespace libnest2d;
  if (!options.keep_out_mm.empty())
    throw LayoutError("the libnest2d packer does not support keep-out zones (registration marks)");
  std::vector<Item> input;
  input.reserve(items.size());
  for (const PackItem& item : items)
    input.emplace_back(to_shape(item));
  // A bin centred on the origin (libnest2d's own convention; a bin elsewhere placed nothing).
  const Vec2 centre = 0.5 * (options.area_mm.min + options.area_mm.max);
  const Box bin(static_cast<Coord>(options.area_mm.width() * kUnitsPerMm),
                static_cast<Coord>(options.area_mm.height() * kUnitsPerMm));
  NestConfig<NfpPlacer, FirstFitSelection> config;
  config.placer_config.rotations.clear();
  for (int k = 0; k < std::max(options.rotations, 1); ++k)
    config.placer_config.rotations.push_back(2 * Pi * k / std::max(options.rotations, 1));
  config.placer_config.alignment = NfpPlacer::Config::Alignment::DONT_ALIGN;
  config.placer_config.parallel = false;
  NestControl control;
  if (options.deadline) {
    const auto deadline = *options.deadline;
    control.stopcond = [deadline] { return std::chrono::steady_clock::now() > deadline; };
  }
  const auto spacing = static_cast<Coord>(options.spacing_mm * kUnitsPerMm);
  const std::size_t bins = nest(input, bin, spacing, config, control);
  if (options.deadline && std::chrono::steady_clock::now() > *options.deadline)
    throw LayoutError("stopped at the time limit while packing (libnest2d)");

  PackResult result;
  result.placements.resize(items.size());
  result.sheet_count =
      options.max_sheets ? std::min(static_cast<int>(bins), *options.max_sheets) : static_cast<int>(bins);
  for (std::size_t i = 0; i < items.size(); ++i) {
    const Item& it = input[i];
    if (it.binId() < 0 || (options.max_sheets && it.binId() >= *options.max_sheets)) {
      result.unplaced.push_back(static_cast<int>(i));
      continue;
    }
    const auto t = it.translation();
    result.placements[i] = {it.binId(), Rigid2{static_cast<double>(it.rotation()) + pre_turn(items[i]),
                                               centre + Vec2{t.X / kUnitsPerMm, t.Y / kUnitsPerMm}}};
  }
  return result;
}

}  // namespace foldkit::layout
