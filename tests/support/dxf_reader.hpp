#pragma once
// A DXF read back as a reader sees it, (code, value) pairs rather than text layout, for the tests of
// the DXF writer and of the bundle: header variables, declared layers and POLYLINE entities.
#include <sstream>
#include <string>
#include <vector>

#include "foldkit/geom/vec.hpp"

namespace foldkit::test {

/// One group: a code and its value line.
struct DxfGroup {
  int code;
  std::string value;
};

/// The file as groups.
inline std::vector<DxfGroup> dxf_groups(const std::string& text) {
  std::istringstream in(text);
  std::vector<DxfGroup> out;
  std::string code, value;
  while (std::getline(in, code) && std::getline(in, value))
    out.push_back({std::stoi(code), value});
  return out;
}

/// The header variable `name`'s first value; empty when the header lacks it.
inline std::string dxf_header_value(const std::vector<DxfGroup>& g, const std::string& name) {
  for (std::size_t i = 0; i + 1 < g.size(); ++i)
    if (g[i].code == 9 && g[i].value == name) return g[i + 1].value;
  return "";
}

/// One POLYLINE entity with its VERTEX points (DXF coordinates, y up).
struct DxfPolyline {
  std::string layer;
  std::vector<Vec2> points;
  bool closed = false;
};

/// Every POLYLINE of the file, in file order.
inline std::vector<DxfPolyline> dxf_polylines(const std::vector<DxfGroup>& g) {
  std::vector<DxfPolyline> out;
  bool in_vertex = false;
  for (const DxfGroup& group : g) {
    if (group.code == 0) {
      in_vertex = group.value == "VERTEX";
      if (group.value == "POLYLINE") out.push_back({});
      if (in_vertex && !out.empty()) out.back().points.push_back({});
      continue;
    }
    if (out.empty()) continue;
    if (group.code == 8 && !in_vertex) out.back().layer = group.value;
    if (group.code == 70 && !in_vertex) out.back().closed = (std::stoi(group.value) & 1) != 0;
    if (in_vertex && group.code == 10) out.back().points.back().x = std::stod(group.value);
    if (in_vertex && group.code == 20) out.back().points.back().y = std::stod(group.value);
  }
  return out;
}

/// The names of the LAYER table entries, in file order.
inline std::vector<std::string> dxf_declared_layers(const std::vector<DxfGroup>& g) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i + 1 < g.size(); ++i)
    if (g[i].code == 0 && g[i].value == "LAYER" && g[i + 1].code == 2) out.push_back(g[i + 1].value);
  return out;
}

}  // namespace foldkit::test
