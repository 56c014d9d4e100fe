#pragma once
// Sheet furniture: what a sheet says about itself. Its number and the total ("2/5"), the model's name,
// and a scale check (a 50 mm bar labelled "50 mm" and a 1 in square) so a builder sees at once that
// the printer did not scale the page; on the first sheet (or the first with a free corner), room for
// the renderer's legend of line styles. All of it goes in one block in a free corner of the printable area,
// clear of every part, tab, text block and registration-mark zone, in the Sheet role (cutters leave it
// alone).
#include <span>
#include <string>
#include <vector>

#include "foldkit/sheet/sheet.hpp"

namespace foldkit::layout {

struct FurnitureOptions {
  std::string model_name;  ///< printed after the sheet number; empty for none
  double spacing_mm = 2;   ///< least gap between the block and anything else
  double text_mm = 3;      ///< cap height of the sheet number and name
};

/// Size of the furniture block (mm).
Vec2 furniture_size_mm();

/// Adds the furniture to every sheet (k/n counts `sheets`). `keep_out_mm` (sheet frame) are zones
/// nothing may enter (registration marks). Returns the 0-based indices of the sheets that had no free
/// corner: those get their number, name and the 50 mm bar in the bottom margin when it is deep
/// enough, and no square.
std::vector<int> add_sheet_furniture(std::span<Sheet> sheets, std::span<const Box2> keep_out_mm,
                                     const FurnitureOptions& options);

}  // namespace foldkit::layout
