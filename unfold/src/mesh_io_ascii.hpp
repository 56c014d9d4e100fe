#pragma once
// Internal to unfold/: the checks every reader shares (declared counts against the file's size, the face
// limit, coordinates a float can hold) and the line-by-line reading of ASCII vertex and face blocks that
// OFF and ASCII PLY have in common. Messages name the vertex or face and the file's line.
#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "foldkit/geom/colour.hpp"
#include "foldkit/geom/vec.hpp"

namespace foldkit::unfold::detail {

/// OpenMesh's readers hold coordinates as float: a number beyond float range fails its stream
/// extraction and leaves the vertex uninitialised, so such a file is refused before it is read.
constexpr double kMaxCoordinate = std::numeric_limits<float>::max();

bool in_coordinate_range(double x);

/// Checked on the counts a file declares, before anything is read and before any repair: a file over
/// the limit fails in a fraction of a second rather than after minutes of work and gigabytes of memory.
void check_face_limit(std::uint64_t triangles, int face_limit, const std::string& name);

/// OFF and PLY headers announce counts; a file too short to hold them is truncated, and a reader would
/// otherwise loop on a failing stream or reserve for counts no file of this size can hold.
void check_declared_counts(std::uint64_t vertices, std::uint64_t faces, std::uint64_t min_bytes_per_vertex,
                           std::uint64_t min_bytes_per_face, std::size_t file_bytes, const std::string& name);

/// How an ASCII block is read.
struct AsciiBlockOptions {
  /// > 0: every vertex line has exactly that many numbers (PLY, whose reader takes tokens, not lines,
  /// so one extra number shifts everything after it).
  int exact_vertex_numbers = 0;
  /// Every face line holds its count and exactly that many indices (PLY faces with no property but the
  /// index list: an extra number would be read as the next face's count).
  bool exact_face_numbers = false;
  bool comments = false;  ///< `#` starts a comment to the end of the line (OFF)
  /// Which numbers of a vertex line are x, y and z: a PLY header may declare other properties first.
  std::array<int, 3> xyz_columns{0, 1, 2};
};

/// Reads `vertices` vertex lines from `pos` (blank lines and, for the vertex block, `#` lines skipped);
/// appends the numbers of each in `xyz_columns` to `positions` when given. Returns the position after the
/// block. Throws InputError(name, …) naming the vertex and line.
std::size_t read_ascii_vertex_block(const std::string& text, std::size_t pos, std::uint64_t vertices,
                                    const std::string& name, const AsciiBlockOptions& options,
                                    std::vector<Vec3>* positions = nullptr);

/// The faces of an ASCII block: polygons of 0-based indices and, per polygon, the colour written
/// after its indices (3 or 4 numbers: bytes, or floats in [0, 1]), if any.
struct AsciiFaces {
  std::vector<std::vector<int>> polygons;
  std::vector<std::optional<Colour>> colours;
};

/// Reads `faces` face lines from `pos`: a count of at least 3, then that many indices below `vertices`,
/// one face per line. OpenMesh's readers loop forever on some malformed face blocks, or take a huge
/// count on a line without indices as that many vertices to read from a failed stream (found by
/// fuzz_load_ply and fuzz_load_off), so this runs before them. Fills `out` when given.
void read_ascii_faces(const std::string& text, std::size_t pos, std::uint64_t faces, std::uint64_t vertices,
                      const std::string& name, const AsciiBlockOptions& options, AsciiFaces* out = nullptr);

}  // namespace foldkit::unfold::detail
