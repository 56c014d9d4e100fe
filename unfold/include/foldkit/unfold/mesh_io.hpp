#pragma once
// Reading meshes from OBJ, OFF, STL (ASCII and binary) and PLY files.
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
/// faces that cannot be collapsed safely, unsupported extension).
LoadedMesh load_mesh(const std::filesystem::path& path, const LoadOptions& options = {});

}  // namespace foldkit::unfold
