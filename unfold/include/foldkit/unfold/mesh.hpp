#pragma once
// The triangle mesh every stage works on: a value type with its own edge connectivity, so that no
// OpenMesh type escapes unfold/.
#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "foldkit/geom/colour.hpp"
#include "foldkit/geom/vec.hpp"
#include "foldkit/unfold/ids.hpp"

namespace foldkit::unfold {

/// An undirected mesh edge between vertices v[0] < v[1]. face[0] traverses it v[0]->v[1] or v[1]->v[0]
/// as `corner[0]` says; face[1] is -1 on a boundary edge (an open mesh's border is already cut).
struct MeshEdge {
  std::array<int, 2> v{-1, -1};
  std::array<int, 2> face{-1, -1};
  /// corner[k]: index i in 0..2 such that the edge is faces[face[k]][i] -> faces[face[k]][(i+1)%3].
  std::array<int, 2> corner{-1, -1};
  bool boundary() const { return face[1] < 0; }
  /// face[k] and v[k] as typed ids.
  FaceId face_id(int k) const { return FaceId(face[k]); }
  VertexId vertex_id(int k) const { return VertexId(v[k]); }
};

/// What faces are printed with: a flat colour, times a texture image when there is one.
struct Material {
  std::string name;  ///< as the file names it (usemtl, glTF material), or made up from the colour
  Colour colour;     ///< OBJ Kd, glTF baseColorFactor, PLY face colour
  /// Image file (OBJ map_Kd resolved against the MTL's folder, glTF baseColorTexture); empty for none.
  std::string texture;
  /// The encoded image (PNG, JPEG) when the file embeds it (.glb, data: URIs); `texture` then names it.
  std::vector<unsigned char> texture_data;
  /// The image exists and its header reads; when false the faces print in `colour` alone.
  bool texture_found = false;
  int texture_width_px = 0, texture_height_px = 0;
};

/// A consistently oriented, edge- and vertex-manifold triangle mesh (validated by `make_mesh`).
struct Mesh {
  std::vector<Vec3> vertices;
  /// Counter-clockwise seen from outside for closed meshes.
  std::vector<std::array<int, 3>> faces;
  std::vector<MeshEdge> edges;
  /// face_edges[f][i] is the edge faces[f][i] -> faces[f][(i+1)%3].
  std::vector<std::array<int, 3>> face_edges;
  /// Per face, the texture coordinates of its three corners (u right, v up, image is [0,1]^2); empty
  /// when the file has none.
  std::vector<std::array<Vec2, 3>> face_uv;
  /// Per face, an index into `materials` (-1: none, printed white); empty when the file has no colours.
  std::vector<int> face_material;
  std::vector<Material> materials;
  /// Where the mesh came from (file name), for messages.
  std::string name;
  /// face_polygon[f]: the 0-based index of the input file's face (polygon) triangle f came from. Empty
  /// when every triangle is a face of its own (a mesh built in code, or decimated).
  std::vector<int> face_polygon;

  int num_faces() const { return static_cast<int>(faces.size()); }
  int num_vertices() const { return static_cast<int>(vertices.size()); }
  int num_edges() const { return static_cast<int>(edges.size()); }
  /// Typed access (the plain vectors above stay for the readers and for layout).
  const MeshEdge& edge(EdgeId e) const { return edges[e.index()]; }
  std::array<EdgeId, 3> edges_of(FaceId f) const {
    const auto& fe = face_edges[f.index()];
    return {EdgeId(fe[0]), EdgeId(fe[1]), EdgeId(fe[2])};
  }
  /// The input file's face that triangle f came from (f itself when face_polygon is empty).
  int polygon_of(int f) const { return face_polygon.empty() ? f : face_polygon[f]; }
  /// Corner positions of face f.
  std::array<Vec3, 3> corners(int f) const {
    return {vertices[faces[f][0]], vertices[faces[f][1]], vertices[faces[f][2]]};
  }
};

/// Builds edges and face_edges from vertices and faces and checks the mesh: indices in range,
/// finite coordinates, every edge in at most two faces traversed in opposite directions, every
/// vertex a single fan. Throws InputError(name, problem) otherwise.
Mesh make_mesh(std::vector<Vec3> vertices, std::vector<std::array<int, 3>> faces, std::string name);

/// The mesh's axis-aligned bounding box, model units (both corners 0 without vertices).
struct MeshBounds {
  Vec3 lo, hi;
  /// The largest of its three sides: the model's size that --size sets.
  double largest_dimension() const { return std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z}); }
};
MeshBounds bounds_of(const Mesh& mesh);

/// Length of edge e in model units.
double edge_length(const Mesh& mesh, int e);
/// Unit normal of face f.
Vec3 face_normal(const Mesh& mesh, int f);
/// Area of face f.
double face_area(const Mesh& mesh, int f);

/// Signed dihedral (fold) angle of edge e in radians, in (-pi, pi): 0 for coplanar faces, positive
/// where the surface is convex (a mountain fold seen from the printed outside), negative where
/// concave (a valley fold). 0 for boundary edges.
double fold_angle(const Mesh& mesh, int e);

}  // namespace foldkit::unfold
