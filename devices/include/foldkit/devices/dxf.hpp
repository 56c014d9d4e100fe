#pragma once
// DXF for the cutting programs that do not open SVG (Silhouette Studio's Basic edition above all): one
// file per sheet, AutoCAD R12 ASCII (the version every cutter program and CAD reader takes), millimetres
// ($INSUNITS 4, $MEASUREMENT 1), one layer per role named in capitals (CUT, MOUNTAIN, VALLEY, TAB,
// LABEL, REGMARK), every path a POLYLINE and every text the single strokes a pen would draw, so a
// program without fonts still shows the labels where the print has them.
//
// Origin: DXF is y-up, the sheet is y-down. The DXF origin (0, 0) is the paper's top-left corner, x runs
// right and y up, so the page lies in 0 <= x <= width, -height <= y <= 0 (a sheet point (x, y) is the DXF
// point (x, -y)). $EXTMIN/$EXTMAX and $LIMMIN/$LIMMAX span the whole page, so a reader that aligns a
// drawing by its extents places the cut lines where the PDF/PNG print has them.
#include <filesystem>
#include <string>
#include <vector>

#include "foldkit/devices/stroke_font.hpp"
#include "foldkit/sheet/sheet.hpp"

namespace foldkit::devices {

struct DxfOptions {
  /// Font that turns texts into strokes; required when a sheet has texts that go into the file.
  const StrokeFont* font = nullptr;
};

/// The DXF layer of a role: its name in capitals ("CUT", "MOUNTAIN", …); part letters and sheet
/// furniture go to LABEL. Empty for roles that only a print shows (hints: glue-order arrows), which the
/// DXF leaves out.
std::string dxf_layer(PathRole role);

/// The DXF point of a sheet point (sheet mm, y down): (x, -y), see the header comment.
Vec2 dxf_point(Vec2 sheet_mm);

/// One line as the cutting programs get it: its layer (dxf_layer) and its points in sheet mm (y down).
struct CutLine {
  std::string layer;
  std::vector<Vec2> points_mm;
  bool closed = false;
};

/// The lines of `sheet` that its DXF holds, in file order: every path on its role's layer (hints left
/// out), every text as the pen's strokes. The cut-line SVG (cut_svg.hpp) draws the same list. Throws
/// OutputError (naming `name`) for a non-finite point, or texts without options.font.
std::vector<CutLine> cut_lines(const Sheet& sheet, const DxfOptions& options,
                               const std::string& name = "sheet");

/// The layers a file of `sheet` declares, in order: the six named layers always, then any other role's.
std::vector<std::string> dxf_layers(const Sheet& sheet);

/// The AutoCAD colour index of a layer (7 black/white for CUT and unknown layers).
int dxf_layer_colour(const std::string& layer);

/// The text of one sheet's DXF file. Throws OutputError (naming `name`) for a sheet without a valid
/// size, a non-finite point, or texts without options.font.
std::string dxf_document(const Sheet& sheet, const DxfOptions& options, const std::string& name = "sheet");

/// Writes one DXF per sheet: `path` for the first, name-2.dxf, … (render.hpp's sheet_file_path) for the
/// rest. All files are complete before the first replaces anything, so a failure leaves no new file and
/// every old one intact. Throws OutputError naming the file. Returns the files written.
std::vector<std::filesystem::path> write_dxf_sheets(const std::vector<Sheet>& sheets,
                                                    const std::filesystem::path& path,
                                                    const DxfOptions& options = {});

}  // namespace foldkit::devices
