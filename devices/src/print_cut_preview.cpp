#include "foldkit/devices/print_cut_preview.hpp"

#include <cmath>
#include <sstream>

#include "cairo_image.hpp"
#include "foldkit/devices/atomic_file.hpp"
#include "foldkit/devices/plan.hpp"
#include "foldkit/error.hpp"
#include "render_internal.hpp"

namespace foldkit::devices {
namespace {

constexpr double kMmPerInch = 25.4;
constexpr double kCutLineMm = 0.25;

}  // namespace

std::vector<std::vector<Vec2>> simulated_cuts_mm(const SimulatedDevice& sim, const DeviceProfile& device,
                                                 const std::string& mat) {
  const Vec2 area = cutting_area_mm(device, mat);
  // After a mark search the device's coordinates are relative to the mark it found, as in its render().
  const Vec2 origin = sim.mark_origin().value_or(Vec2{0, 0});
  std::vector<std::vector<Vec2>> out;
  for (const SimStroke& s : sim.strokes()) {
    std::vector<Vec2> line;
    line.reserve(s.points.size());
    for (Vec2 q : s.points)
      line.push_back(device_to_page(device, q + origin, area));
    out.push_back(std::move(line));
  }
  return out;
}

void render_print_and_cut(const Sheet& sheet, const std::vector<std::vector<Vec2>>& cuts_mm,
                          const std::filesystem::path& png, const RenderOptions& print) {
  RenderOptions options = print;
  options.format = "png";
  const double dpi = options.png_dpi;
  std::ostringstream printed;
  std::string error;
  if (!detail::write_png(printed, sheet, options, error)) throw OutputError(png.string(), error);
  const detail::SurfacePtr image = detail::decode_png(printed.str());
  if (cairo_surface_status(image.get()) != CAIRO_STATUS_SUCCESS)
    throw OutputError(png.string(), "cannot read back the rendered sheet");
  {
    const detail::ContextPtr cr(cairo_create(image.get()));
    const double px_per_mm = dpi / kMmPerInch;
    cairo_scale(cr.get(), px_per_mm, px_per_mm);
    cairo_set_source_rgb(cr.get(), 0.85, 0.05, 0.05);
    cairo_set_line_width(cr.get(), kCutLineMm);
    cairo_set_line_cap(cr.get(), CAIRO_LINE_CAP_ROUND);
    for (const auto& line : cuts_mm) {
      for (std::size_t i = 0; i < line.size(); ++i) {
        if (i == 0)
          cairo_move_to(cr.get(), line[i].x, line[i].y);
        else
          cairo_line_to(cr.get(), line[i].x, line[i].y);
      }
      cairo_stroke(cr.get());
    }
    if (cairo_status(cr.get()) != CAIRO_STATUS_SUCCESS)
      throw OutputError(png.string(), "cannot draw the cuts");
  }
  write_file_atomically(png, [&](std::ostream& out) {
    if (!detail::encode_png(image.get(), out)) throw OutputError(png.string(), "cannot encode the PNG");
  });
}

}  // namespace foldkit::devices
