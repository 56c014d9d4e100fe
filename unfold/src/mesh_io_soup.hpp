#pragma once
// Internal to unfold/: the raw polygon soup a reader produces, and the repairs that turn it into a
// valid Mesh. Split from mesh_io.cpp so the repairs can be reasoned about without file formats.
#include <array>
#include <string>
#include <vector>

#include "foldkit/geom/vec.hpp"
#include "foldkit/unfold/mesh.hpp"
#include "foldkit/unfold/mesh_io.hpp"

namespace foldkit::unfold::detail {

/// Vertices and polygons exactly as the file holds them (indices 0-based, not yet checked).
struct PolygonSoup {
  std::vector<Vec3> vertices;
  std::vector<std::vector<int>> polygons;
  /// Per polygon, the texture coordinates of its corners (one per index of polygons[p]); empty when the
  /// file has none. A polygon without coordinates in a file that has some gets an empty list.
  std::vector<std::vector<Vec2>> polygon_uvs;
  /// Per polygon, an index into `materials`; empty when the file has no colours.
  std::vector<int> polygon_material;
  std::vector<Material> materials;
};

/// What to do to a soup; `weld_all` for formats without shared vertices (STL).
struct RepairOptions {
  bool weld_all = false;
};

/// A repaired mesh and how the soup's vertices became its vertices.
struct Repaired {
  Mesh mesh;
  VertexOrigin origin;
};

/// Validates and repairs a soup into a Mesh, appending one note per change made. Throws InputError(name,
/// ...).
Repaired repair_soup(PolygonSoup soup, const std::string& name, const RepairOptions& options,
                     std::vector<std::string>& notes);

/// Splits a simple polygon (given by 3D points, possibly non-planar or non-convex) into triangles of
/// indices into `points`, keeping its orientation; avoids slivers by clipping the fattest ear first.
std::vector<std::array<int, 3>> triangulate_polygon(const std::vector<Vec3>& points);

}  // namespace foldkit::unfold::detail
