// Written by hand rather than through dxflib: dxflib writes only to a file it opens by name (so not
// through AtomicFile's stream) and R12 needs no more than the few group codes below.
#include "foldkit/devices/dxf.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <sstream>

#include "foldkit/devices/atomic_file.hpp"
#include "foldkit/devices/render.hpp"
#include "foldkit/error.hpp"

namespace foldkit::devices {
namespace {

constexpr int kInsUnitsMillimetres = 4;  // $INSUNITS: 1 inch, 4 mm
constexpr int kMeasurementMetric = 1;    // $MEASUREMENT: 0 imperial, 1 metric
constexpr int kPolylineClosed = 1;       // POLYLINE group 70 flag
constexpr int kColourDefault = 7;        // AutoCAD colour index: white on black, black on white

// The layers every file declares, in this order, so a user's per-layer settings find the same names in
// every file; other roles get their layer when they occur.
constexpr PathRole kNamedRoles[] = {PathRole::Cut, PathRole::Mountain, PathRole::Valley,
                                    PathRole::Tab, PathRole::Label,    PathRole::RegMark};

// 0.1 µm, locale-independent, trailing zeros dropped.
std::string num(double v) {
  if (std::abs(v) < 5e-5) v = 0;
  char buffer[64];
  auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v, std::chars_format::fixed, 4);
  std::string s(buffer, ec == std::errc() ? end : buffer);
  if (s.find('.') != std::string::npos) {
    while (s.back() == '0')
      s.pop_back();
    if (s.back() == '.') s.pop_back();
  }
  return s.empty() || s == "-0" ? "0" : s;
}

// Group codes are written right-aligned in three columns, as AutoCAD does; readers accept either.
class GroupWriter {
 public:
  explicit GroupWriter(std::ostream& out) : out_(out) {}
  void code(int c, const std::string& value) {
    char buffer[8];
    std::snprintf(buffer, sizeof buffer, "%3d", c);
    out_ << buffer << "\n" << value << "\n";
  }
  void code(int c, int value) { code(c, std::to_string(value)); }
  void real(int c, double value) { code(c, num(value)); }
  void point(int base, Vec2 p) {
    real(base, p.x);
    real(base + 10, p.y);
  }
  void header_point(const char* name, Vec2 p, bool with_z) {
    code(9, name);
    point(10, p);
    if (with_z) real(30, 0);
  }

 private:
  std::ostream& out_;
};

void write_header(GroupWriter& g, Vec2 size_mm) {
  g.code(0, "SECTION");
  g.code(2, "HEADER");
  g.code(9, "$ACADVER");
  g.code(1, "AC1009");
  g.code(9, "$INSUNITS");
  g.code(70, kInsUnitsMillimetres);
  g.code(9, "$MEASUREMENT");
  g.code(70, kMeasurementMetric);
  // The page, not the drawing's bounding box: readers that place a drawing by its extents then keep
  // the page origin.
  g.header_point("$EXTMIN", dxf_point({0, size_mm.y}), true);
  g.header_point("$EXTMAX", dxf_point({size_mm.x, 0}), true);
  g.header_point("$LIMMIN", dxf_point({0, size_mm.y}), false);
  g.header_point("$LIMMAX", dxf_point({size_mm.x, 0}), false);
  g.code(0, "ENDSEC");
}

void write_tables(GroupWriter& g, const std::vector<std::string>& layers) {
  g.code(0, "SECTION");
  g.code(2, "TABLES");
  g.code(0, "TABLE");
  g.code(2, "LTYPE");
  g.code(70, 1);
  g.code(0, "LTYPE");
  g.code(2, "CONTINUOUS");
  g.code(70, 0);
  g.code(3, "Solid line");
  g.code(72, 65);
  g.code(73, 0);
  g.real(40, 0);
  g.code(0, "ENDTAB");
  g.code(0, "TABLE");
  g.code(2, "LAYER");
  g.code(70, static_cast<int>(layers.size()));
  for (const std::string& layer : layers) {
    g.code(0, "LAYER");
    g.code(2, layer);
    g.code(70, 0);
    g.code(62, dxf_layer_colour(layer));
    g.code(6, "CONTINUOUS");
  }
  g.code(0, "ENDTAB");
  g.code(0, "ENDSEC");
}

void write_entities(GroupWriter& g, const std::vector<CutLine>& lines) {
  g.code(0, "SECTION");
  g.code(2, "ENTITIES");
  for (const CutLine& pl : lines) {
    g.code(0, "POLYLINE");
    g.code(8, pl.layer);
    g.code(66, 1);  // vertices follow
    g.point(10, {0, 0});
    g.real(30, 0);
    g.code(70, pl.closed ? kPolylineClosed : 0);
    for (Vec2 p : pl.points_mm) {
      g.code(0, "VERTEX");
      g.code(8, pl.layer);
      g.point(10, dxf_point(p));
      g.real(30, 0);
    }
    g.code(0, "SEQEND");
    g.code(8, pl.layer);
  }
  g.code(0, "ENDSEC");
}

}  // namespace

std::string dxf_layer(PathRole role) {
  if (role == PathRole::Hint) return "";
  // Part letters and sheet furniture are text a cutter must not cut: in a cutting program they are one
  // more thing to switch off, so they join the labels rather than add layers.
  if (role == PathRole::Piece || role == PathRole::Sheet) return "LABEL";
  std::string name = role_name(role);
  std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return std::toupper(c); });
  return name;
}

Vec2 dxf_point(Vec2 sheet_mm) {
  return {sheet_mm.x, -sheet_mm.y};
}

std::vector<CutLine> cut_lines(const Sheet& sheet, const DxfOptions& options, const std::string& name) {
  std::vector<CutLine> out;
  auto add = [&](const std::string& layer, const std::vector<Vec2>& pts, bool closed,
                 const std::string& what) {
    if (layer.empty() || pts.size() < 2) return;
    for (Vec2 p : pts)
      if (!std::isfinite(p.x) || !std::isfinite(p.y))
        throw OutputError(name, what + " has a point that is not a number");
    out.push_back({layer, pts, closed});
  };
  for (std::size_t i = 0; i < sheet.paths.size(); ++i) {
    const Path& p = sheet.paths[i];
    add(dxf_layer(p.role), p.points_mm, p.closed,
        std::string(role_name(p.role)) + " path " + std::to_string(i + 1));
  }
  for (const Text& t : sheet.texts) {
    const std::string layer = dxf_layer(t.role);
    if (layer.empty() || t.text.empty()) continue;
    if (!options.font) throw OutputError(name, "cannot write the labels: no stroke font loaded");
    for (const auto& stroke : text_strokes(*options.font, t))
      add(layer, stroke, false, "text \"" + t.text + "\"");
  }
  return out;
}

std::vector<std::string> dxf_layers(const Sheet& sheet) {
  std::vector<std::string> layers;
  auto declare = [&](PathRole role) {
    const std::string layer = dxf_layer(role);
    if (!layer.empty() && std::find(layers.begin(), layers.end(), layer) == layers.end())
      layers.push_back(layer);
  };
  for (PathRole role : kNamedRoles)
    declare(role);
  for (const Path& p : sheet.paths)
    declare(p.role);
  for (const Text& t : sheet.texts)
    declare(t.role);
  return layers;
}

// Colours as the print draws the roles (AutoCAD index nearest to each), so a user who picks lines by
// colour in the cutting program sees the same choice as on the print preview.
int dxf_layer_colour(const std::string& layer) {
  if (layer == "MOUNTAIN") return 1;  // red
  if (layer == "VALLEY") return 5;    // blue
  if (layer == "TAB") return 8;       // grey
  if (layer == "LABEL") return 3;     // green: apart from the black cut lines
  if (layer == "REGMARK") return 6;   // magenta
  return kColourDefault;
}

std::string dxf_document(const Sheet& sheet, const DxfOptions& options, const std::string& name) {
  const Vec2 size = sheet.size_mm;
  if (!(std::isfinite(size.x) && std::isfinite(size.y) && size.x > 0 && size.y > 0))
    throw OutputError(name, "the sheet has no valid size");
  const std::vector<CutLine> lines = cut_lines(sheet, options, name);
  const std::vector<std::string> layers = dxf_layers(sheet);

  std::ostringstream out;
  GroupWriter g(out);
  write_header(g, size);
  write_tables(g, layers);
  g.code(0, "SECTION");
  g.code(2, "BLOCKS");
  g.code(0, "ENDSEC");
  write_entities(g, lines);
  g.code(0, "EOF");
  return out.str();
}

std::vector<std::filesystem::path> write_dxf_sheets(const std::vector<Sheet>& sheets,
                                                    const std::filesystem::path& path,
                                                    const DxfOptions& options) {
  if (sheets.empty()) throw OutputError(path.string(), "nothing to write: no sheets");
  // Every document is built and every temporary file written before the first rename, as render_sheets
  // does: a failure on sheet 3 never leaves sheets 1 and 2 of this run beside sheet 3 of an old one.
  std::vector<AtomicFile> files;
  files.reserve(sheets.size());
  for (std::size_t i = 0; i < sheets.size(); ++i) {
    const std::filesystem::path target = sheet_file_path(path, i);
    const std::string text = dxf_document(sheets[i], options, target.string());
    files.emplace_back(target);
    files.back().stream() << text;
  }
  std::vector<std::filesystem::path> written;
  for (AtomicFile& file : files) {
    file.commit();
    written.push_back(file.target());
  }
  return written;
}

}  // namespace foldkit::devices
