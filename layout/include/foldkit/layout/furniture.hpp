#pragma once
// Sheet furniture: what a sheet says about itself. Its number and the total ("2/5"), the model's name,
// and a scale check (a 50 mm bar labelled "50 mm" and a 1 in square) so a builder sees at once that
// the printer did not scale the page; on the first sheet (or the first with room), the renderer's legend
// of line styles. All of it goes in one block in a free corner of the printable area when there is one;
// on a fuller sheet the number, name and bar go in the bottom margin and the square and the legend take
// smaller free spots along the edges (the first sheet's legend, failing that, one row in its top
// margin). Always clear of every part, tab, text block and registration-mark zone, in the Sheet role
// (cutters leave it alone). Layout keeps a corner free for the square where no spot is left and that
// costs no sheet (least_furniture_block_mm).
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

/// The least block (mm) that holds the 1 in square on a sheet too full for the whole block: the square
/// alone when the bottom margin (`bottom_margin_mm`) holds the number, name and bar, else those above it.
/// A packing that keeps a corner this large free gives every sheet its scale check.
Vec2 least_furniture_block_mm(double bottom_margin_mm, const FurnitureOptions& options);

/// Adds the furniture to every sheet (k/n counts `sheets`). `keep_out_mm` (sheet frame) are zones
/// nothing may enter (registration marks). A sheet without room for the whole block gets its number,
/// name and the 50 mm bar in the bottom margin when it is deep enough, and the square and the legend each
/// in a smaller free spot of its own. Returns the 0-based indices of the sheets that got no square.
std::vector<int> add_sheet_furniture(std::span<Sheet> sheets, std::span<const Box2> keep_out_mm,
                                     const FurnitureOptions& options);

}  // namespace foldkit::layout
