#pragma once
// The options of coloured printing (make, cut): bleed, tab fill, fold-line style, print resolution.
// cut takes them too, because the bleed widens the spacing between pieces and so moves them: the same
// options on both commands give the same outlines.
#include <string>

#include <CLI/CLI.hpp>

#include "foldkit/devices/render.hpp"
#include "foldkit/layout/fills.hpp"

namespace foldkit::cli {

struct ColourCliOptions {
  std::string bleed = "1mm";
  std::string tab_fill = "face";
  std::string fold_lines = "auto";  ///< auto: light on coloured sheets, normal otherwise
  double dpi_print = 300;
  bool no_colour = false;
};

/// Adds --bleed, --tab-fill, --fold-lines, --dpi-print and --no-colour to `cmd`.
void add_colour_options(CLI::App& cmd, ColourCliOptions& options);

/// The fill options, or nullopt with --no-colour.
std::optional<layout::FillOptions> to_fill_options(const ColourCliOptions& options);

/// Applies the fold-line style and print resolution to `render`; `coloured`: the sheets have fills.
void apply_colour_render_options(const ColourCliOptions& options, bool coloured,
                                 devices::RenderOptions& render);

}  // namespace foldkit::cli
