#pragma once
// Discrete Gaussian curvature of a mesh at its vertices: the angle defect, and the classes the
// unfolders reason about (elliptic vertices unfold easily, hyperbolic ones are where overlaps start).
#include <vector>

#include "foldkit/unfold/mesh.hpp"

namespace foldkit::unfold {

/// Sum of the corner angles (radians) of the faces around each vertex, indexed by vertex.
std::vector<double> angle_sums(const Mesh& mesh);

/// Angle defect per vertex in radians: 2*pi - sum for interior vertices, pi - sum for boundary vertices.
/// Their total is 2*pi times the Euler characteristic (Gauss-Bonnet).
std::vector<double> angle_defects(const Mesh& mesh);

/// Curvature class of a vertex by the sign of its angle defect.
enum class VertexClass {
  Elliptic,    ///< interior, defect > tolerance (a cone point: the star flattens with a gap)
  Hyperbolic,  ///< interior, defect < -tolerance (a saddle: the star flattens only by overlapping)
  Flat,        ///< interior, |defect| <= tolerance
  Boundary,    ///< on an open boundary (already cut)
};

/// Classifies each vertex; |defect| <= flat_tolerance_rad counts as flat.
std::vector<VertexClass> classify_vertices(const Mesh& mesh, double flat_tolerance_rad = 1e-6);

/// True for vertices on a boundary edge, indexed by vertex.
std::vector<bool> boundary_vertices(const Mesh& mesh);

}  // namespace foldkit::unfold
