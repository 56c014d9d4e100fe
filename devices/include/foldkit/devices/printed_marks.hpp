#pragma once
// What a sheet's printed registration marks measure: the Silhouette layout of a filled square at the
// top-left and L brackets at the top-right and bottom-left, read back from the sheet's RegMark paths so
// that the search command a cutter gets describes the marks that were actually printed.
#include <optional>

#include "foldkit/geom/vec.hpp"
#include "foldkit/sheet/sheet.hpp"

namespace foldkit::devices {

/// The printed marks, in sheet millimetres.
struct PrintedMarks {
  Vec2 origin_mm;  ///< outer top-left corner of the square: where the device's (0,0) goes after the search
  Vec2 extent_mm;  ///< from the origin to the outer edges of the far brackets (x right, y down)
  double square_mm{};  ///< side of the filled square
  double arm_mm{};     ///< outer length of each bracket arm
  double stroke_mm{};  ///< line width of the brackets
};

/// Reads the marks from `sheet` (bracket strokes centred half a stroke inside their outer edge, as the
/// layout draws them). nullopt when the sheet has no RegMark path; throws DeviceError when its marks are
/// not one filled square and two L brackets.
std::optional<PrintedMarks> printed_marks(const Sheet& sheet);

}  // namespace foldkit::devices
