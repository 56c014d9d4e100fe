#pragma once
// The hand-off bundle: everything a maker needs to print and cut the sheets in the cutter's own program
// (Silhouette Studio, Cricut Design Space, Brother CanvasWorkspace) in one folder. Per sheet the print
// (PNG at 300 dpi and PDF) and the cut lines (DXF and SVG), all on the same page with the origin at the
// paper's top-left corner, so that a print and its cut lines line up when both are placed at the page
// origin; per part a PNG with a transparent background for Cricut's Print Then Cut; and a README.txt
// saying which file goes where, with the programs' size limits and where each figure comes from.
#include <filesystem>
#include <string>
#include <vector>

#include "foldkit/devices/render.hpp"
#include "foldkit/devices/stroke_font.hpp"
#include "foldkit/sheet/sheet.hpp"

namespace foldkit::devices {

struct BundleOptions {
  std::string name = "model";        ///< file stem: NAME-sheet-1.pdf, …
  RenderOptions render;              ///< styles; the PNGs are written at png_dpi (300 unless changed)
  const StrokeFont* font = nullptr;  ///< labels as strokes in the DXF (required when sheets have texts)
  const Sheet* guide = nullptr;      ///< assembly guide, written as NAME-guide.pdf when given
  BundleOptions() { render.png_dpi = 300; }
};

/// One file of a bundle, as the README lists it.
struct BundleFile {
  std::filesystem::path path;                 ///< inside the bundle directory
  std::string what;                           ///< one line for the README
  bool too_large_for_print_then_cut = false;  ///< a part PNG beyond Print Then Cut's 9.25 x 6.75 in
};

/// The files of a bundle, in README order, without writing anything.
std::vector<BundleFile> bundle_files(const std::vector<Sheet>& sheets, const BundleOptions& options);

/// The README.txt of a bundle holding `files` (bundle_files' list), with `notes` from the caller (model
/// name, scale, paper) at the top.
std::string bundle_readme(const std::vector<BundleFile>& files, const std::vector<Sheet>& sheets,
                          const BundleOptions& options, const std::vector<std::string>& notes = {});

/// Throws OutputError (naming `name`) when a sheet of `size_mm` is too large for a bundle's print at
/// `dpi`: more than 150 megapixels (A0 at 300 dpi is 139), as the print is held twice while its parts are
/// cut out of it. write_bundle checks every sheet; a caller may check the paper before the work.
void check_bundle_sheet_size(Vec2 size_mm, double dpi, const std::string& name);

/// Writes the bundle into `dir` (created when missing, and removed again when a failure leaves it
/// empty; its parent must exist). Every file is complete
/// before the first replaces anything; files an earlier bundle listed in its README.txt that this one no
/// longer has (a sheet fewer) are removed, nothing else in the folder is touched. Throws OutputError
/// naming the file. Returns the files written, README.txt last.
std::vector<std::filesystem::path> write_bundle(const std::vector<Sheet>& sheets,
                                                const std::filesystem::path& dir,
                                                const BundleOptions& options,
                                                const std::vector<std::string>& notes = {});

}  // namespace foldkit::devices
