#include "limits.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "foldkit/error.hpp"

namespace foldkit::cli {
namespace {

constexpr double kMmPerInch = 25.4;

double surface_area(const unfold::Mesh& mesh) {
  double area = 0;
  for (int f = 0; f < mesh.num_faces(); ++f) {
    const auto [a, b, c] = mesh.corners(f);
    area += 0.5 * norm(cross(b - a, c - a));
  }
  return area;
}

}  // namespace

// Rounded as the renderer rounds (render_cairo.cpp).
void check_png_raster(Vec2 paper_mm, double dpi) {
  const double width = std::round(paper_mm.x / kMmPerInch * dpi),
               height = std::round(paper_mm.y / kMmPerInch * dpi);
  if (width * height <= kMaxPngPixels) return;
  const double largest_dpi = std::floor(std::sqrt(kMaxPngPixels / (paper_mm.x * paper_mm.y)) * kMmPerInch);
  char text[256];
  std::snprintf(
      text, sizeof text,
      "--dpi %g: a %gx%g mm sheet is %.0fx%.0f pixels (%.0f million), over the limit of %.0f million; "
      "--dpi %.0f at most",
      dpi, paper_mm.x, paper_mm.y, width, height, width * height / 1e6, kMaxPngPixels / 1e6, largest_dpi);
  throw Error(text, ExitCode::Usage);
}

void check_sheet_budget(const unfold::Mesh& mesh, const layout::LayoutOptions& options) {
  if (!options.size_mm || options.fit || mesh.vertices.empty()) return;
  const double extent = unfold::bounds_of(mesh).largest_dimension();
  if (!(extent > 0)) return;
  const Box2 area = layout::printable_area(options);
  const double sheet_mm2 = area.width() * area.height();
  if (!(sheet_mm2 > 0)) return;
  // Area scales with the square of the size: the size at which the surface fills the budget exactly.
  const double model_mm2_per_size2 = surface_area(mesh) / (extent * extent);
  const double sheets = model_mm2_per_size2 * *options.size_mm * *options.size_mm / sheet_mm2;
  if (sheets <= kMaxSheets) return;
  const double largest = std::sqrt(kMaxSheets * sheet_mm2 / model_mm2_per_size2);
  char text[256];
  std::snprintf(
      text, sizeof text,
      "--size %s: the model's surface alone would fill %.0f sheets of %gx%g mm, over the limit of %d; "
      "the largest --size that fits %d sheets is %.0fmm",
      format_length_mm(*options.size_mm).c_str(), sheets, options.paper_mm.x, options.paper_mm.y, kMaxSheets,
      kMaxSheets, std::floor(largest));
  throw LayoutError(text);
}

}  // namespace foldkit::cli
