#pragma once
// The print-and-cut calibration page: registration marks, printed crosshairs with millimetre ticks at
// known places, and short cuts through the crosses' centre lines. Printed, then cut relative to the marks,
// every cut cross lies on its printed cross when printer and cutter agree; the distance between them,
// read off the ticks, is the offset `foldkit calibrate --offset` stores.
#include <vector>

#include "foldkit/layout/regmarks.hpp"
#include "foldkit/sheet/sheet.hpp"

namespace foldkit::layout {

struct CalibrationOptions {
  Vec2 paper_mm{210, 297};
  RegMarkOptions regmark;
  double cross_arm_mm = 12;   ///< half length of each printed crosshair line
  double cut_arm_mm = 6;      ///< half length of each cut line: shorter, so the printed ends stay visible
  double tick_step_mm = 0.5;  ///< spacing of the measuring ticks along the printed arms
  double inset_mm = 25;       ///< distance of the outer crosses from the marks' cut area edges
};

/// The page and where its crosses are.
struct CalibrationPage {
  Sheet sheet;                   ///< marks (RegMark), crosses and ticks (Hint: printed only), cuts (Cut)
  std::vector<Vec2> crosses_mm;  ///< cross centres, sheet mm, top-left first, row by row
};

/// Builds the page: crosses at the four corners and the centre of the marks' cut area, moved `inset_mm`
/// inwards. Throws LayoutError when the paper is too small for the marks and the crosses.
CalibrationPage calibration_page(const CalibrationOptions& options = {});

}  // namespace foldkit::layout
