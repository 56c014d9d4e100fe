#pragma once
// Reading meshes from OBJ, OFF, STL (ASCII and binary) and PLY files.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "foldkit/unfold/mesh.hpp"

namespace foldkit::unfold {

struct LoadOptions {
  /// Decimate with OpenMesh's quadric decimater to at most this many faces first (the seed's
  /// preprocessing). nullopt: keep every face.
  std::optional<int> max_faces;
  /// Files larger than this are refused before reading: no paper model needs a gigabyte of mesh, and a
  /// hostile file should not exhaust memory.
  std::uintmax_t max_file_bytes = std::uintmax_t{1} << 30;
  /// Meshes with more (triangulated) faces are refused before any repair work: far beyond anything that
  /// can be folded, and the unfolders' cost grows faster than linearly. Decimate offline first.
  int face_limit = 2'000'000;
};

/// A loaded mesh plus what the loader changed or noticed, for the user to read.
struct LoadedMesh {
  Mesh mesh;
  /// One line each, e.g. "welded 1,204 coincident vertices", "triangulated 12 quads and 2 n-gons",
  /// "collapsed 3 zero-area faces", "3 connected components: unfolded separately".
  std::vector<std::string> notes;
  int original_faces = 0;  ///< faces in the file, before triangulation and decimation
};

/// Reads and validates a mesh file. Throws InputError naming the file and the problem (missing,
/// empty, truncated, unparsable, non-finite coordinates, non-manifold, non-orientable, zero-area
/// faces that cannot be collapsed safely, unsupported extension, over the size limits).
LoadedMesh load_mesh(const std::filesystem::path& path, const LoadOptions& options = {});

}  // namespace foldkit::unfold
