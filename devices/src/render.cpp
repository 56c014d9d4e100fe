#include "foldkit/devices/render.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>
#include <string>

#include "foldkit/devices/atomic_file.hpp"
#include "foldkit/error.hpp"
#include "render_internal.hpp"

namespace foldkit::devices {
namespace {

std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

void check_sheets(const std::vector<Sheet>& sheets, const std::filesystem::path& path) {
  if (sheets.empty()) throw OutputError(path.string(), "nothing to render: no sheets");
  for (std::size_t i = 0; i < sheets.size(); ++i) {
    const Vec2 size = sheets[i].size_mm;
    if (!(std::isfinite(size.x) && std::isfinite(size.y) && size.x > 0 && size.y > 0)) {
      throw OutputError(path.string(), "sheet " + std::to_string(i + 1) + " has no valid size");
    }
  }
}

}  // namespace

const RoleStyle& RenderOptions::style(PathRole role) const {
  switch (role) {
    case PathRole::Cut:
      return cut;
    case PathRole::Mountain:
      return mountain;
    case PathRole::Valley:
      return valley;
    case PathRole::Tab:
      return tab;
    case PathRole::Label:
      return label;
    case PathRole::Hint:
      return hint;
    case PathRole::RegMark:
      return regmark;
    case PathRole::Piece:
      return piece;
    case PathRole::Sheet:
      return sheet;
  }
  return cut;
}

namespace detail {

std::optional<RoleStyle> sheet_style(const RenderOptions& options, const Sheet& sheet, PathRole role) {
  RoleStyle style = options.style(role);
  const bool fold = role == PathRole::Mountain || role == PathRole::Valley;
  if (fold && options.fold_lines == FoldLines::None) return std::nullopt;
  if (fold && options.fold_lines == FoldLines::Light) {
    // Two thirds of the way to white and thinner: visible to fold by, quiet on the print.
    constexpr double kToWhite = 0.65, kThinner = 0.6;
    auto light = [](double c) { return c + (1 - c) * kToWhite; };
    style.stroke = {light(style.stroke.r), light(style.stroke.g), light(style.stroke.b)};
    style.width_mm *= kThinner;
  }
  if (role == PathRole::Tab && !sheet.fills.empty()) style.fill_closed = false;
  return style;
}

}  // namespace detail

std::filesystem::path sheet_file_path(const std::filesystem::path& path, std::size_t index) {
  if (index == 0) return path;
  std::filesystem::path numbered = path;
  numbered.replace_filename(path.stem().string() + "-" + std::to_string(index + 1) +
                            path.extension().string());
  return numbered;
}

std::vector<std::filesystem::path> remove_stale_sheet_files(const std::filesystem::path& path,
                                                            std::size_t sheet_count) {
  std::vector<std::filesystem::path> removed;
  if (path == "-" || sheet_count == 0) return removed;
  for (std::size_t k = sheet_count;; ++k) {
    const std::filesystem::path stale = sheet_file_path(path, k);
    std::error_code ec;
    const auto status = std::filesystem::symlink_status(stale, ec);
    if (ec || !(std::filesystem::is_regular_file(status) || std::filesystem::is_symlink(status))) break;
    if (!std::filesystem::remove(stale, ec) || ec)
      throw OutputError(stale.string(), "cannot remove this sheet of an earlier run: " + ec.message());
    removed.push_back(stale);
  }
  return removed;
}

namespace {

std::string output_type(const std::filesystem::path& path, const RenderOptions& options) {
  const std::string ext = options.format.empty() ? lower_extension(path) : "." + options.format;
  if (ext != ".pdf" && ext != ".svg" && ext != ".png") {
    throw OutputError(path.string(),
                      "unknown output type '" + path.extension().string() + "' (use .pdf, .svg or .png)");
  }
  if (ext == ".png" && !(std::isfinite(options.png_dpi) && options.png_dpi > 0)) {
    throw OutputError(path.string(), "PNG resolution must be a positive number of dots per inch");
  }
  return ext;
}

void write_pdf_file(AtomicFile& file, const std::vector<Sheet>& pages, const RenderOptions& options) {
  std::string error;
  // Drawn into memory first: the scaling preference is appended once Cairo has finished the file.
  std::ostringstream bytes;
  if (!detail::write_pdf(bytes, pages, options, file.target().stem().string(), error)) {
    throw OutputError(file.target().string(), error);
  }
  std::string pdf = std::move(bytes).str();
  detail::ask_viewers_not_to_scale(pdf);
  file.stream().write(pdf.data(), static_cast<std::streamsize>(pdf.size()));
}

// One sheet as one SVG or PNG file.
void write_picture_file(AtomicFile& file, const Sheet& sheet, const std::string& ext,
                        const RenderOptions& options, const detail::CapRatios& caps) {
  if (ext == ".svg") {
    detail::write_svg(file.stream(), sheet, options, caps);
    return;
  }
  std::string error;
  if (!detail::write_png(file.stream(), sheet, options, error))
    throw OutputError(file.target().string(), error);
}

}  // namespace

std::vector<std::filesystem::path> render_sheets(const std::vector<Sheet>& sheets,
                                                 const std::filesystem::path& path,
                                                 const RenderOptions& options) {
  return render_sheets(sheets, path, options, CompanionSheet{});
}

std::vector<std::filesystem::path> render_sheets(const std::vector<Sheet>& sheets,
                                                 const std::filesystem::path& path,
                                                 const RenderOptions& options,
                                                 const CompanionSheet& companion) {
  const std::string ext = output_type(path, options);
  check_sheets(sheets, path);
  if (companion.sheet) check_sheets({*companion.sheet}, companion.path);
  const bool one_file = ext == ".pdf";
  if (!one_file && sheets.size() > 1 && resolve_output(path).kind != OutputKind::File) {
    throw OutputError(path.string(), "SVG and PNG are one file per sheet and the layout has " +
                                         std::to_string(sheets.size()) +
                                         " sheets: give a file name, or write PDF");
  }
  // Every file is complete before the first rename, and a rename that fails puts the earlier ones
  // back, so a run never leaves sheets 1 and 2 of a new layout beside sheet 3 of an old one, or new
  // sheets beside an old guide.
  AtomicFileSet files;
  const detail::CapRatios caps = ext == ".svg" ? detail::cap_height_ratios(options) : detail::CapRatios{};
  if (one_file) {
    write_pdf_file(files.add(path), sheets, options);
  } else {
    for (std::size_t i = 0; i < sheets.size(); ++i)
      write_picture_file(files.add(sheet_file_path(path, i)), sheets[i], ext, options, caps);
  }
  if (companion.sheet) {
    AtomicFile& file = files.add(companion.path);
    if (one_file)
      write_pdf_file(file, {*companion.sheet}, options);
    else
      write_picture_file(file, *companion.sheet, ext, options, caps);
  }
  files.commit();
  return files.targets();
}

}  // namespace foldkit::devices
