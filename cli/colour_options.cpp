#include "colour_options.hpp"

#include "foldkit/layout/paper.hpp"
#include "length_option.hpp"

namespace foldkit::cli {
namespace {

std::optional<double> bleed_mm(const std::string& text) {
  return layout::parse_non_negative_length_mm(text);
}

// A bleed wider than this only wastes paper and pushes pieces apart.
constexpr double kMaxBleedMm = 10;

}  // namespace

void add_colour_options(CLI::App& cmd, ColourCliOptions& o) {
  cmd.add_option("--bleed", o.bleed,
                 "How far colour reaches past every cut line, e.g. 1mm (0 for none; up to " +
                     format_length_mm(kMaxBleedMm) + ")")
      ->transform(length_in({0, kMaxBleedMm}))
      ->capture_default_str();
  cmd.add_option("--tab-fill", o.tab_fill, "Glue tabs in the colour of the face they glue under, or white")
      ->check(CLI::IsMember({"face", "white"}))
      ->capture_default_str();
  cmd.add_option(
         "--fold-lines", o.fold_lines,
         "Fold lines drawn normal, light or not at all (none; a cutter still scores them); auto: light "
         "on coloured sheets")
      ->check(CLI::IsMember({"auto", "normal", "light", "none"}))
      ->capture_default_str();
  cmd.add_option("--dpi-print", o.dpi_print, "Finest resolution textures are embedded at, dpi")
      ->check(number_in(50, 2400, "dpi"))
      ->capture_default_str();
  cmd.add_flag("--no-colour,--no-color", o.no_colour, "Print white pieces even when the model has colours");
}

std::optional<layout::FillOptions> to_fill_options(const ColourCliOptions& o) {
  if (o.no_colour) return std::nullopt;
  layout::FillOptions out;
  out.bleed_mm = bleed_mm(o.bleed).value_or(1.0);  // validated when parsing
  out.tab_fill = o.tab_fill == "white" ? layout::TabFill::White : layout::TabFill::Face;
  return out;
}

void apply_colour_render_options(const ColourCliOptions& o, bool coloured, devices::RenderOptions& render) {
  const std::string style = o.fold_lines == "auto" ? (coloured ? "light" : "normal") : o.fold_lines;
  render.fold_lines = style == "none"    ? devices::FoldLines::None
                      : style == "light" ? devices::FoldLines::Light
                                         : devices::FoldLines::Normal;
  render.image_dpi = o.dpi_print;
}

}  // namespace foldkit::cli
