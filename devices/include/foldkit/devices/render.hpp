#pragma once
// Rendering sheets to PDF, SVG and PNG through Cairo. 1 mm on the sheet is 1 mm in the file.
#include <filesystem>
#include <vector>

#include "foldkit/sheet/sheet.hpp"

namespace foldkit::devices {

struct RenderOptions {
  double png_dpi = 150;  ///< resolution of PNG previews
};

/// Writes all sheets to `path`, the format chosen by its extension: .pdf (one page per sheet),
/// .svg (one file per sheet: name.svg, name-2.svg, …), .png (likewise). Written to a temporary file
/// and renamed, so a failure never leaves a half-written file. Throws OutputError.
/// Returns the files written.
std::vector<std::filesystem::path> render_sheets(const std::vector<Sheet>& sheets,
                                                 const std::filesystem::path& path,
                                                 const RenderOptions& options = {});

}  // namespace foldkit::devices
