#pragma once
// The bounds of what one command may ask for, checked before any work: the ranges of the length
// options, the largest sheet, the largest PNG raster and the most sheets a layout may need. Each is a
// usage or layout error in one line, never gigabytes of memory or minutes of work first.
#include <string>

#include "foldkit/layout/layout.hpp"
#include "foldkit/unfold/mesh.hpp"
#include "length_option.hpp"

namespace foldkit::cli {

/// Each side of a sheet: from a business card to a 3 m roll (the longest a roll-fed desktop cutter takes).
inline constexpr LengthRange kSheetSide{10, 3000};
/// The model's largest dimension (--size): up to life-size furniture; the sheet budget bounds it further.
inline constexpr LengthRange kModelSize{1, 10'000};
inline constexpr LengthRange kMargin{0, 200};
inline constexpr LengthRange kTabWidth{0.5, 50};
inline constexpr LengthRange kSpacing{0, 50};
inline constexpr LengthRange kRegMarkInset{0, 100};
inline constexpr LengthRange kRegMarkSquare{1, 50};
inline constexpr LengthRange kRegMarkArm{1, 100};
inline constexpr LengthRange kOvercut{0, 10};
/// Edge numbers: smaller is unreadable, larger than the layout's largest label (3.5 mm).
inline constexpr LengthRange kLabelMin{0.5, 3.5};

/// A PNG sheet holds at most this many pixels (4 bytes each while it is drawn).
inline constexpr double kMaxPngPixels = 150e6;
/// A layout needs at most this many sheets (the packer keeps a raster of each).
inline constexpr int kMaxSheets = 500;

/// Throws Error (usage) when a `paper_mm` sheet at `dpi` is over kMaxPngPixels, naming the largest dpi.
void check_png_raster(Vec2 paper_mm, double dpi);

/// Throws LayoutError when the mesh's surface at options.size_mm needs more than kMaxSheets sheets of
/// the printable area even if packed without a gap, naming the largest --size within the budget.
void check_sheet_budget(const unfold::Mesh& mesh, const layout::LayoutOptions& options);

}  // namespace foldkit::cli
