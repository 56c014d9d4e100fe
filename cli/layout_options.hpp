#pragma once
// The layout options every command that lays out sheets shares (make, cut): paper, scale, margins,
// tabs, numbers, arrows, hints and registration marks.
#include <string>

#include <CLI/CLI.hpp>

#include "choose_parts.hpp"
#include "foldkit/layout/layout.hpp"

namespace foldkit::cli {

struct LayoutCliOptions {
  std::string size;  ///< millimetres as text once parsed ("6in" becomes "152.4"); empty: --fit
  bool fit = false;
  std::string paper = "A4";
  bool landscape = false;
  double margin_mm = layout::LayoutOptions{}.margin_mm;
  double tab_width_mm = layout::TabOptions{}.width_mm;
  bool no_tabs = false;
  bool no_split = false;
  bool no_numbers = false;
  bool arrows = false;
  bool hints = false;
  bool regmarks = false;
  double regmark_inset_mm = layout::RegMarkOptions{}.inset_mm;
  double regmark_square_mm = layout::RegMarkOptions{}.square_mm;
  double regmark_arm_mm = layout::RegMarkOptions{}.arm_mm;
  double spacing_mm = layout::PackOptions{}.spacing_mm;
  bool spacing_asked = false;  ///< --spacing was given: the gap holds everywhere
  double label_min_mm = layout::LabelOptions{}.min_mm;
};

/// Adds --size, --fit, --paper, --landscape, --margin, --tab-width, --no-tabs, --no-numbers, --arrows,
/// --hints, --regmarks (with --regmark-inset/-square/-arm) and --spacing to `cmd`. Every length takes
/// units (length_option.hpp) within the bounds of limits.hpp; anything else is a usage error at parse time.
void add_layout_options(CLI::App& cmd, LayoutCliOptions& options);

/// The library options for the parsed command line.
layout::LayoutOptions to_layout_options(const LayoutCliOptions& options);

/// What the choice of parts may do with these options: close the gaps between parts to
/// kCloserSpacing_mm where that saves a sheet, unless --spacing was given.
ChooseOptions choose_options_of(const LayoutCliOptions& options);

}  // namespace foldkit::cli
