// load_mesh: check the facts a reader might trust blindly (size, header counts, numbers), let OpenMesh's
// readers parse into a polygon soup through our own importer (so that our validation, not OpenMesh's
// TriMesh, decides what is wrong), then repair and validate the soup (mesh_io_soup.cpp). OFF, whose
// OpenMesh reader cannot be made safe from outside, is read by foldkit itself (mesh_io_off.cpp).
#include "foldkit/unfold/mesh_io.hpp"

#include <OpenMesh/Core/IO/IOManager.hh>
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/IO/importer/BaseImporter.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <string_view>

#include "face_colours.hpp"
#include "foldkit/error.hpp"
#include "foldkit/unfold/decimate.hpp"
#include "mesh_io_ascii.hpp"
#include "mesh_io_off.hpp"
#include "mesh_io_ply_body.hpp"
#include "mesh_io_soup.hpp"

namespace foldkit::unfold {
namespace {

namespace fs = std::filesystem;
using detail::check_declared_counts;
using detail::check_face_limit;
using detail::in_coordinate_range;
using detail::kMaxCoordinate;
using detail::PolygonSoup;
using detail::RawColours;

Colour colour_of(double r, double g, double b) {
  return {std::clamp(r, 0.0, 1.0), std::clamp(g, 0.0, 1.0), std::clamp(b, 0.0, 1.0)};
}

/// Collects what an OpenMesh reader finds, unchanged; everything else a reader may call is ignored.
class SoupImporter final : public OpenMesh::IO::BaseImporter {
 public:
  SoupImporter(PolygonSoup& soup, RawColours& colours) : soup_(soup), colours_(colours) {}

  OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3f& p) override { return add({p[0], p[1], p[2]}); }
  OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3d& p) override { return add({p[0], p[1], p[2]}); }
  OpenMesh::VertexHandle add_vertex() override { return add({}); }
  OpenMesh::HalfedgeHandle add_edge(OpenMesh::VertexHandle, OpenMesh::VertexHandle) override {
    return OpenMesh::HalfedgeHandle();
  }
  OpenMesh::FaceHandle add_face(const VHandles& indices) override {
    std::vector<int> poly;
    poly.reserve(indices.size());
    for (const auto& vh : indices)
      poly.push_back(vh.idx());
    soup_.polygons.push_back(std::move(poly));
    return OpenMesh::FaceHandle(static_cast<int>(soup_.polygons.size()) - 1);
  }
  OpenMesh::FaceHandle add_face(OpenMesh::HalfedgeHandle) override { return OpenMesh::FaceHandle(); }
  void add_face_texcoords(OpenMesh::FaceHandle fh, OpenMesh::VertexHandle,
                          const std::vector<OpenMesh::Vec2f>& uvs) override {
    if (auto* slot = face_slot(colours_.face_uvs, fh)) {
      slot->clear();
      for (const auto& uv : uvs)
        slot->push_back({uv[0], uv[1]});
    }
  }
  void add_face_texcoords(OpenMesh::FaceHandle, OpenMesh::VertexHandle,
                          const std::vector<OpenMesh::Vec3f>&) override {}
  void set_face_texindex(OpenMesh::FaceHandle fh, int index) override {
    // OpenMesh numbers textures from 1 and gives 0 to faces without one.
    if (auto* slot = face_slot(colours_.face_texture, fh, -1)) *slot = index > 0 ? index : -1;
  }
  void set_point(OpenMesh::VertexHandle vh, const OpenMesh::Vec3f& p) override {
    if (vh.idx() >= 0 && vh.idx() < static_cast<int>(soup_.vertices.size()))
      soup_.vertices[vh.idx()] = {p[0], p[1], p[2]};
  }
  void set_halfedge(OpenMesh::VertexHandle, OpenMesh::HalfedgeHandle) override {}
  void set_normal(OpenMesh::VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_normal(OpenMesh::VertexHandle, const OpenMesh::Vec3d&) override {}
  void set_color(OpenMesh::VertexHandle vh, const OpenMesh::Vec3uc& c) override {
    set_vertex_colour(vh, colour_of(c[0] / 255.0, c[1] / 255.0, c[2] / 255.0));
  }
  void set_color(OpenMesh::VertexHandle vh, const OpenMesh::Vec4uc& c) override {
    set_vertex_colour(vh, colour_of(c[0] / 255.0, c[1] / 255.0, c[2] / 255.0));
  }
  void set_color(OpenMesh::VertexHandle vh, const OpenMesh::Vec3f& c) override {
    set_vertex_colour(vh, colour_of(c[0], c[1], c[2]));
  }
  void set_color(OpenMesh::VertexHandle vh, const OpenMesh::Vec4f& c) override {
    set_vertex_colour(vh, colour_of(c[0], c[1], c[2]));
  }
  void set_texcoord(OpenMesh::VertexHandle, const OpenMesh::Vec2f&) override {}
  void set_status(OpenMesh::VertexHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_next(OpenMesh::HalfedgeHandle, OpenMesh::HalfedgeHandle) override {}
  void set_face(OpenMesh::HalfedgeHandle, OpenMesh::FaceHandle) override {}
  void request_face_texcoords2D() override {}
  void set_texcoord(OpenMesh::HalfedgeHandle, const OpenMesh::Vec2f&) override {}
  void set_texcoord(OpenMesh::VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_texcoord(OpenMesh::HalfedgeHandle, const OpenMesh::Vec3f&) override {}
  void set_status(OpenMesh::HalfedgeHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec3f&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec4f&) override {}
  void set_status(OpenMesh::EdgeHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_normal(OpenMesh::FaceHandle, const OpenMesh::Vec3f&) override {}
  void set_normal(OpenMesh::FaceHandle, const OpenMesh::Vec3d&) override {}
  void set_color(OpenMesh::FaceHandle fh, const OpenMesh::Vec3uc& c) override {
    set_face_colour(fh, colour_of(c[0] / 255.0, c[1] / 255.0, c[2] / 255.0));
  }
  void set_color(OpenMesh::FaceHandle fh, const OpenMesh::Vec4uc& c) override {
    set_face_colour(fh, colour_of(c[0] / 255.0, c[1] / 255.0, c[2] / 255.0));
  }
  void set_color(OpenMesh::FaceHandle fh, const OpenMesh::Vec3f& c) override {
    set_face_colour(fh, colour_of(c[0], c[1], c[2]));
  }
  void set_color(OpenMesh::FaceHandle fh, const OpenMesh::Vec4f& c) override {
    set_face_colour(fh, colour_of(c[0], c[1], c[2]));
  }
  void set_status(OpenMesh::FaceHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void add_texture_information(int id, std::string file) override {
    colours_.texture_names[id] = std::move(file);
  }
  // Header counts are not trusted for allocation: a hostile header could ask for terabytes.
  void reserve(unsigned int, unsigned int, unsigned int) override {}
  size_t n_vertices() const override { return soup_.vertices.size(); }
  size_t n_faces() const override { return soup_.polygons.size(); }
  size_t n_edges() const override { return 0; }

 private:
  OpenMesh::VertexHandle add(Vec3 p) {
    soup_.vertices.push_back(p);
    return OpenMesh::VertexHandle(static_cast<int>(soup_.vertices.size()) - 1);
  }
  // The slot of face fh in a per-face list, grown on demand; nullptr for a handle no face has.
  template <class T>
  T* face_slot(std::vector<T>& list, OpenMesh::FaceHandle fh, T fill = T{}) {
    if (fh.idx() < 0 || fh.idx() >= static_cast<int>(soup_.polygons.size())) return nullptr;
    if (list.size() < soup_.polygons.size()) list.resize(soup_.polygons.size(), fill);
    return &list[fh.idx()];
  }
  void set_face_colour(OpenMesh::FaceHandle fh, Colour c) {
    if (auto* slot = face_slot(colours_.face_colour, fh)) *slot = c;
  }
  void set_vertex_colour(OpenMesh::VertexHandle vh, Colour c) {
    if (vh.idx() < 0 || vh.idx() >= static_cast<int>(soup_.vertices.size())) return;
    if (colours_.vertex_colour.size() < soup_.vertices.size())
      colours_.vertex_colour.resize(soup_.vertices.size());
    colours_.vertex_colour[vh.idx()] = c;
  }
  PolygonSoup& soup_;
  RawColours& colours_;
};

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

std::string read_all(const fs::path& path, const std::string& name) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(name, "cannot open the file");
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// An OBJ `l v1 v2 ...` element (corners may be "v/vt", negative numbers count back from the last
// vertex): each segment is a seam between two file vertices.
void read_obj_line_element(const char* q, const char* eol, long vertices, const std::string& name, int line,
                           std::vector<FileEdge>& seams) {
  const auto where = " (line " + std::to_string(line) + ")";
  std::vector<int> corners;
  while (true) {
    while (q < eol && (*q == ' ' || *q == '\t' || *q == '\r'))
      ++q;
    if (q == eol || *q == '#') break;
    char* stop = nullptr;
    const long idx = std::strtol(q, &stop, 10);
    if (stop == q || (stop < eol && *stop != '/' && *stop != ' ' && *stop != '\t' && *stop != '\r'))
      throw InputError(name, "unparsable line element corner" + where);
    const long resolved = idx < 0 ? vertices + idx + 1 : idx;
    if (resolved < 1 || resolved > vertices)
      throw InputError(name, "line element references vertex " + std::to_string(idx) + " (only " +
                                 std::to_string(vertices) + " vertices so far)" + where);
    corners.push_back(static_cast<int>(resolved - 1));
    q = stop;
    while (q < eol && *q != ' ' && *q != '\t' && *q != '\r')
      ++q;
  }
  if (corners.size() < 2) throw InputError(name, "line element with fewer than 2 vertices" + where);
  for (std::size_t i = 0; i + 1 < corners.size(); ++i)
    seams.push_back({{corners[i], corners[i + 1]}, line});
}

std::string trimmed(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r");
  return std::string(s.substr(first, last - first + 1));
}

// Material names are few: a linear search keeps them in the order the file first uses them.
int material_index(std::vector<std::string>& names, const std::string& material) {
  const auto it = std::find(names.begin(), names.end(), material);
  if (it != names.end()) return static_cast<int>(it - names.begin());
  names.push_back(material);
  return static_cast<int>(names.size()) - 1;
}

// OpenMesh's OBJ reader parses numbers with iostreams, which reject "nan" and "inf" and silently keep
// going, and it skips faces with fewer than three corners (the mark of a truncated file). So the facts a
// user can get wrong are checked here first, line by line, with file line numbers in the messages.
// Returns the seams the file marks with `l` (line) elements, which OpenMesh's reader skips.
// What an OBJ says that OpenMesh's reader does not pass on.
struct ObjFacts {
  std::vector<FileEdge> seams;              ///< `l` (line) elements
  std::vector<std::string> material_names;  ///< `usemtl` names in order of first use
  std::vector<int> face_material_name;      ///< per face, index into material_names (-1: none)
  /// Every `v` line's coordinates as written, in double precision: OpenMesh's reader narrows them to
  /// float, which moves a point of a model placed far from the origin (a building at its survey
  /// coordinates, 5,412,345.71 m north) by up to a quarter of a metre.
  std::vector<Vec3> positions;
};

ObjFacts check_obj_text(const std::string& text, const std::string& name, int face_limit) {
  ObjFacts facts;
  std::vector<FileEdge>& seams = facts.seams;
  int current_material = -1;
  // Pointer scanning, not iostreams: this pass runs over every byte of files up to the size limit.
  // std::string keeps a terminating NUL, so strtod/strtol stop at the end of the buffer too.
  const char* p = text.c_str();
  const char* const end = p + text.size();
  std::size_t line_no = 0;
  long vertices = 0;
  std::uint64_t triangles = 0;
  auto next_token = [](const char*& q, const char* eol) -> std::string_view {
    while (q < eol && (*q == ' ' || *q == '\t' || *q == '\r'))
      ++q;
    const char* start = q;
    while (q < eol && *q != ' ' && *q != '\t' && *q != '\r')
      ++q;
    return {start, static_cast<std::size_t>(q - start)};
  };
  while (p < end) {
    const char* eol = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(end - p)));
    const bool last_line_unterminated = eol == nullptr;
    if (last_line_unterminated) eol = end;
    ++line_no;
    const char* q = p;
    p = eol + 1;
    const std::string_view tag = next_token(q, eol);
    if (tag == "usemtl") {
      current_material = material_index(facts.material_names, trimmed(std::string_view(q, eol - q)));
      continue;
    }
    if (tag != "v" && tag != "f" && tag != "l") continue;
    const auto where = [&] { return " (line " + std::to_string(line_no) + ")"; };
    if (tag == "v") {
      ++vertices;
      double xyz[3];
      for (int k = 0; k < 3; ++k) {
        const std::string_view tok = next_token(q, eol);
        if (tok.empty())
          throw InputError(name, "vertex " + std::to_string(vertices) + " has fewer than 3 coordinates" +
                                     (last_line_unterminated ? " (truncated file?)" : "") + where());
        char* stop = nullptr;
        const double x = std::strtod(tok.data(), &stop);
        if (stop != tok.data() + tok.size())
          throw InputError(name, "unparsable coordinate '" + std::string(tok.substr(0, 32)) + "'" + where());
        if (!std::isfinite(x))
          throw InputError(name,
                           "vertex " + std::to_string(vertices) + " has a non-finite coordinate" + where());
        if (!in_coordinate_range(x))
          throw InputError(name, "vertex " + std::to_string(vertices) + ": coordinate out of range '" +
                                     std::string(tok.substr(0, 32)) + "'" + where());
        xyz[k] = x;
      }
      facts.positions.push_back({xyz[0], xyz[1], xyz[2]});
    } else if (tag == "l") {
      read_obj_line_element(q, eol, vertices, name, static_cast<int>(line_no), seams);
    } else {
      int corners = 0;
      for (std::string_view tok = next_token(q, eol); !tok.empty(); tok = next_token(q, eol)) {
        char* stop = nullptr;
        const long idx = std::strtol(tok.data(), &stop, 10);
        if (stop == tok.data() || (stop != tok.data() + tok.size() && *stop != '/'))
          throw InputError(name, "unparsable face corner '" + std::string(tok.substr(0, 32)) + "'" + where());
        const long resolved = idx < 0 ? vertices + idx + 1 : idx;
        if (resolved < 1 || resolved > vertices)
          throw InputError(name, "face references vertex " + std::to_string(idx) + " (only " +
                                     std::to_string(vertices) + " vertices so far)" + where());
        ++corners;
      }
      if (corners < 3)
        throw InputError(name, std::string(last_line_unterminated ? "truncated file: " : "") +
                                   "face with only " + std::to_string(corners) + " corners" + where());
      triangles += static_cast<std::uint64_t>(corners - 2);
      check_face_limit(triangles, face_limit, name);
      facts.face_material_name.push_back(current_material);
    }
  }
  return facts;
}

// An ASCII STL says "solid" first and holds only printable text; the first 4 KiB decide it (a binary STL's
// header may say "solid" too, but its triangles soon hold other bytes).
constexpr std::size_t kStlSniffBytes = 4096;

bool head_may_be_ascii_stl(std::string_view head) {
  const std::size_t first = head.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return true;  // only blank so far: the rest decides
  return head.compare(first, 5, "solid") == 0 &&
         std::all_of(head.begin(), head.begin() + std::min(head.size(), kStlSniffBytes), [](unsigned char c) {
           return c == '\n' || c == '\r' || c == '\t' || (c >= 32 && c < 127);
         });
}

InputError stl_count_mismatch(std::uint32_t count, std::uintmax_t size, const std::string& name) {
  return InputError(name, "binary STL header says " + std::to_string(count) + " triangles (" +
                              std::to_string(84 + 50 * static_cast<std::uint64_t>(count)) +
                              " bytes) but the file has " + std::to_string(size) + " bytes");
}

// A binary STL is an 80-byte header, a 32-bit triangle count and 50 bytes per triangle: the size must
// agree with the count, or the reader would run past the end or silently drop triangles.
bool check_stl(const std::string& bytes, const std::string& name, int face_limit) {
  std::size_t first = bytes.find_first_not_of(" \t\r\n");
  const bool says_solid = first != std::string::npos && bytes.compare(first, 5, "solid") == 0;
  if (bytes.size() >= 84) {
    std::uint32_t count = 0;
    std::memcpy(&count, bytes.data() + 80, 4);  // little-endian on every platform we build for
    if (84 + 50 * static_cast<std::uint64_t>(count) == bytes.size()) {
      check_face_limit(count, face_limit, name);
      return true;
    }
    if (!head_may_be_ascii_stl(bytes) || bytes.find("facet") == std::string::npos)
      throw stl_count_mismatch(count, bytes.size(), name);
    return false;
  }
  if (!says_solid) throw InputError(name, "too short for a binary STL and not an ASCII STL");
  return false;
}

void check_ascii_stl_text(const std::string& text, const std::string& name) {
  std::istringstream in(text);
  std::string tok;
  std::size_t facets = 0, endfacets = 0, vertices = 0;
  while (in >> tok) {
    if (tok == "facet")
      ++facets;
    else if (tok == "endfacet")
      ++endfacets;
    else if (tok == "vertex") {
      ++vertices;
      for (int k = 0; k < 3; ++k) {
        if (!(in >> tok))
          throw InputError(name, "truncated ASCII STL (vertex " + std::to_string(vertices) + ")");
        char* stop = nullptr;
        const double x = std::strtod(tok.c_str(), &stop);
        if (stop == tok.c_str() || *stop != '\0')
          throw InputError(name, "unparsable coordinate '" + tok.substr(0, 32) + "' in ASCII STL");
        if (!std::isfinite(x))
          throw InputError(name, "vertex " + std::to_string(vertices) + " has a non-finite coordinate");
        if (!in_coordinate_range(x))
          throw InputError(name, "vertex " + std::to_string(vertices) + ": coordinate out of range '" +
                                     tok.substr(0, 32) + "'");
      }
    }
  }
  const auto endsolid = text.rfind("endsolid");
  const bool finished = endsolid != std::string::npos && endsolid > text.rfind("endfacet");
  if (facets != endfacets || vertices != 3 * facets || !finished)
    throw InputError(name, "truncated or malformed ASCII STL (" + std::to_string(facets) + " facets, " +
                               std::to_string(endfacets) + " closed, " + std::to_string(vertices) +
                               " vertices)");
  if (facets == 0) throw InputError(name, "no faces in the file");
}

// OpenMesh's PLY reader loops forever or crashes on some malformed headers (an unknown keyword, an
// element line without a count), so the header is checked strictly here: only what a triangle mesh needs.

// Where end_header starts, after checking the magic line and that end_header is a line of its own.
std::size_t ply_header_end(const std::string& text, const std::string& name) {
  if (text.compare(0, 4, "ply\n") != 0 && text.compare(0, 5, "ply\r\n") != 0)
    throw InputError(name, "not a PLY file (no 'ply' magic line)");
  const auto end = text.find("end_header");
  if (end == std::string::npos) throw InputError(name, "truncated PLY header (no end_header)");
  // OpenMesh reads the header word by word and loops forever (printing "Unsupported entry type") when
  // end_header runs into the next bytes, so it must be a line of its own (found by fuzz_load_ply).
  const std::size_t after = end + std::string("end_header").size();
  const bool own_line = (end > 0 && text[end - 1] == '\n') &&
                        (text.compare(after, 1, "\n") == 0 || text.compare(after, 2, "\r\n") == 0);
  if (!own_line) throw InputError(name, "malformed PLY header: end_header is not a line of its own");
  return end;
}

bool is_ply_type(const std::string& t) {
  static constexpr std::array<std::string_view, 16> kTypes{
      "char", "uchar", "short", "ushort", "int",   "uint",   "float",   "double",
      "int8", "uint8", "int16", "uint16", "int32", "uint32", "float32", "float64"};
  return std::find(kTypes.begin(), kTypes.end(), t) != kTypes.end();
}

// What a PLY header declares, as far as a triangle mesh needs it.
struct PlyHeader {
  std::string format, element;  ///< element: the one the next property lines belong to
  std::uint64_t nv = 0, nf = 0;
  std::vector<detail::PlyProperty> vertex_layout, face_layout;
  bool has_vertex = false, has_face = false, face_list = false;
  int xyz = 0, vertex_properties = 0;
};

// `element vertex N` or `element face N`, vertices first, each once.
void read_ply_element(const std::vector<std::string>& w, const std::string& where, const std::string& name,
                      PlyHeader& h) {
  if (w.size() != 3 || w[2].find_first_not_of("0123456789") != std::string::npos || w[2].size() > 12)
    throw InputError(name, "unparsable PLY element line" + where);
  const std::uint64_t count = std::stoull(w[2]);
  h.element = w[1];
  if (h.element == "vertex") {
    if (h.has_vertex) throw InputError(name, "two vertex elements" + where);
    h.has_vertex = true;
    h.nv = count;
  } else if (h.element == "face") {
    if (h.has_face || !h.has_vertex) throw InputError(name, "face element before vertices or twice" + where);
    h.has_face = true;
    h.nf = count;
  } else {
    throw InputError(name, "unsupported PLY element '" + h.element.substr(0, 32) + "'" + where);
  }
}

// `property TYPE NAME` of the current element, or the face's one `property list COUNT INDEX vertex_indices`.
void read_ply_property(const std::vector<std::string>& w, const std::string& where, const std::string& name,
                       PlyHeader& h) {
  if (h.element.empty()) throw InputError(name, "PLY property before any element" + where);
  if (w.size() == 5 && w[1] == "list" && is_ply_type(w[2]) && is_ply_type(w[3])) {
    if (h.element != "face" || h.face_list) throw InputError(name, "unsupported PLY list property" + where);
    if (w[4] != "vertex_indices" && w[4] != "vertex_index")
      throw InputError(name, "unsupported PLY face list '" + w[4].substr(0, 32) + "'" + where);
    if (!detail::ply_integer_type(w[2]) || !detail::ply_integer_type(w[3]))
      throw InputError(name, "PLY face list with a non-integer count or index type" + where);
    h.face_list = true;
    h.face_layout.push_back({w[3], w[2], w[4]});
  } else if (w.size() == 3 && is_ply_type(w[1])) {
    if (h.element == "vertex" && detail::ply_axis(w[2]) >= 0) ++h.xyz;
    if (h.element == "vertex") ++h.vertex_properties;
    (h.element == "vertex" ? h.vertex_layout : h.face_layout).push_back({w[1], "", w[2]});
  } else {
    throw InputError(name, "unparsable PLY property line" + where);
  }
}

// The header lines before end_header, each checked as it is read; then that it names a triangle mesh.
PlyHeader read_ply_header(const std::string& text, std::size_t end, const std::string& name) {
  std::istringstream in(text.substr(0, end));
  std::string line;
  PlyHeader h;
  int line_no = 0;
  std::getline(in, line);  // "ply"
  ++line_no;
  while (std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::istringstream ls(line);
    std::vector<std::string> w;
    for (std::string t; ls >> t;)
      w.push_back(t);
    const std::string where = " (PLY header line " + std::to_string(line_no) + ")";
    if (w.empty() || w[0] == "comment" || w[0] == "obj_info") continue;
    if (w[0] == "format") {
      if (w.size() != 3 ||
          (w[1] != "ascii" && w[1] != "binary_little_endian" && w[1] != "binary_big_endian") || w[2] != "1.0")
        throw InputError(name, "unsupported PLY format line" + where);
      h.format = w[1];
    } else if (w[0] == "element") {
      read_ply_element(w, where, name, h);
    } else if (w[0] == "property") {
      read_ply_property(w, where, name, h);
    } else {
      throw InputError(name, "unparsable PLY header line '" + line.substr(0, 32) + "'" + where);
    }
  }
  if (h.format.empty()) throw InputError(name, "PLY header without a format line");
  if (!h.has_vertex || h.xyz != 3) throw InputError(name, "PLY header without vertex x, y and z");
  if (!h.has_face || !h.face_list) throw InputError(name, "PLY header without a face list");
  return h;
}

// Where x, y and z stand among a vertex's properties (the header has declared each once).
std::array<int, 3> ply_xyz_columns(const std::vector<detail::PlyProperty>& vertex_layout) {
  std::array<int, 3> columns{0, 1, 2};
  for (std::size_t i = 0; i < vertex_layout.size(); ++i)
    if (const int axis = detail::ply_axis(vertex_layout[i].name); axis >= 0)
      columns[static_cast<std::size_t>(axis)] = static_cast<int>(i);
  return columns;
}

// The header and body checked before OpenMesh reads them; returns every vertex's x, y and z as written.
std::vector<Vec3> check_ply_text(const std::string& text, const std::string& name, int face_limit) {
  const std::size_t end = ply_header_end(text, name);
  const PlyHeader h = read_ply_header(text, end, name);
  const bool ascii = h.format == "ascii";
  check_face_limit(h.nf, face_limit, name);
  check_declared_counts(h.nv, h.nf, ascii ? 6 : 12, ascii ? 8 : 13, text.size() - end, name);
  std::vector<Vec3> written;
  if (ascii) {
    const auto body = text.find('\n', end);
    detail::AsciiBlockOptions block;
    block.exact_vertex_numbers = h.vertex_properties;
    block.exact_face_numbers = h.face_layout.size() == 1;
    block.xyz_columns = ply_xyz_columns(h.vertex_layout);
    const std::size_t faces_at = detail::read_ascii_vertex_block(
        text, body == std::string::npos ? text.size() : body + 1, h.nv, name, block, &written);
    detail::read_ascii_faces(text, faces_at, h.nf, h.nv, name, block);
  } else {
    const std::size_t after = end + std::string("end_header").size();
    const std::size_t body = after + (text[after] == '\r' ? 2 : 1);
    detail::check_binary_ply_body(std::string_view(text).substr(body), h.format == "binary_big_endian",
                                  h.vertex_layout, h.nv, h.face_layout, h.nf, kMaxCoordinate, name, &written);
  }
  return written;
}

void silence_openmesh() {
  // OpenMesh reports problems on its global log streams; a library must not print, and our own
  // validation reports every problem that matters.
  omerr().disable();
  omlog().disable();
  omout().disable();
}

// The file exists, is a regular file and is within the size limit: its size in bytes.
std::uintmax_t checked_file_size(const fs::path& path, const std::string& name, const LoadOptions& options) {
  std::error_code ec;
  const auto status = fs::status(path, ec);
  if (ec || !fs::exists(status)) throw InputError(name, "no such file");
  if (!fs::is_regular_file(status)) throw InputError(name, "not a regular file");
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) throw InputError(name, "cannot read the file size");
  if (size == 0) throw InputError(name, "empty file");
  if (size > options.max_file_bytes)
    throw InputError(name, "file is " + std::to_string(size) + " bytes, over the limit of " +
                               std::to_string(options.max_file_bytes) + " bytes");
  return size;
}

// The file's extension in lower case, one of the formats load_mesh reads.
std::string checked_extension(const fs::path& path, const std::string& name) {
  const std::string ext = lower(path.extension().string());
  if (ext != ".obj" && ext != ".off" && ext != ".stl" && ext != ".ply" && ext != ".gltf" && ext != ".glb")
    throw InputError(name,
                     "unsupported file type '" + ext + "' (expected .obj, .off, .stl, .ply, .gltf or .glb)");
  return ext;
}

// A binary STL states its triangle count up front: one over the limit, or one whose count disagrees with
// the file's size and whose first bytes are not ASCII STL, is refused from its first 4 KiB, before the
// whole file is read (and held: up to 1 GiB).
void refuse_bad_binary_stl_early(const fs::path& path, std::uintmax_t size, int face_limit,
                                 const std::string& name) {
  if (size < 84) return;
  std::ifstream in(path, std::ios::binary);
  std::string head(static_cast<std::size_t>(std::min<std::uintmax_t>(size, kStlSniffBytes)), '\0');
  if (!in.read(head.data(), static_cast<std::streamsize>(head.size()))) return;
  std::uint32_t count = 0;
  std::memcpy(&count, head.data() + 80, 4);
  if (84 + 50 * static_cast<std::uint64_t>(count) == size)
    check_face_limit(count, face_limit, name);
  else if (!head_may_be_ascii_stl(head))
    throw stl_count_mismatch(count, size, name);
}

// What a format's reader hands on to the repairs, besides the soup itself.
struct FileSoup {
  PolygonSoup soup;
  detail::RepairOptions repair;
  std::vector<std::string> notes;  ///< the reader's notes (texture files, materials)
  std::vector<FileEdge> seams;     ///< OBJ `l` elements
};

// How far OpenMesh's float narrowing may move a point, as a share of the model's largest dimension,
// before the OBJ's coordinates are taken as written: a millionth is 0.15 micrometres at 150 mm. Below it
// the model is read as Blender and every float-based tool read it, and as foldkit always has.
constexpr double kFloatShiftShare = 1e-6;

// The vertices as written (an OBJ's `v` lines, a PLY's x, y and z) in place of OpenMesh's single-precision
// copies, where the narrowing moved a point by more than kFloatShiftShare of the model's size and the two are
// the same vertices: as many, each the same point once narrowed to float.
void keep_double_positions(std::vector<Vec3> written, PolygonSoup& soup) {
  if (written.size() != soup.vertices.size() || written.empty()) return;
  const auto narrowed = [](double x) { return static_cast<double>(static_cast<float>(x)); };
  Vec3 lo = written.front(), hi = written.front();
  double shift = 0;
  for (std::size_t i = 0; i < written.size(); ++i) {
    const Vec3 &w = written[i], &read = soup.vertices[i];
    if (narrowed(w.x) != read.x || narrowed(w.y) != read.y || narrowed(w.z) != read.z) return;
    lo = {std::min(lo.x, w.x), std::min(lo.y, w.y), std::min(lo.z, w.z)};
    hi = {std::max(hi.x, w.x), std::max(hi.y, w.y), std::max(hi.z, w.z)};
    shift = std::max({shift, std::fabs(w.x - read.x), std::fabs(w.y - read.y), std::fabs(w.z - read.z)});
  }
  if (shift > kFloatShiftShare * std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z}))
    soup.vertices = std::move(written);
}

// OBJ, STL and PLY through OpenMesh's readers into the soup (their text already checked), with the colours
// and textures they name.
void read_with_openmesh(const fs::path& path, const std::string& ext, const std::string& bytes, ObjFacts obj,
                        std::vector<Vec3> written, FileSoup& out) {
  const std::string name = path.string();
  silence_openmesh();
  RawColours colours;
  SoupImporter importer(out.soup, colours);
  OpenMesh::IO::Options read_options;
  read_options += OpenMesh::IO::Options::FaceTexCoord;
  read_options += OpenMesh::IO::Options::FaceColor;
  read_options += OpenMesh::IO::Options::VertexColor;
  if (!OpenMesh::IO::IOManager().read(name, importer, read_options))
    throw InputError(name, "unparsable " + ext.substr(1) + " file");
  keep_double_positions(std::move(written), out.soup);
  // map_Kd names are relative to the MTL file, which mtllib names relative to the OBJ.
  fs::path texture_dir = path.parent_path();
  if (ext == ".obj")
    if (const auto mtl = detail::obj_material_library(bytes, path)) {
      texture_dir = mtl->parent_path();
      std::error_code exists_ec;
      if (!fs::is_regular_file(*mtl, exists_ec))
        out.notes.push_back("material library " + mtl->string() + " not found: faces print white");
    }
  colours.material_names = std::move(obj.material_names);
  colours.face_material_name = std::move(obj.face_material_name);
  detail::attach_raw_colours(std::move(colours), texture_dir, out.soup, out.notes);
}

// The file's polygons as its format's reader finds them, after the format's own checks.
FileSoup read_file_soup(const fs::path& path, const std::string& ext, const std::string& bytes,
                        const LoadOptions& options) {
  const std::string name = path.string();
  FileSoup out;
  if (ext == ".gltf" || ext == ".glb") {
    out.soup = detail::read_gltf(bytes, path, name, {options.max_file_bytes, options.face_limit}, out.notes);
    return out;
  }
  if (ext == ".off") {
    RawColours colours;
    out.soup = detail::read_off(bytes, name, options.face_limit, colours);
    detail::attach_raw_colours(std::move(colours), path.parent_path(), out.soup, out.notes);
    return out;
  }
  ObjFacts obj;
  std::vector<Vec3> written;  // the coordinates as the file writes them, where foldkit's own check read them
  if (ext == ".obj") {
    obj = check_obj_text(bytes, name, options.face_limit);
    out.seams = obj.seams;
    written = std::move(obj.positions);
  } else if (ext == ".stl") {
    if (!check_stl(bytes, name, options.face_limit)) check_ascii_stl_text(bytes, name);
    out.repair.weld_all = true;
  } else {
    written = check_ply_text(bytes, name, options.face_limit);
  }
  read_with_openmesh(path, ext, bytes, std::move(obj), std::move(written), out);
  return out;
}

// Polygons become at least this many triangles: refused over the limit before any repair runs.
void check_triangle_count(const PolygonSoup& soup, int face_limit, const std::string& name) {
  std::uint64_t triangles = 0;
  for (const auto& poly : soup.polygons)
    triangles += poly.size() >= 3 ? poly.size() - 2 : 1;
  if (triangles > static_cast<std::uint64_t>(face_limit))
    throw InputError(name, std::to_string(triangles) + " triangles, over the limit of " +
                               std::to_string(face_limit) + " (decimate the mesh first)");
}

// Down to options.max_faces (quadric error), when the mesh has more.
void decimate_to_limit(LoadedMesh& out, const LoadOptions& options) {
  if (!options.max_faces || out.mesh.num_faces() <= *options.max_faces) return;
  const int before = out.mesh.num_faces();
  out.mesh = decimate(out.mesh, *options.max_faces);
  out.origin = {};  // no vertex of the file is kept as it was
  out.notes.push_back("decimated from " + std::to_string(before) + " to " +
                      std::to_string(out.mesh.num_faces()) + " faces (quadric error)");
}

}  // namespace

LoadedMesh load_mesh(const fs::path& path, const LoadOptions& options) {
  const std::string name = path.string();
  const std::uintmax_t size = checked_file_size(path, name, options);
  const std::string ext = checked_extension(path, name);
  if (ext == ".stl") refuse_bad_binary_stl_early(path, size, options.face_limit, name);
  const std::string bytes = read_all(path, name);
  if (bytes.find_first_not_of(" \t\r\n") == std::string::npos)
    throw InputError(name, "empty file (only whitespace)");
  FileSoup file = read_file_soup(path, ext, bytes, options);
  if (file.soup.polygons.empty()) throw InputError(name, "no faces in the file");
  check_triangle_count(file.soup, options.face_limit, name);

  LoadedMesh out;
  out.file_seams = std::move(file.seams);
  // The first vertex number in the format's own face lists (glTF indices count from 0 too).
  out.index_base = ext == ".obj" || ext == ".stl" ? 1 : 0;
  out.original_faces = static_cast<int>(file.soup.polygons.size());
  for (const auto& polygon : file.soup.polygons)
    (polygon.size() == 4 ? out.file_quads : out.file_ngons) += polygon.size() > 3;
  detail::Repaired repaired = detail::repair_soup(std::move(file.soup), name, file.repair, out.notes);
  out.mesh = std::move(repaired.mesh);
  out.origin = std::move(repaired.origin);
  out.notes.insert(out.notes.end(), file.notes.begin(), file.notes.end());
  if (ext == ".stl")
    out.notes.insert(out.notes.begin(),
                     "welded " + std::to_string(3 * static_cast<std::uint64_t>(out.original_faces)) +
                         " triangle corners into " + std::to_string(out.mesh.num_vertices()) +
                         " shared vertices");
  decimate_to_limit(out, options);
  return out;
}

}  // namespace foldkit::unfold
