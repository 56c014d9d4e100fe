#include "mesh_io_ply_body.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <optional>
#include <utility>

#include "foldkit/error.hpp"

namespace foldkit::unfold::detail {
namespace {

bool is_signed_type(const std::string& type) {
  return type == "char" || type == "short" || type == "int" || type == "int8" || type == "int16" ||
         type == "int32";
}

// An integer of the given PLY type at `at`, widened; the caller has checked that the bytes are there.
std::int64_t read_integer(const char* at, const std::string& type, bool big_endian) {
  const int bytes = ply_type_bytes(type);
  unsigned char raw[4] = {};
  std::memcpy(raw, at, static_cast<std::size_t>(bytes));
  if (big_endian) std::reverse(raw, raw + bytes);
  std::uint64_t u = 0;
  for (int i = bytes - 1; i >= 0; --i)
    u = (u << 8) | raw[i];
  if (is_signed_type(type) && (u >> (8 * bytes - 1)) != 0)
    return static_cast<std::int64_t>(u) - (std::int64_t{1} << (8 * bytes));
  return static_cast<std::int64_t>(u);
}

// A float or double of the given type at `at`, the caller has checked that the bytes are there.
double read_real(const char* at, const std::string& type, bool big_endian) {
  const int bytes = ply_type_bytes(type);
  unsigned char raw[8] = {};
  std::memcpy(raw, at, static_cast<std::size_t>(bytes));
  if (big_endian) std::reverse(raw, raw + bytes);  // every platform we build for is little-endian
  if (bytes == 4) {
    float f = 0;
    std::memcpy(&f, raw, 4);
    return f;
  }
  double d = 0;
  std::memcpy(&d, raw, 8);
  return d;
}

// OpenMesh narrows every coordinate to float: a double beyond float range becomes infinite there (or,
// converted by other code, undefined), so it is refused here with the vertex named. The coordinates as
// written are kept for the loader, which restores them where the narrowing moved the model.
void check_coordinates(std::string_view body, bool big_endian, const std::vector<PlyProperty>& vertex,
                       std::uint64_t vertices, std::uint64_t vertex_bytes, double max_coordinate,
                       const std::string& name, std::vector<Vec3>* positions) {
  struct Axis {
    std::uint64_t offset = 0;  ///< in the record
    std::string type;
  };
  std::array<std::optional<Axis>, 3> axes;
  std::uint64_t offset = 0;
  for (const PlyProperty& p : vertex) {
    if (const int axis = ply_axis(p.name); axis >= 0)
      axes[static_cast<std::size_t>(axis)] = Axis{offset, p.type};
    offset += static_cast<std::uint64_t>(ply_type_bytes(p.type));
  }
  if (positions) positions->reserve(positions->size() + vertices);
  for (std::uint64_t v = 0; v < vertices; ++v) {
    double xyz[3] = {0, 0, 0};
    for (std::size_t i = 0; i < axes.size(); ++i) {
      if (!axes[i]) continue;
      const char* at = body.data() + v * vertex_bytes + axes[i]->offset;
      const std::string& type = axes[i]->type;
      xyz[i] = ply_integer_type(type) ? static_cast<double>(read_integer(at, type, big_endian))
                                      : read_real(at, type, big_endian);
      if (!std::isfinite(xyz[i]))
        throw InputError(name, "vertex " + std::to_string(v + 1) + " has a non-finite coordinate");
      if (std::fabs(xyz[i]) > max_coordinate)
        throw InputError(name, "vertex " + std::to_string(v + 1) + ": coordinate out of range");
    }
    if (positions) positions->push_back({xyz[0], xyz[1], xyz[2]});
  }
}

}  // namespace

int ply_axis(const std::string& name) {
  return name.size() == 1 && name[0] >= 'x' && name[0] <= 'z' ? name[0] - 'x' : -1;
}

bool ply_integer_type(const std::string& type) {
  return ply_type_bytes(type) > 0 && type != "float" && type != "float32" && type != "double" &&
         type != "float64";
}

int ply_type_bytes(const std::string& type) {
  if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
  if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
  if (type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" ||
      type == "float32")
    return 4;
  if (type == "double" || type == "float64") return 8;
  return 0;
}

void check_binary_ply_body(std::string_view body, bool big_endian, const std::vector<PlyProperty>& vertex,
                           std::uint64_t vertices, const std::vector<PlyProperty>& face, std::uint64_t faces,
                           double max_coordinate, const std::string& name, std::vector<Vec3>* positions) {
  std::uint64_t vertex_bytes = 0;
  for (const PlyProperty& p : vertex)
    vertex_bytes += static_cast<std::uint64_t>(ply_type_bytes(p.type));
  const std::uint64_t size = body.size();
  if (vertices * vertex_bytes > size)
    throw InputError(name, "truncated file: the header declares " + std::to_string(vertices) +
                               " vertices of " + std::to_string(vertex_bytes) + " bytes, the body has " +
                               std::to_string(size) + " bytes");
  check_coordinates(body, big_endian, vertex, vertices, vertex_bytes, max_coordinate, name, positions);
  std::uint64_t at = vertices * vertex_bytes;
  const auto truncated = [&](std::uint64_t f) {
    return InputError(name, "truncated file: face " + std::to_string(f + 1) + " of " + std::to_string(faces) +
                                " runs past the end of the file");
  };
  for (std::uint64_t f = 0; f < faces; ++f) {
    for (const PlyProperty& p : face) {
      const auto bytes = static_cast<std::uint64_t>(ply_type_bytes(p.type));
      if (p.count_type.empty()) {
        if (size - at < bytes) throw truncated(f);
        at += bytes;
        continue;
      }
      const auto count_bytes = static_cast<std::uint64_t>(ply_type_bytes(p.count_type));
      if (size - at < count_bytes) throw truncated(f);
      const std::int64_t count = read_integer(body.data() + at, p.count_type, big_endian);
      at += count_bytes;
      if (count < 3)
        throw InputError(name, "face " + std::to_string(f + 1) + " has " + std::to_string(count) +
                                   " vertices (at least 3 needed)");
      // Checked before multiplying: a count near 2^31 must not wrap around.
      if (static_cast<std::uint64_t>(count) > (size - at) / bytes)
        throw InputError(name, "face " + std::to_string(f + 1) + " declares " + std::to_string(count) +
                                   " vertices, more than the rest of the file can hold");
      for (std::int64_t k = 0; k < count; ++k, at += bytes) {
        const std::int64_t index = read_integer(body.data() + at, p.type, big_endian);
        if (index < 0 || static_cast<std::uint64_t>(index) >= vertices)
          throw InputError(name, "face " + std::to_string(f + 1) + " references vertex " +
                                     std::to_string(index + 1) + " (only " + std::to_string(vertices) +
                                     " vertices)");
      }
    }
  }
}

}  // namespace foldkit::unfold::detail
