#pragma once
// Registration marks for print-and-cut in the Silhouette convention (plotter-protocols.md §2.4): a
// filled square at the top-left, L brackets at the top-right and bottom-left, all `inset_mm` from the
// paper edges. The cutter's optical sensor finds them, so nothing else may be printed near them, and
// it can only cut inside the rectangle they span.
#include <vector>

#include "foldkit/sheet/sheet.hpp"

namespace foldkit::layout {

struct RegMarkOptions {
  double square_mm = 5;     ///< side of the filled top-left square
  double arm_mm = 20;       ///< length of each arm of the L brackets (TB51,400 = 20 mm)
  double inset_mm = 10;     ///< distance of the marks' outer edges from the paper edges
  double stroke_mm = 0.5;   ///< line width of the brackets (TB53,10 = 0.5 mm)
  double clearance_mm = 3;  ///< nothing else within this distance of a mark
};

/// The three marks as sheet paths (mm from the top-left, y down), role RegMark; the square is filled.
std::vector<Path> regmark_paths(Vec2 paper_mm, const RegMarkOptions& options = {});

/// Zones around the marks where nothing else may be placed (sheet frame, y down).
std::vector<Box2> regmark_keep_out(Vec2 paper_mm, const RegMarkOptions& options = {});

/// The rectangle the marks span: the cutter's reach after it has found them (sheet frame, y down).
Box2 regmark_cut_area(Vec2 paper_mm, const RegMarkOptions& options = {});

}  // namespace foldkit::layout
