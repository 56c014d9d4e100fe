#pragma once
// Rendering sheets to PDF, SVG and PNG. 1 mm on the sheet is 1 mm in the file.
#include <filesystem>
#include <string>
#include <vector>

#include "foldkit/sheet/sheet.hpp"

namespace foldkit::devices {

/// A colour, components in [0, 1].
struct Rgb {
  double r = 0, g = 0, b = 0;
};

/// How one role is drawn. Dash lengths alternate on/off in millimetres; empty means solid.
struct RoleStyle {
  Rgb stroke;                   ///< line colour (and text colour for texts of this role)
  double width_mm = 0.2;        ///< line width
  std::vector<double> dash_mm;  ///< on, off, on, off, … lengths; empty = solid
  bool fill_closed = false;     ///< closed paths of this role are filled with `fill`
  Rgb fill{1, 1, 1};            ///< fill colour when fill_closed
};

/// How fold lines are drawn: on coloured sheets they are best light or absent (a cutter scores them).
enum class FoldLines { Normal, Light, None };

struct RenderOptions {
  double png_dpi = 150;                    ///< resolution of PNG previews
  std::string format;                      ///< "pdf", "svg" or "png"; empty: from the path's extension
  std::string font_family = "sans-serif";  ///< fontconfig family for texts (embedded in PDF)
  /// Family of the seam labels and their hints: narrow digits (two thirds of the cap height, Debian's
  /// fonts-liberation) are what lets a two-digit number sit beside a small face at a legible height.
  std::string label_font_family = "Liberation Sans Narrow";
  RoleStyle cut{{0, 0, 0}, 0.25, {}};
  RoleStyle mountain{{0.62, 0.12, 0.08}, 0.2, {2.5, 0.8, 0.4, 0.8}};  ///< dash-dot
  RoleStyle valley{{0.08, 0.28, 0.62}, 0.2, {2.0, 1.0}};              ///< dashed
  RoleStyle tab{{0.45, 0.45, 0.45}, 0.15, {}, true, {0.91, 0.91, 0.91}};
  /// Label texts in black; label paths (the leader of a label that stands away from its edge) thin and
  /// dotted, so that no one takes one for a cut or fold line.
  RoleStyle label{{0, 0, 0}, 0.15, {0.5, 0.3}};
  RoleStyle hint{{0.1, 0.45, 0.15}, 0.2, {}};
  RoleStyle regmark{{0, 0, 0}, 0.5, {}};         ///< 0.5 mm: the stroke Silhouette's optical sensor expects
  RoleStyle piece{{0.25, 0.25, 0.25}, 0.2, {}};  ///< part letters: dark grey, readable under the lines
  RoleStyle sheet{{0, 0, 0}, 0.25, {}};          ///< sheet number, scale check, legend
  FoldLines fold_lines = FoldLines::Normal;
  /// Textures are embedded at most this fine (texels per inch of paper): a 1024 x 1024 texture on a
  /// small model need not cost tens of megabytes.
  double image_dpi = 300;

  /// The style of `role`.
  const RoleStyle& style(PathRole role) const;
};

/// Writes all sheets to `path`, the format chosen by its extension (case-insensitive): .pdf (one page
/// per sheet, page size = sheet size, fonts embedded), .svg (one file per sheet: name.svg,
/// name-2.svg, …; one group per role with the role's name as id), .png (likewise, white background,
/// options.png_dpi). Text heights are cap heights: a "Text" of height_mm h has capitals and digits
/// h millimetres tall. Every file is written to a temporary file and renamed only once all files are
/// complete, so a failure never leaves a half-written file. `path` may be "-" (standard output) or a
/// device node (see atomic_file.hpp); SVG and PNG of more than one sheet need a file name. Throws
/// OutputError naming the file. Returns the files written.
std::vector<std::filesystem::path> render_sheets(const std::vector<Sheet>& sheets,
                                                 const std::filesystem::path& path,
                                                 const RenderOptions& options = {});

/// A sheet that goes to a file of its own beside the numbered sheets (the assembly guide).
struct CompanionSheet {
  const Sheet* sheet = nullptr;
  std::filesystem::path path;
};

/// As render_sheets, and `companion` to its own file in the same format, committed with the sheets:
/// a run that stops (an error, a signal) leaves either all of these files new or none of them.
std::vector<std::filesystem::path> render_sheets(const std::vector<Sheet>& sheets,
                                                 const std::filesystem::path& path,
                                                 const RenderOptions& options,
                                                 const CompanionSheet& companion);

/// The file that sheet `index` (0-based) goes to when every sheet gets its own file:
/// `path` itself for the first, name-2.ext, name-3.ext, … after it.
std::filesystem::path sheet_file_path(const std::filesystem::path& path, std::size_t index);

/// Removes the numbered files an earlier run with more sheets left beside `path`: sheet_file_path(path,
/// k) for k = `sheet_count`, `sheet_count`+1, … while such a file exists (so an unrelated name further
/// on is never touched). Returns the files removed; throws OutputError naming one that cannot be.
std::vector<std::filesystem::path> remove_stale_sheet_files(const std::filesystem::path& path,
                                                            std::size_t sheet_count);

}  // namespace foldkit::devices
