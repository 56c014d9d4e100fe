#pragma once
// `foldkit make`: load -> unfold -> lay out -> render, the main job.
#include <string>

#include "colour_options.hpp"
#include "layout_options.hpp"
#include "unfold_options.hpp"

namespace foldkit::cli {

/// What `foldkit make` was asked; the parser fills it, run_make does the work.
struct MakeArgs {
  std::string mesh;
  std::string output;  ///< .pdf/.svg/.png/.dxf, or - for stdout; empty: only the bundle
  std::string format;  ///< overrides the output's extension
  std::string bundle;  ///< hand-off folder; empty: none
  double dpi = 150;
  bool json = false;
  bool quiet = false;
  bool no_guide = false;
  std::string guide_up = "auto";  ///< auto, y or z: which way is up in the guide's views
  std::string mountain = "dash-dot", valley = "dashed";  ///< fold styles (names of fold_styles())
  UnfoldCliOptions unfold;
  LayoutCliOptions layout;
  ColourCliOptions colour;
};

/// Checks the request, runs the pipeline (load_unfold_layout), draws the guide, writes the sheets
/// (devices::render_sheets or write_dxf_sheets) and the bundle, and prints the summary on stdout (JSON with
/// --json). Throws Error (usage), InputError, LayoutError.
void run_make(MakeArgs args);

}  // namespace foldkit::cli
