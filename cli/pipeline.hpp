#pragma once
// load -> unfold -> lay out: the part `foldkit make` and `foldkit cut` share.
#include <optional>
#include <string>

#include "foldkit/layout/fills.hpp"
#include "foldkit/layout/layout.hpp"
#include "progress.hpp"
#include "unfold_options.hpp"

namespace foldkit::cli {

struct PipelineRun {
  UnfoldRun unfolded;
  layout::LayoutResult layout;
  double layout_seconds = 0;
};

/// Loads `mesh_file`, unfolds it and lays out the sheets, showing progress on `line`. Pieces too large
/// for the paper at the asked --size are first cut into parts that fit (layout::split_and_layout; noted).
/// With `fills` and a mesh in colour, pieces are spaced for the bleed and the sheets get their fills (make
/// and cut pass the same, so that they lay out the same outlines).
/// Throws InputError (mesh), LayoutError (does not fit) or Error.
PipelineRun load_unfold_layout(const std::string& mesh_file, const UnfoldCliOptions& unfold_options,
                               const layout::LayoutOptions& layout_options, ProgressLine& line,
                               const std::optional<layout::FillOptions>& fills = std::nullopt);

}  // namespace foldkit::cli
