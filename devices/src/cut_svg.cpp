#include "foldkit/devices/cut_svg.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "foldkit/error.hpp"

namespace foldkit::devices {
namespace {

// Fixed 4 decimals (0.1 µm) in the C locale: no exponents, which some cutting programs' SVG readers
// do not take.
std::string num(double v) {
  if (std::abs(v) < 5e-5) v = 0;
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, "%.4f", v);
  return buffer;
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

// Strokes wide enough to see on screen, thin enough not to hide detail; a cutter follows the path.
double stroke_width_mm(const std::string& layer) {
  return layer == "CUT" ? 0.25 : 0.2;
}

}  // namespace

std::string cut_svg_colour(const std::string& layer) {
  switch (dxf_layer_colour(layer)) {
    case 1:
      return "#ff0000";
    case 3:
      return "#00a000";  // AutoCAD's 3 is #00ff00, unreadable on white; a darker green of the same hue
    case 5:
      return "#0000ff";
    case 6:
      return "#ff00ff";
    case 8:
      return "#808080";
    default:
      return "#000000";
  }
}

std::string cut_svg_document(const Sheet& sheet, const DxfOptions& options, const std::string& name) {
  const Vec2 size = sheet.size_mm;
  if (!(std::isfinite(size.x) && std::isfinite(size.y) && size.x > 0 && size.y > 0))
    throw OutputError(name, "the sheet has no valid size");
  const std::vector<CutLine> lines = cut_lines(sheet, options, name);
  std::ostringstream out;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" "
         "xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\" version=\"1.1\" width=\""
      << num(size.x) << "mm\" height=\"" << num(size.y) << "mm\" viewBox=\"0 0 " << num(size.x) << " "
      << num(size.y) << "\">\n";
  for (const std::string& layer : dxf_layers(sheet)) {
    out << "  <g id=\"" << lower(layer) << "\" inkscape:groupmode=\"layer\" inkscape:label=\"" << layer
        << "\" fill=\"none\" stroke=\"" << cut_svg_colour(layer) << "\" stroke-width=\""
        << stroke_width_mm(layer) << "\" stroke-linejoin=\"round\" stroke-linecap=\"round\">\n";
    for (const CutLine& line : lines) {
      if (line.layer != layer) continue;
      out << "    <path d=\"";
      for (std::size_t i = 0; i < line.points_mm.size(); ++i)
        out << (i == 0 ? "M" : " L") << num(line.points_mm[i].x) << " " << num(line.points_mm[i].y);
      out << (line.closed ? " Z" : "") << "\"/>\n";
    }
    out << "  </g>\n";
  }
  out << "</svg>\n";
  return out.str();
}

}  // namespace foldkit::devices
