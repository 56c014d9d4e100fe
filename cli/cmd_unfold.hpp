#pragma once
// `foldkit unfold`: the flat net alone, as OBJ, with a summary line or JSON.
#include <string>

#include "layout_options.hpp"
#include "unfold_options.hpp"

namespace foldkit::cli {

/// What `foldkit unfold` was asked; the parser fills it, run_unfold does the work.
struct UnfoldArgs {
  std::string mesh;
  std::string output;  ///< the net (.obj or - for stdout); empty: none written
  bool json = false;
  bool quiet = false;
  UnfoldCliOptions unfold;
  LayoutCliOptions layout;  ///< with --size the net is cut into the parts `make` would lay out
};

/// Loads, unfolds, chooses the parts, writes the net (unfold::write_net_obj) and prints the summary on
/// stdout (JSON with --json). Throws Error (usage), InputError or LayoutError.
void run_unfold(UnfoldArgs args);

}  // namespace foldkit::cli
