#include "foldkit/devices/bundle.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <sstream>

#include "cairo_image.hpp"
#include "foldkit/devices/atomic_file.hpp"
#include "foldkit/devices/cut_svg.hpp"
#include "foldkit/devices/dxf.hpp"
#include "foldkit/error.hpp"
#include "render_internal.hpp"

namespace foldkit::devices {
namespace {

constexpr double kMmPerInch = 25.4;
constexpr double kPartPadMm = 1.0;  // transparent border around a part so its outline is not clipped
constexpr const char* kReadmeName = "README.txt";
// The sheet's print is held twice while its parts are cut out (rendered and decoded): 150 megapixels
// (A0 at 300 dpi is 139) keeps that near 1.2 GB; larger paper is refused before anything is drawn.
constexpr double kMaxSheetPixels = 150e6;
constexpr const char* kFilesHeading = "FILES";
// Print Then Cut's area, 9.25 x 6.75 in (source [6] in the README).
constexpr double kPrintThenCutLongMm = 9.25 * 25.4, kPrintThenCutShortMm = 6.75 * 25.4;

using detail::ContextPtr;
using detail::SurfacePtr;

std::string fixed(double v, int digits) {
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(digits);
  s << v;
  return s.str();
}

std::string sheet_stem(const BundleOptions& o, std::size_t i) {
  return o.name + "-sheet-" + std::to_string(i + 1);
}

// A part of a sheet: the closed cut outlines of one piece (its outline with tabs, and its holes).
struct Part {
  int piece = -1;
  std::string name;  // the part letter printed on it (layout's Piece text), else its number from 1
  std::vector<const Path*> outlines;
  Box2 box_mm;
};

std::vector<Part> sheet_parts(const Sheet& sheet) {
  std::map<int, Part> by_piece;
  for (const Path& p : sheet.paths) {
    if (p.role != PathRole::Cut || !p.closed || p.piece < 0 || p.points_mm.size() < 3) continue;
    Part& part = by_piece[p.piece];
    part.piece = p.piece;
    part.outlines.push_back(&p);
    for (Vec2 q : p.points_mm)
      part.box_mm.add(q);
  }
  std::vector<Part> parts;
  for (auto& [piece, part] : by_piece) {
    part.name = std::to_string(piece + 1);
    for (const Text& t : sheet.texts) {
      // Only a name every file system and cutting program takes; letters are A..Z, AA.. in practice.
      const bool plain =
          !t.text.empty() && t.text.size() <= 8 &&
          std::all_of(t.text.begin(), t.text.end(), [](unsigned char c) { return std::isalnum(c) != 0; });
      if (t.role == PathRole::Piece && t.piece == piece && plain) {
        part.name = t.text;
        break;
      }
    }
    // Two parts printed with the same letter would write one file twice: numbers keep them apart.
    const std::string& name = part.name;  // clang cannot capture a structured binding in C++20
    if (std::any_of(parts.begin(), parts.end(), [&name](const Part& p) { return p.name == name; }))
      part.name = std::to_string(piece + 1);
    parts.push_back(std::move(part));
  }
  return parts;
}

// Whether the part fits Print Then Cut's area in either orientation.
bool fits_print_then_cut(const Part& part) {
  const double w = part.box_mm.width(), h = part.box_mm.height();
  return std::max(w, h) <= kPrintThenCutLongMm && std::min(w, h) <= kPrintThenCutShortMm;
}

std::string guide_file(const BundleOptions& o) {
  return o.name + "-guide.pdf";
}

std::string part_file(const BundleOptions& o, std::size_t sheet, const Part& part) {
  return sheet_stem(o, sheet) + "-part-" + part.name + ".png";
}

std::array<int, 2> part_size_px(const Part& part, double dpi) {
  const double px_per_mm = dpi / kMmPerInch;
  return {static_cast<int>(std::ceil((part.box_mm.width() + 2 * kPartPadMm) * px_per_mm)),
          static_cast<int>(std::ceil((part.box_mm.height() + 2 * kPartPadMm) * px_per_mm))};
}

// The part cut out of the sheet's own print (so colours, textures and labels are exactly those of the
// sheet PNG), transparent outside its outline and in its holes: Print Then Cut cuts around what is not
// transparent.
std::string part_png(const SurfacePtr& sheet_image, const Part& part, double dpi, const std::string& file) {
  const double px_per_mm = dpi / kMmPerInch;
  const auto [w, h] = part_size_px(part, dpi);
  SurfacePtr surface(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, w, h));
  ContextPtr cr(cairo_create(surface.get()));
  const Vec2 origin = part.box_mm.min - Vec2{kPartPadMm, kPartPadMm};
  cairo_scale(cr.get(), px_per_mm, px_per_mm);
  cairo_translate(cr.get(), -origin.x, -origin.y);
  cairo_new_path(cr.get());
  for (const Path* p : part.outlines) {
    cairo_move_to(cr.get(), p->points_mm.front().x, p->points_mm.front().y);
    for (Vec2 q : p->points_mm)
      cairo_line_to(cr.get(), q.x, q.y);
    cairo_close_path(cr.get());
  }
  cairo_set_fill_rule(cr.get(), CAIRO_FILL_RULE_EVEN_ODD);
  cairo_clip(cr.get());
  cairo_scale(cr.get(), 1 / px_per_mm, 1 / px_per_mm);
  cairo_set_source_surface(cr.get(), sheet_image.get(), 0, 0);
  cairo_paint(cr.get());
  std::ostringstream out;
  if (cairo_status(cr.get()) != CAIRO_STATUS_SUCCESS || !detail::encode_png(surface.get(), out))
    throw OutputError(file, "cannot render the part");
  return detail::with_resolution(out.str(), dpi);
}

// File names the README of an earlier bundle in `dir` lists (empty when there is none).
std::set<std::filesystem::path> listed_in_readme(const std::filesystem::path& readme,
                                                 const BundleOptions& o) {
  std::set<std::filesystem::path> names;
  std::ifstream in(readme);
  std::string line;
  bool in_files = false;
  while (std::getline(in, line)) {
    if (line == kFilesHeading) {
      in_files = true;
      continue;
    }
    if (!in_files) continue;
    if (line.empty()) break;
    const std::string name = line.substr(0, line.find(' '));
    // Only files this bundle would write (its own name, a sheet suffix, one of its types, or its
    // guide): a README edited by hand must never make us delete a user's file or anything outside
    // the folder.
    const std::string ext = std::filesystem::path(name).extension().string();
    const bool sheet_file = name.rfind(o.name + "-sheet-", 0) == 0 && name.find('/') == std::string::npos &&
                            (ext == ".pdf" || ext == ".png" || ext == ".dxf" || ext == ".svg");
    if (sheet_file || name == guide_file(o)) names.insert(name);
  }
  return names;
}

std::string size_text(Vec2 mm) {
  return fixed(mm.x, 1) + " x " + fixed(mm.y, 1) + " mm";
}

// Where each figure in the README comes from. Figures without a source are said to be unknown, not
// guessed.
const char* kProgramNotes = R"(HOW TO LOAD THEM
Silhouette Studio (Basic edition opens DXF and PDF; SVG needs Designer edition or above [1]):
  File > Open NAME-sheet-N.dxf (Preferences > Import: open DXF "As-Is" [3]) on a page of the
  paper size above. The DXF origin is the paper's top-left corner (DXF y = minus the distance from
  the top edge), so the lines land where NAME-sheet-N.pdf prints them. Each role is its own layer
  and colour: CUT black/white, MOUNTAIN red, VALLEY blue, TAB grey, LABEL green, REGMARK magenta.
  In the Send panel cut CUT, give MOUNTAIN and VALLEY a light score setting (or none), and do not
  cut LABEL, TAB or REGMARK. Print and cut with Studio's own registration marks: with the DXF open,
  import NAME-sheet-N.png, give it the page's size (listed above; the file says 300 dpi) and move
  it to the page's top-left corner, under the lines; switch on registration marks (at least 10 mm
  in from the edge [2]: no part may lie in their area), print from Studio at 100 % and cut.
  Otherwise print NAME-sheet-N.pdf at 100 % (not "fit to page") and cut by hand, or with the
  sheet's own marks if it has them (see the notes at the top).
Cricut Design Space (Print Then Cut):
  Upload > the NAME-sheet-N-part-M.png files (transparent backgrounds: Design Space cuts around
  the outline of the image), keep them as "Print Then Cut" images, and set each one's width to the
  width listed above so the print keeps its scale. Cut lines alone (blank card, no print): upload
  NAME-sheet-N.svg as a cut image; its groups are the DXF's layers in the same colours: keep cut,
  set mountain and valley to Score (or hide them), hide tab, label and regmark.
Brother CanvasWorkspace:
  Import NAME-sheet-N.svg; its groups are the DXF's layers: cut the cut group,
  set mountain and valley to a half cut or to none (score by hand), and delete tab, label, regmark.

SIZE LIMITS THE PROGRAMS STATE
(only figures with a source; where we found none we say so rather than guess)
Silhouette Studio
  - Basic edition: opens DXF and PDF; SVG only from Designer edition up [1].
  - Registration marks: the inset from the paper edge cannot be set below 10 mm [2], so keep parts
    more than 10 mm plus the mark size inside the paper for Studio's own print-and-cut.
  - DXF import: set Preferences > Import to open DXF "As-Is" so Studio keeps the size and place [3].
  - Cutting mats 12 x 12 in (304.8 x 304.8 mm) and 12 x 24 in (304.8 x 609.6 mm); the sticky area
    is the 12 in square, with about 1/4 in margins at the sides and 1 in at top and bottom where
    the rollers grip [4]. Studio's own maximum page and print-and-cut area: no source found.
Cricut Design Space
  - Print Then Cut page size is chosen in Settings > Load Type; the tutorial [3] recommends
    1.25 to 2.5 cm margins around the design for the printed sensor marks.
  - Mats 12 x 12 in and 12 x 24 in (Explore), Explore Air 2 cuts up to 11.5 x 23.5 in [5].
  - Print Then Cut prints and cuts within 9.25 x 6.75 in (235 x 171 mm) [6] (a summary in an
    open-source project, not Cricut's own page): parts marked "larger than Print Then Cut" above
    do not fit; make the model smaller or cut those parts from the DXF or SVG instead.
  - Its printed sensor marks need about 14 mm of margin on every side [7] (a user's report).
  - Upload file size limit: no source found.
Brother CanvasWorkspace
  - SVG import size and file limits, mat sizes: no source found.

Sources
  [1] krafix.de, "Grundlegendes zu Plottdateien",
      https://www.krafix.de/index.php/anleitung/allgemeine-hilfe/grundlegendes-zu-plotterdateien
  [2] silhouette-card-maker, "Borderless Templates",
      https://alan-cha.github.io/silhouette-card-maker/miscellaneous/borderless/
  [3] Proxy-PDF-Maker, tutorials/AutoCutting/README.md,
      https://github.com/Malacath-92/Proxy-PDF-Maker (Silhouette Studio and Cricut Design Space steps)
  [4] smart-silhouette.com, "Cut border", https://smart-silhouette.com/cut-border/
  [5] Wikipedia, "Cricut", https://en.wikipedia.org/wiki/Cricut (model comparison)
  [6] piecepackr, issue 343 "Cricut cut line files" (comment of 2026-05-05),
      https://github.com/piecepackr/piecepackr/issues/343
  [7] MTGProxyPrinter, discussion 4, https://github.com/luziferius/MTGProxyPrinter/discussions/4
)";

// The files of the bundle, all complete before the first replaces anything, then the earlier
// bundle's files this one no longer has removed. `dir` exists.
std::vector<std::filesystem::path> write_into(const std::vector<Sheet>& sheets,
                                              const std::filesystem::path& dir, const BundleOptions& options,
                                              const std::vector<std::string>& notes) {
  std::error_code ec;
  const std::vector<BundleFile> listing = bundle_files(sheets, options);
  const std::set<std::filesystem::path> earlier = listed_in_readme(dir / kReadmeName, options);

  std::vector<AtomicFile> files;
  files.reserve(listing.size());
  auto open = [&](const std::string& name) -> std::ostream& {
    files.emplace_back(dir / name);
    return files.back().stream();
  };
  for (std::size_t i = 0; i < sheets.size(); ++i) {
    const Sheet& s = sheets[i];
    const std::string stem = sheet_stem(options, i);
    std::string error;
    if (!detail::write_pdf(open(stem + ".pdf"), {s}, options.render, stem, error))
      throw OutputError((dir / (stem + ".pdf")).string(), error);
    std::ostringstream png;
    if (!detail::write_png(png, s, options.render, error))
      throw OutputError((dir / (stem + ".png")).string(), error);
    const std::string png_bytes = png.str();
    open(stem + ".png") << detail::with_resolution(png_bytes, options.render.png_dpi);
    open(stem + ".dxf") << dxf_document(s, {options.font}, (dir / (stem + ".dxf")).string());
    open(stem + ".svg") << cut_svg_document(s, {options.font}, (dir / (stem + ".svg")).string());

    const SurfacePtr image = detail::decode_png(png_bytes);
    if (cairo_surface_status(image.get()) != CAIRO_STATUS_SUCCESS)
      throw OutputError((dir / (stem + ".png")).string(), "cannot read back the sheet's print for its parts");
    for (const Part& part : sheet_parts(s)) {
      const std::string name = part_file(options, i, part);
      open(name) << part_png(image, part, options.render.png_dpi, (dir / name).string());
    }
  }
  if (options.guide) {
    const std::string name = guide_file(options);
    std::string error;
    if (!detail::write_pdf(open(name), {*options.guide}, options.render, options.name + " guide", error))
      throw OutputError((dir / name).string(), error);
  }
  open(kReadmeName) << bundle_readme(listing, sheets, options, notes);

  std::vector<std::filesystem::path> written;
  for (AtomicFile& f : files) {
    f.commit();
    written.push_back(f.target());
  }
  // Only once the new bundle is complete: a sheet the earlier bundle had and this one has not would
  // otherwise sit beside the new files as if it belonged to them.
  for (const std::filesystem::path& old : earlier) {
    if (std::none_of(listing.begin(), listing.end(), [&](const BundleFile& f) { return f.path == old; }))
      std::filesystem::remove(dir / old, ec);
  }
  return written;
}

}  // namespace

void check_bundle_sheet_size(Vec2 size_mm, double dpi, const std::string& name) {
  // In doubles: a hostile paper size must not overflow an int before it is refused.
  const double px_per_mm = dpi / kMmPerInch;
  if (size_mm.x * px_per_mm * size_mm.y * px_per_mm <= kMaxSheetPixels) return;
  throw OutputError(name, size_text(size_mm) + " is too large for a " + fixed(dpi, 0) +
                              " dpi print in a bundle (at most A0)");
}

std::vector<BundleFile> bundle_files(const std::vector<Sheet>& sheets, const BundleOptions& options) {
  std::vector<BundleFile> files;
  const double dpi = options.render.png_dpi;
  for (std::size_t i = 0; i < sheets.size(); ++i) {
    const Sheet& s = sheets[i];
    const std::string stem = sheet_stem(options, i);
    const std::string n = "sheet " + std::to_string(i + 1) + ": ";
    const auto px = detail::png_size_px(s, dpi);
    files.push_back({stem + ".pdf", n + "print, PDF, " + size_text(s.size_mm) + " page, print at 100 %"});
    files.push_back({stem + ".png", n + "print, PNG " + std::to_string(px[0]) + " x " +
                                        std::to_string(px[1]) + " px at " + fixed(dpi, 0) + " dpi (" +
                                        size_text(s.size_mm) + ")"});
    files.push_back(
        {stem + ".dxf", n + "cut lines, DXF in mm, layers CUT MOUNTAIN VALLEY TAB LABEL REGMARK"});
    files.push_back({stem + ".svg", n + "cut lines, SVG in mm, the DXF's lines and layers (groups)"});
    for (const Part& part : sheet_parts(s)) {
      const auto ppx = part_size_px(part, dpi);
      files.push_back(
          {part_file(options, i, part),
           n + "part " + part.name + " for Print Then Cut, " +
               size_text(part.box_mm.max - part.box_mm.min + Vec2{2 * kPartPadMm, 2 * kPartPadMm}) + " (" +
               std::to_string(ppx[0]) + " x " + std::to_string(ppx[1]) + " px), top-left at (" +
               fixed(part.box_mm.min.x - kPartPadMm, 1) + ", " + fixed(part.box_mm.min.y - kPartPadMm, 1) +
               ") mm on the sheet" + (fits_print_then_cut(part) ? "" : "; larger than Print Then Cut's area"),
           !fits_print_then_cut(part)});
    }
  }
  if (options.guide)
    files.push_back({guide_file(options), "assembly guide: which part goes where and in what order, PDF"});
  files.push_back({kReadmeName, "this file"});
  return files;
}

std::string bundle_readme(const std::vector<BundleFile>& files, const std::vector<Sheet>& sheets,
                          const BundleOptions& options, const std::vector<std::string>& notes) {
  std::ostringstream out;
  out << "foldkit hand-off bundle: " << options.name << ", " << sheets.size() << " sheet"
      << (sheets.size() == 1 ? "" : "s");
  if (!sheets.empty()) out << " of " << size_text(sheets.front().size_mm);
  out << "\n";
  for (const std::string& n : notes)
    out << n << "\n";
  out << "Every file of a sheet has the same page: origin at the paper's top-left corner, millimetres.\n\n";
  std::size_t width = 0;
  for (const BundleFile& f : files)
    width = std::max(width, f.path.string().size());
  out << kFilesHeading << "\n";
  for (const BundleFile& f : files)
    out << f.path.string() << std::string(width + 2 - f.path.string().size(), ' ') << f.what << "\n";
  out << "\n";
  std::string how = kProgramNotes;
  for (std::size_t at; (at = how.find("NAME")) != std::string::npos;)
    how.replace(at, 4, options.name);
  out << how;
  return out.str();
}

std::vector<std::filesystem::path> write_bundle(const std::vector<Sheet>& sheets,
                                                const std::filesystem::path& dir,
                                                const BundleOptions& options,
                                                const std::vector<std::string>& notes) {
  if (sheets.empty()) throw OutputError(dir.string(), "nothing to write: no sheets");
  if (!(std::isfinite(options.render.png_dpi) && options.render.png_dpi > 0))
    throw OutputError(dir.string(), "PNG resolution must be a positive number of dots per inch");
  for (std::size_t i = 0; i < sheets.size(); ++i)
    check_bundle_sheet_size(sheets[i].size_mm, options.render.png_dpi,
                            dir.string() + ": sheet " + std::to_string(i + 1));
  std::error_code ec;
  bool created = false;
  if (!std::filesystem::is_directory(dir, ec)) {
    if (std::filesystem::exists(dir, ec)) throw OutputError(dir.string(), "exists and is not a folder");
    if (!std::filesystem::create_directory(dir, ec))
      throw OutputError(dir.string(), "cannot create the folder: " + ec.message());
    created = true;
  }
  try {
    return write_into(sheets, dir, options, notes);
  } catch (...) {
    // A failed first bundle leaves no folder behind (its files removed themselves): nothing new at all.
    if (created) std::filesystem::remove(dir, ec);  // only removes it when empty
    throw;
  }
}

}  // namespace foldkit::devices
