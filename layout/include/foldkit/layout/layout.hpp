#pragma once
// The layout stage: Unfolding -> sheets. Owned by layout/; extended by the layout issue.
#include <optional>
#include <string>
#include <vector>

#include "foldkit/sheet/sheet.hpp"
#include "foldkit/unfold/unfolding.hpp"

namespace foldkit::layout {

struct LayoutOptions {
  /// Largest model dimension on paper, mm. Ignored when fit is set.
  std::optional<double> size_mm;
  /// Largest scale at which the whole model fits on one sheet.
  bool fit = false;
  Vec2 paper_mm{210, 297};  ///< A4 portrait by default
  double margin_mm = 10;
  /// Folds whose |angle| is below this (radians) are not drawn.
  double flat_fold_rad = 0.5 * 3.14159265358979323846 / 180.0;
};

struct LayoutResult {
  std::vector<Sheet> sheets;
  double scale_mm_per_unit = 1;  ///< model units -> mm
};

/// Scales, places and draws every piece. Throws LayoutError when a piece cannot fit a sheet.
LayoutResult layout_sheets(const unfold::Unfolding& unfolding, const LayoutOptions& options);

}  // namespace foldkit::layout
