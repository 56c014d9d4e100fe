#pragma once
// The cut lines of one sheet as SVG, for the cutting programs that open SVG (Cricut Design Space,
// Brother CanvasWorkspace, Silhouette Studio from Designer edition up): exactly the lines of the sheet's
// DXF (dxf.hpp's cut_lines), on the same page (width and height in mm, viewBox in mm, origin at the
// paper's top-left), one group per DXF layer (id in lower case: cut, mountain, valley, tab, label,
// regmark; Inkscape layer named like the DXF layer), solid strokes in the DXF layer's colour, labels as
// the pen's strokes. No fills, images or text elements: a cutting program turns every shape it is given
// into a cut, and drops or substitutes text.
#include <string>

#include "foldkit/devices/dxf.hpp"
#include "foldkit/sheet/sheet.hpp"

namespace foldkit::devices {

/// The SVG text of one sheet's cut lines. Throws OutputError (naming `name`) as dxf_document does.
std::string cut_svg_document(const Sheet& sheet, const DxfOptions& options,
                             const std::string& name = "sheet");

/// The SVG colour ("#rrggbb") of a DXF layer: its AutoCAD colour, black for CUT.
std::string cut_svg_colour(const std::string& layer);

}  // namespace foldkit::devices
