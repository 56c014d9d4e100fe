#pragma once
// Reading meshes from OBJ, OFF, STL (ASCII and binary) and PLY files.
#include <array>
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

/// Two vertices of the mesh file named together as an edge (a seam), 0-based in the file's vertex order.
struct FileEdge {
  std::array<int, 2> v{};
  int line = 0;  ///< the line that named it (1-based), for messages
};

/// How the file's vertices became the mesh's, so that edges can be named by the file's own numbers:
/// welding merges file vertices, zero-area repair collapses edges, pinched vertices are split and unused
/// ones dropped. Empty after decimation, which keeps no vertex of the file.
struct VertexOrigin {
  /// Per mesh vertex: the file vertex (0-based) it stands for.
  std::vector<int> file_vertex;
  /// Per file vertex: the file vertex it was merged into by welding or repair (itself if none).
  std::vector<int> merged_into;
  /// The edges of the file's polygons as (smaller, larger) file vertex pairs, sorted.
  std::vector<std::array<int, 2>> file_edges;
};

/// A loaded mesh plus what the loader changed or noticed, for the user to read.
struct LoadedMesh {
  Mesh mesh;
  /// One line each, e.g. "welded 1,204 coincident vertices", "collapsed 3 zero-area faces", "3 connected
  /// components: unfolded separately". Quads and n-gons are split into triangles without a note: the
  /// unfolding keeps every flat one whole (flat_faces.hpp) and notes those that are not flat.
  std::vector<std::string> notes;
  int original_faces = 0;  ///< faces in the file, before triangulation and decimation
  int file_quads = 0;      ///< faces of the file with four corners
  int file_ngons = 0;      ///< faces of the file with more than four corners
  VertexOrigin origin;
  /// Seams the file marks itself (OBJ `l` elements), one per segment of each line element.
  std::vector<FileEdge> file_seams;
  /// The number of the first vertex in the file's own face lists: 1 for OBJ, 0 for OFF, PLY and glTF; STL,
  /// which has no vertex numbers, counts its distinct corners from 1 in the order they appear.
  int index_base = 1;
};

/// Reads and validates a mesh file. Throws InputError naming the file and the problem (missing,
/// empty, truncated, unparsable, non-finite coordinates, non-manifold, non-orientable, zero-area
/// faces that cannot be collapsed safely, unsupported extension, over the size limits).
LoadedMesh load_mesh(const std::filesystem::path& path, const LoadOptions& options = {});

}  // namespace foldkit::unfold
