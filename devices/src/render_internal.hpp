#pragma once
// Shared between the renderers: drawing order, number formatting and the text metrics that make
// `Text::height_mm` a cap height in every format.
#include <array>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "foldkit/devices/render.hpp"

namespace foldkit::devices::detail {

/// Roles in painting order: fills and marks under everything, cuts above folds, marks on top.
inline constexpr std::array<PathRole, 9> kPaintOrder = {
    PathRole::Tab, PathRole::Piece, PathRole::Hint,    PathRole::Valley, PathRole::Mountain,
    PathRole::Cut, PathRole::Label, PathRole::RegMark, PathRole::Sheet};

/// Colour `tint` (>= 0) of a palette of twelve colours that stay apart on paper (Path::tint).
inline Rgb tint_colour(int tint) {
  static constexpr std::array<Rgb, 12> kPalette = {{{0.90, 0.10, 0.10},
                                                    {0.10, 0.45, 0.85},
                                                    {0.05, 0.60, 0.20},
                                                    {0.95, 0.55, 0.00},
                                                    {0.55, 0.20, 0.75},
                                                    {0.00, 0.65, 0.65},
                                                    {0.85, 0.20, 0.60},
                                                    {0.45, 0.30, 0.10},
                                                    {0.50, 0.65, 0.00},
                                                    {0.15, 0.15, 0.55},
                                                    {0.75, 0.45, 0.45},
                                                    {0.35, 0.35, 0.35}}};
  return kPalette[static_cast<std::size_t>(tint) % kPalette.size()];
}

/// One row of the legend of line styles: a sample of `role` drawn `sample` (a line, or a filled box
/// for tabs) and its name.
struct LegendRow {
  PathRole role;
  const char* name;
  bool box;
};
inline constexpr std::array<LegendRow, 4> kLegend = {{{PathRole::Cut, "cut", false},
                                                      {PathRole::Mountain, "mountain fold", false},
                                                      {PathRole::Valley, "valley fold", false},
                                                      {PathRole::Tab, "glue tab", true}}};
/// Row pitch and sample length of the legend (mm), and its text's cap height.
inline constexpr double kLegendRow_mm = 5.5, kLegendSample_mm = 8, kLegendText_mm = 2.2;

/// Where entry `i` of the legend starts (its sample's left end, on the sample's centre line): stacked
/// rows in the box, or side by side along it (Sheet::legend_in_row).
inline Vec2 legend_entry_mm(const Sheet& sheet, std::size_t i) {
  const Box2& box = sheet.legend_mm;
  const double at = static_cast<double>(i);
  if (sheet.legend_in_row)
    return {box.min.x + at * box.width() / static_cast<double>(kLegend.size()),
            0.5 * (box.min.y + box.max.y)};
  return {box.min.x, box.min.y + kLegendRow_mm * (at + 0.5)};
}
/// Stroke width of the white halo under texts on coloured sheets, per millimetre of cap height.
inline constexpr double kHaloPerCap = 0.35;

/// The colour of a filled, tinted path (the guide's part colours): the tint lightened, times its shade.
inline Rgb shaded_fill(const Path& path) {
  constexpr double kLighten = 0.35;
  const Rgb t = tint_colour(path.tint);
  auto mix = [&](double c) { return (c + kLighten * (1 - c)) * path.shade; };
  return {mix(t.r), mix(t.g), mix(t.b)};
}

/// The style `role` is drawn in on `sheet`: fold lines lightened or hidden as options.fold_lines says,
/// tabs unfilled on coloured sheets (their fills are the sheet's). nullopt: the role is not drawn.
std::optional<RoleStyle> sheet_style(const RenderOptions& options, const Sheet& sheet, PathRole role);

/// Cap height of `family` as a fraction of its font size (DejaVu Sans: about 0.73), measured with Cairo
/// so that PDF, PNG and SVG texts come out the same size.
double cap_height_ratio(const std::string& family);

/// Cap heights as fractions of the font size, of the text family and of the label family.
struct CapRatios {
  double text = 0.72;
  double label = 0.72;
};

/// Both families of `options` measured with cap_height_ratio.
CapRatios cap_height_ratios(const RenderOptions& options);

/// True for the roles printed in the label family (seam labels and their hints).
bool in_label_font(PathRole role);

/// Writes one sheet as a standalone SVG document.
void write_svg(std::ostream& out, const Sheet& sheet, const RenderOptions& options, const CapRatios& caps);

/// Writes all sheets as one PDF document, one page per sheet. Returns false with `error` set on failure.
bool write_pdf(std::ostream& out, const std::vector<Sheet>& sheets, const RenderOptions& options,
               const std::string& title, std::string& error);

/// Appends to a finished PDF an incremental update whose catalog asks viewers to print at 100%
/// (/ViewerPreferences << /PrintScaling /None >>). Returns false, leaving `pdf` untouched, when the
/// file's structure is not the plain one Cairo writes.
bool ask_viewers_not_to_scale(std::string& pdf);

/// Writes one sheet as a PNG image at options.png_dpi. Returns false with `error` set on failure.
bool write_png(std::ostream& out, const Sheet& sheet, const RenderOptions& options, std::string& error);

/// Pixel size of a sheet's PNG preview.
std::array<int, 2> png_size_px(const Sheet& sheet, double dpi);

}  // namespace foldkit::devices::detail
