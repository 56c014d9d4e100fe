#pragma once
// Topological and geometric summary of a mesh, for `foldkit inspect` and for tests.
#include <vector>

#include "foldkit/unfold/mesh.hpp"

namespace foldkit::unfold {

/// Topology of one connected component.
struct ComponentStats {
  int faces = 0, vertices = 0, edges = 0;
  int boundary_loops = 0;
  int euler_characteristic = 0;  ///< V - E + F
  int genus = 0;                 ///< (2 - chi - boundary_loops) / 2: handles of the closed-up surface
  bool closed = false;
};

/// What `foldkit inspect` reports.
struct MeshStats {
  int faces = 0, vertices = 0, edges = 0;
  int boundary_edges = 0;
  int boundary_loops = 0;
  int components = 0;
  int genus = 0;  ///< sum over components
  int euler_characteristic = 0;
  bool closed = false;     ///< no boundary edge
  bool orientable = true;  ///< always true for a Mesh (make_mesh refuses the others), kept for the report
  int elliptic_vertices = 0, hyperbolic_vertices = 0, flat_vertices = 0, boundary_vertices = 0;
  Vec3 bbox_min{}, bbox_max{};
  double surface_area = 0;
  std::vector<ComponentStats> per_component;
};

/// Computes the summary; curvature classes use classify_vertices with `flat_tolerance_rad`.
MeshStats compute_mesh_stats(const Mesh& mesh, double flat_tolerance_rad = 1e-6);

/// Connected component of each face (faces joined across shared edges), numbered from 0 in face order.
std::vector<int> face_components(const Mesh& mesh);

}  // namespace foldkit::unfold
