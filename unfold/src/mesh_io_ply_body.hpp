#pragma once
// Internal to unfold/: the body of a binary PLY file checked against its header before OpenMesh reads
// it. OpenMesh trusts every list count it reads, so one hostile count makes it read billions of indices
// past the end of the file into a growing vector.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "foldkit/geom/vec.hpp"

namespace foldkit::unfold::detail {

/// One property of a PLY element as its header declares it.
struct PlyProperty {
  std::string type;        ///< scalar type, or the index type of a list
  std::string count_type;  ///< the list's count type; empty for a scalar
  std::string name;        ///< "x", "vertex_indices", …
};

/// Byte size of a PLY scalar type name ("uchar", "float32", …); 0 for an unknown name.
int ply_type_bytes(const std::string& type);

/// 0, 1 or 2 for a vertex property named x, y or z; -1 for any other.
int ply_axis(const std::string& name);

/// True for the integer types, the only ones a list count or a vertex index may have.
bool ply_integer_type(const std::string& type);

/// Walks the binary body (the bytes after the end_header line): `vertices` records of `vertex` whose x,
/// y and z are finite and within `max_coordinate`, then `faces` records of `face` whose list holds 3 or
/// more indices below `vertices`. Throws InputError(name, …) naming the first vertex or face that is
/// malformed or runs past the end of the file. Appends each vertex's x, y and z, as written, to
/// `positions` when given.
void check_binary_ply_body(std::string_view body, bool big_endian, const std::vector<PlyProperty>& vertex,
                           std::uint64_t vertices, const std::vector<PlyProperty>& face, std::uint64_t faces,
                           double max_coordinate, const std::string& name,
                           std::vector<Vec3>* positions = nullptr);

}  // namespace foldkit::unfold::detail
