// Readers report colour face by face; printing wants few materials. Faces with the same colour and
// texture share one. Texture images are probed here (header only) so that a missing or unreadable
// image is one note at load time, not a surprise on the printed sheet.
#include "face_colours.hpp"

#include <stb_image.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <tuple>

namespace foldkit::unfold::detail {
namespace {

namespace fs = std::filesystem;

std::string hex_colour(Colour c) {
  auto byte = [](double v) { return static_cast<int>(std::lround(std::clamp(v, 0.0, 1.0) * 255)); };
  char buf[16];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", byte(c.r), byte(c.g), byte(c.b));
  return buf;
}

// A face of a PLY with vertex colours only: the mean of its corners, when every corner has one.
std::optional<Colour> mean_vertex_colour(const std::vector<std::optional<Colour>>& vertex_colour,
                                         const std::vector<int>& polygon) {
  Colour sum{0, 0, 0};
  for (int v : polygon) {
    if (v < 0 || v >= static_cast<int>(vertex_colour.size()) || !vertex_colour[v]) return std::nullopt;
    sum = {sum.r + vertex_colour[v]->r, sum.g + vertex_colour[v]->g, sum.b + vertex_colour[v]->b};
  }
  const double n = static_cast<double>(polygon.size());
  return Colour{sum.r / n, sum.g / n, sum.b / n};
}

}  // namespace

void probe_texture(Material& material) {
  int w = 0, h = 0, channels = 0;
  bool ok = false;
  if (!material.texture_data.empty()) {
    ok = material.texture_data.size() < (std::size_t{1} << 31) &&
         stbi_info_from_memory(material.texture_data.data(), static_cast<int>(material.texture_data.size()),
                               &w, &h, &channels) != 0;
  } else if (!material.texture.empty()) {
    std::error_code ec;
    ok = fs::is_regular_file(material.texture, ec) &&
         stbi_info(material.texture.c_str(), &w, &h, &channels) != 0;
  }
  material.texture_found = ok && w > 0 && h > 0;
  material.texture_width_px = material.texture_found ? w : 0;
  material.texture_height_px = material.texture_found ? h : 0;
}

std::optional<fs::path> obj_material_library(const std::string& obj_text, const fs::path& obj_path) {
  std::size_t at = 0;
  while ((at = obj_text.find("mtllib", at)) != std::string::npos) {
    const bool line_start = at == 0 || obj_text[at - 1] == '\n';
    at += 6;
    if (!line_start || at >= obj_text.size() || (obj_text[at] != ' ' && obj_text[at] != '\t')) continue;
    const std::size_t eol = std::min(obj_text.find('\n', at), obj_text.size());
    std::string file = obj_text.substr(at, eol - at);
    const auto first = file.find_first_not_of(" \t");
    const auto last = file.find_last_not_of(" \t\r");
    if (first == std::string::npos) continue;
    file = file.substr(first, last - first + 1);
    return obj_path.parent_path() / file;
  }
  return std::nullopt;
}

void attach_raw_colours(RawColours raw, const fs::path& texture_dir, PolygonSoup& soup,
                        std::vector<std::string>& notes) {
  const std::size_t n = soup.polygons.size();
  raw.face_uvs.resize(n);
  raw.face_colour.resize(n);
  raw.face_texture.resize(n, -1);
  // Names are per `f` line of the file; should the reader's faces not be those lines one to one, no
  // name is better than a wrong one.
  if (raw.face_material_name.size() != n) raw.face_material_name.assign(n, -1);
  bool any_uv = false, any_colour = false;
  for (std::size_t f = 0; f < n; ++f) {
    if (!raw.face_colour[f] && !raw.vertex_colour.empty())
      raw.face_colour[f] = mean_vertex_colour(raw.vertex_colour, soup.polygons[f]);
    // OpenMesh reports coordinates only for faces that have one per corner; anything else is dropped.
    if (raw.face_uvs[f].size() != soup.polygons[f].size()) raw.face_uvs[f].clear();
    any_uv = any_uv || !raw.face_uvs[f].empty();
    any_colour = any_colour || raw.face_colour[f] || raw.face_texture[f] >= 0;
  }
  if (any_uv) soup.polygon_uvs = std::move(raw.face_uvs);
  if (!any_colour) return;

  // Materials as the file names them: two `usemtl` of the same colour stay two materials.
  std::map<std::tuple<double, double, double, int, int>, int> material_of;
  soup.polygon_material.assign(n, -1);
  for (std::size_t f = 0; f < n; ++f) {
    const Colour c = raw.face_colour[f].value_or(Colour{});
    // A texture without coordinates cannot be mapped: that face prints in its colour.
    int tex = raw.face_texture[f];
    if (tex >= 0 && (soup.polygon_uvs.empty() || soup.polygon_uvs[f].empty())) tex = -1;
    if (tex >= 0 && !raw.texture_names.count(tex)) tex = -1;
    const int named = raw.face_material_name[f];
    const auto key = std::make_tuple(c.r, c.g, c.b, tex, named);
    auto [it, inserted] = material_of.try_emplace(key, static_cast<int>(soup.materials.size()));
    if (inserted) {
      Material m;
      m.colour = c;
      if (tex >= 0) {
        m.texture = (texture_dir / raw.texture_names[tex]).lexically_normal().string();
        m.name = fs::path(raw.texture_names[tex]).stem().string();
        probe_texture(m);
        if (!m.texture_found)
          notes.push_back("texture " + m.texture +
                          " is missing or unreadable: its faces print in their colour " + hex_colour(c));
      } else {
        m.name = hex_colour(c);
      }
      if (named >= 0 && !raw.material_names[static_cast<std::size_t>(named)].empty())
        m.name = raw.material_names[static_cast<std::size_t>(named)];
      soup.materials.push_back(std::move(m));
    }
    soup.polygon_material[f] = it->second;
  }
}

}  // namespace foldkit::unfold::detail
