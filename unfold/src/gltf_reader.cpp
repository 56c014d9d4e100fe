// glTF 2.0 into a polygon soup: the default scene's node tree walked under its transforms, triangle
// primitives (lists, strips, fans), TEXCOORD_0 and the base colour of each material. The soup then goes
// through the same repairs and checks as every other format.
//
// foldkit reads glTF itself (on nlohmann-json and gltf_document) instead of through Assimp: Assimp 5.2's
// importer crashed (strcmp on a number read as a string) and allocated 2.3 GB on fuzz inputs within
// 20 s, and it hands a file its glTF importer refuses to whichever other importer claims the bytes.
#include <array>
#include <cmath>

#include "face_colours.hpp"
#include "foldkit/error.hpp"
#include "gltf_document.hpp"

namespace foldkit::unfold::detail {
namespace {

namespace fs = std::filesystem;
using gltf::Document;
using gltf::Json;

// Primitive modes of glTF 2.0; points and lines (0-3) are not surface.
constexpr std::uint64_t kTriangles = 4;
constexpr std::uint64_t kTriangleStrip = 5;
constexpr std::uint64_t kTriangleFan = 6;
constexpr std::uint64_t kMaxMode = 6;

/// A column-major 4x4 affine transform, as glTF writes `matrix`.
using Matrix = std::array<double, 16>;

constexpr Matrix kIdentity{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

Matrix multiply(const Matrix& a, const Matrix& b) {
  Matrix m{};
  for (int col = 0; col < 4; ++col)
    for (int row = 0; row < 4; ++row)
      for (int k = 0; k < 4; ++k)
        m[col * 4 + row] += a[k * 4 + row] * b[col * 4 + k];
  return m;
}

Vec3 apply(const Matrix& m, Vec3 p) {
  return {m[0] * p.x + m[4] * p.y + m[8] * p.z + m[12], m[1] * p.x + m[5] * p.y + m[9] * p.z + m[13],
          m[2] * p.x + m[6] * p.y + m[10] * p.z + m[14]};
}

// A mirroring transform turns counter-clockwise triangles clockwise (glTF 2.0, 3.7.2.1).
bool mirrors(const Matrix& m) {
  const double det = m[0] * (m[5] * m[10] - m[9] * m[6]) - m[4] * (m[1] * m[10] - m[9] * m[2]) +
                     m[8] * (m[1] * m[6] - m[5] * m[2]);
  return det < 0;
}

// `matrix`, or translation * rotation * scale.
Matrix local_transform(const Document& doc, const Json& node, const std::string& where) {
  if (const auto m = doc.numbers(node, "matrix", 16, where)) {
    Matrix out;
    std::copy(m->begin(), m->end(), out.begin());
    return out;
  }
  const std::vector<double> t =
      doc.numbers(node, "translation", 3, where).value_or(std::vector<double>{0, 0, 0});
  const std::vector<double> q =
      doc.numbers(node, "rotation", 4, where).value_or(std::vector<double>{0, 0, 0, 1});
  const std::vector<double> s = doc.numbers(node, "scale", 3, where).value_or(std::vector<double>{1, 1, 1});
  const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (n == 0) doc.fail(where, "rotation is a zero quaternion");
  const double x = q[0] / n, y = q[1] / n, z = q[2] / n, w = q[3] / n;
  const Matrix r{1 - 2 * (y * y + z * z),
                 2 * (x * y + z * w),
                 2 * (x * z - y * w),
                 0,
                 2 * (x * y - z * w),
                 1 - 2 * (x * x + z * z),
                 2 * (y * z + x * w),
                 0,
                 2 * (x * z + y * w),
                 2 * (y * z - x * w),
                 1 - 2 * (x * x + y * y),
                 0,
                 0,
                 0,
                 0,
                 1};
  Matrix out = r;
  for (int col = 0; col < 3; ++col)
    for (int row = 0; row < 3; ++row)
      out[col * 4 + row] *= s[static_cast<std::size_t>(col)];
  out[12] = t[0];
  out[13] = t[1];
  out[14] = t[2];
  return out;
}

Material read_material(Document& doc, std::size_t index) {
  const Json& in = doc.array("materials")[index];
  const std::string where = "material " + std::to_string(index);
  Material m;
  if (const Json* name = doc.member(in, "name", Json::value_t::string, where))
    m.name = gltf::printable(name->get<std::string>());
  const Json* pbr = doc.member(in, "pbrMetallicRoughness", Json::value_t::object, where);
  if (!pbr) return m;
  if (const auto f = doc.numbers(*pbr, "baseColorFactor", 4, where))
    m.colour = {std::clamp((*f)[0], 0.0, 1.0), std::clamp((*f)[1], 0.0, 1.0), std::clamp((*f)[2], 0.0, 1.0)};
  const Json* tex = doc.member(*pbr, "baseColorTexture", Json::value_t::object, where);
  if (!tex) return m;
  const auto texture = doc.index(*tex, "index", "textures", where);
  if (!texture) doc.fail(where, "baseColorTexture names no texture");
  const std::string tex_where = "texture " + std::to_string(*texture);
  const auto image = doc.index(doc.array("textures")[*texture], "source", "images", tex_where);
  if (!image) return m;  // an extension's image format (KTX2, WebP): printed in the colour alone
  const Json& img = doc.array("images")[*image];
  const std::string img_where = "image " + std::to_string(*image);
  if (const auto view = doc.index(img, "bufferView", "bufferViews", img_where)) {
    const std::string_view bytes = doc.view_bytes(*view, img_where);
    m.texture_data.assign(bytes.begin(), bytes.end());
    m.texture = "embedded image " + std::to_string(*image);
  } else if (const Json* uri = doc.member(img, "uri", Json::value_t::string, img_where)) {
    try {
      if (auto data = gltf::decode_data_uri(uri->get<std::string>())) {
        m.texture_data.assign(data->begin(), data->end());
        m.texture = "embedded image " + std::to_string(*image);
      } else {
        m.texture =
            (doc.folder() / gltf::uri_to_relative_path(uri->get<std::string>())).lexically_normal().string();
        if (gltf::printable(m.texture) != m.texture) throw std::invalid_argument("a name unfit to print");
      }
    } catch (const std::invalid_argument& e) {
      m.texture = gltf::printable(uri->get<std::string>()) + " (" + e.what() + ")";
    }
  }
  probe_texture(m);
  return m;
}

class SoupBuilder {
 public:
  SoupBuilder(Document& doc, int face_limit) : doc_(doc), face_limit_(face_limit) {}

  void add_mesh(std::size_t mesh_index, const Matrix& transform) {
    const std::string where = "mesh " + std::to_string(mesh_index);
    const Json* primitives =
        doc_.member(doc_.array("meshes")[mesh_index], "primitives", Json::value_t::array, where);
    if (!primitives) doc_.fail(where, "has no primitives");
    for (std::size_t p = 0; p < primitives->size(); ++p)
      add_primitive((*primitives)[p], transform, where + ", primitive " + std::to_string(p));
  }

  PolygonSoup take() {
    if (!any_uv_) soup_.polygon_uvs.clear();
    return std::move(soup_);
  }

 private:
  void add_primitive(const Json& prim, const Matrix& transform, const std::string& where) {
    if (!prim.is_object()) doc_.fail(where, "is not an object");
    std::uint64_t mode = kTriangles;
    if (const auto it = prim.find("mode"); it != prim.end()) {
      if (!it->is_number_unsigned() || it->get<std::uint64_t>() > kMaxMode)
        doc_.fail(where, "unknown primitive mode");
      mode = it->get<std::uint64_t>();
    }
    if (mode < kTriangles) return;
    const Json* attributes = doc_.member(prim, "attributes", Json::value_t::object, where);
    const auto position = attributes ? doc_.index(*attributes, "POSITION", "accessors", where) : std::nullopt;
    if (!position) doc_.fail(where, "has no POSITION");
    const std::vector<Vec3> points = doc_.read_vec3(*position, where);
    std::vector<Vec2> uvs;
    if (const auto uv = doc_.index(*attributes, "TEXCOORD_0", "accessors", where)) {
      uvs = doc_.read_vec2(*uv, where);
      if (uvs.size() != points.size()) doc_.fail(where, "TEXCOORD_0 and POSITION differ in count");
    }
    std::vector<std::uint32_t> indices;
    if (const auto ind = doc_.index(prim, "indices", "accessors", where)) {
      indices = doc_.read_indices(*ind, where);
    } else {
      indices.resize(points.size());
      for (std::size_t i = 0; i < indices.size(); ++i)
        indices[i] = static_cast<std::uint32_t>(i);
    }
    for (std::uint32_t i : indices)
      if (i >= points.size()) doc_.fail(where, "index " + std::to_string(i) + " names no vertex");
    const auto material = doc_.index(prim, "material", "materials", where);
    Corners corners{points, uvs, transform, mirrors(transform), material ? static_cast<int>(*material) : -1,
                    {}};
    corners.soup_index.assign(points.size(), -1);
    triangles_of(mode, indices, corners, where);
  }

  struct Corners {
    const std::vector<Vec3>& points;
    const std::vector<Vec2>& uvs;
    const Matrix& transform;
    bool mirrored;
    int material;
    std::vector<int> soup_index;  // per primitive vertex, its soup vertex once a face uses it
  };

  void triangles_of(std::uint64_t mode, const std::vector<std::uint32_t>& idx, Corners& c,
                    const std::string& where) {
    if (mode == kTriangles) {
      for (std::size_t i = 0; i + 2 < idx.size(); i += 3)
        add_triangle({idx[i], idx[i + 1], idx[i + 2]}, c, where);
    } else if (mode == kTriangleStrip) {
      for (std::size_t i = 0; i + 2 < idx.size(); ++i)
        add_triangle({idx[i], idx[i + 1 + i % 2], idx[i + 2 - i % 2]}, c, where, /*skip_degenerate=*/true);
    } else if (mode == kTriangleFan) {
      for (std::size_t i = 1; i + 1 < idx.size(); ++i)
        add_triangle({idx[i], idx[i + 1], idx[0]}, c, where, /*skip_degenerate=*/true);
    }
  }

  // Strips and fans stitch with repeated indices on purpose; a list's repeats go to the repairs.
  void add_triangle(std::array<std::uint32_t, 3> t, Corners& c, const std::string& where,
                    bool skip_degenerate = false) {
    if (skip_degenerate && (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])) return;
    if (++triangles_ > static_cast<std::uint64_t>(face_limit_))
      doc_.fail(where,
                "over the limit of " + std::to_string(face_limit_) + " triangles (decimate the mesh first)");
    if (c.mirrored) std::swap(t[1], t[2]);
    std::vector<int> poly;
    std::vector<Vec2> uv;
    for (std::uint32_t v : t) {
      if (c.soup_index[v] < 0) {
        c.soup_index[v] = static_cast<int>(soup_.vertices.size());
        soup_.vertices.push_back(apply(c.transform, c.points[v]));
      }
      poly.push_back(c.soup_index[v]);
      // glTF's v runs down the image; the mesh's runs up.
      if (!c.uvs.empty()) uv.push_back({c.uvs[v].x, 1 - c.uvs[v].y});
    }
    any_uv_ = any_uv_ || !uv.empty();
    soup_.polygons.push_back(std::move(poly));
    soup_.polygon_uvs.push_back(std::move(uv));
    soup_.polygon_material.push_back(c.material);
  }

  Document& doc_;
  int face_limit_;
  std::uint64_t triangles_ = 0;
  bool any_uv_ = false;
  PolygonSoup soup_;
};

// The scene's root nodes: `scene`, else the first scene, else every node no other node lists as a child.
std::vector<std::size_t> scene_roots(const Document& doc) {
  const Json& root = doc.root();
  std::optional<std::size_t> scene = doc.index(root, "scene", "scenes", "document");
  if (!scene && !doc.array("scenes").empty()) scene = 0;
  std::vector<std::size_t> roots;
  if (scene) {
    const std::string where = "scene " + std::to_string(*scene);
    const Json& s = doc.array("scenes")[*scene];
    if (const Json* nodes = doc.member(s, "nodes", Json::value_t::array, where))
      for (std::size_t k = 0; k < nodes->size(); ++k) {
        roots.push_back(doc.as_index((*nodes)[k], "nodes", where + ", node " + std::to_string(k)));
      }
    return roots;
  }
  std::vector<bool> child(doc.array("nodes").size(), false);
  for (std::size_t n = 0; n < child.size(); ++n)
    if (const Json* kids = doc.member(doc.array("nodes")[n], "children", Json::value_t::array, "node"))
      for (const Json& k : *kids)
        if (k.is_number_unsigned() && k.get<std::uint64_t>() < child.size())
          child[k.get<std::size_t>()] = true;
  for (std::size_t n = 0; n < child.size(); ++n)
    if (!child[n]) roots.push_back(n);
  return roots;
}

// Depth-first with an explicit stack (a node chain may be as deep as the file is long); every node is
// entered once, so a cycle or a node with two parents is an error instead of endless work.
void walk_nodes(Document& doc, SoupBuilder& builder) {
  const Json& nodes = doc.array("nodes");
  if (nodes.empty()) {
    for (std::size_t m = 0; m < doc.array("meshes").size(); ++m)
      builder.add_mesh(m, kIdentity);
    return;
  }
  std::vector<bool> entered(nodes.size(), false);
  std::vector<std::pair<std::size_t, Matrix>> stack;
  for (std::size_t r : scene_roots(doc))
    stack.emplace_back(r, kIdentity);
  while (!stack.empty()) {
    const auto [n, parent] = stack.back();
    stack.pop_back();
    const std::string where = "node " + std::to_string(n);
    if (entered[n]) doc.fail(where, "is reached twice (a cycle, or two parents)");
    entered[n] = true;
    const Json& node = nodes[n];
    const Matrix transform = multiply(parent, local_transform(doc, node, where));
    if (const auto mesh = doc.index(node, "mesh", "meshes", where)) builder.add_mesh(*mesh, transform);
    if (const Json* kids = doc.member(node, "children", Json::value_t::array, where))
      for (std::size_t k = 0; k < kids->size(); ++k) {
        stack.emplace_back(doc.as_index((*kids)[k], "nodes", where + ", child " + std::to_string(k)),
                           transform);
      }
  }
}

// Only materials some face uses, numbered in order of first use; unnamed ones get a name.
void keep_used_materials(Document& doc, PolygonSoup& soup) {
  std::vector<int> renumber(doc.array("materials").size(), -1);
  for (int& m : soup.polygon_material) {
    if (m < 0) continue;
    if (renumber[static_cast<std::size_t>(m)] < 0) {
      renumber[static_cast<std::size_t>(m)] = static_cast<int>(soup.materials.size());
      Material mat = read_material(doc, static_cast<std::size_t>(m));
      if (mat.name.empty()) mat.name = "material " + std::to_string(m + 1);
      soup.materials.push_back(std::move(mat));
    }
    m = renumber[static_cast<std::size_t>(m)];
  }
  if (soup.materials.empty()) soup.polygon_material.clear();
}

}  // namespace

PolygonSoup read_gltf(const std::string& bytes, const fs::path& path, const std::string& name,
                      const GltfLimits& limits, std::vector<std::string>& notes) {
  // A file within the face limit decodes at most a few vertices and indices per triangle.
  constexpr std::uint64_t kElementsPerFace = 8;
  const gltf::Limits doc_limits{
      limits.max_file_bytes, kElementsPerFace * static_cast<std::uint64_t>(std::max(limits.face_limit, 1))};
  Document doc(bytes, path.parent_path(), name, doc_limits);
  SoupBuilder builder(doc, limits.face_limit);
  walk_nodes(doc, builder);
  PolygonSoup soup = builder.take();
  keep_used_materials(doc, soup);
  for (const Material& m : soup.materials)
    if (!m.texture.empty() && !m.texture_found)
      notes.push_back("texture " + m.texture + " of material '" + m.name +
                      "' is missing or unreadable: its faces print in their colour");
  return soup;
}

}  // namespace foldkit::unfold::detail
