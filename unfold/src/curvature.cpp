// Corner angles use atan2(|a x b|, a.b), which stays accurate for angles near 0 and pi where acos does not.
#include "foldkit/unfold/curvature.hpp"

#include <cmath>
#include <numbers>

namespace foldkit::unfold {

std::vector<double> angle_sums(const Mesh& mesh) {
  std::vector<double> sums(mesh.vertices.size(), 0.0);
  for (int f = 0; f < mesh.num_faces(); ++f) {
    const auto c = mesh.corners(f);
    for (int i = 0; i < 3; ++i) {
      const Vec3 a = c[(i + 1) % 3] - c[i];
      const Vec3 b = c[(i + 2) % 3] - c[i];
      sums[mesh.faces[f][i]] += std::atan2(norm(cross(a, b)), dot(a, b));
    }
  }
  return sums;
}

std::vector<bool> boundary_vertices(const Mesh& mesh) {
  std::vector<bool> on_boundary(mesh.vertices.size(), false);
  for (const MeshEdge& e : mesh.edges)
    if (e.boundary()) on_boundary[e.v[0]] = on_boundary[e.v[1]] = true;
  return on_boundary;
}

std::vector<double> angle_defects(const Mesh& mesh) {
  std::vector<double> defects = angle_sums(mesh);
  const std::vector<bool> on_boundary = boundary_vertices(mesh);
  for (std::size_t v = 0; v < defects.size(); ++v)
    defects[v] = (on_boundary[v] ? std::numbers::pi : 2 * std::numbers::pi) - defects[v];
  return defects;
}

std::vector<VertexClass> classify_vertices(const Mesh& mesh, double flat_tolerance_rad) {
  const std::vector<double> defects = angle_defects(mesh);
  const std::vector<bool> on_boundary = boundary_vertices(mesh);
  std::vector<VertexClass> classes(defects.size());
  for (std::size_t v = 0; v < defects.size(); ++v) {
    if (on_boundary[v]) {
      classes[v] = VertexClass::Boundary;
    } else if (defects[v] > flat_tolerance_rad) {
      classes[v] = VertexClass::Elliptic;
    } else if (defects[v] < -flat_tolerance_rad) {
      classes[v] = VertexClass::Hyperbolic;
    } else {
      classes[v] = VertexClass::Flat;
    }
  }
  return classes;
}

}  // namespace foldkit::unfold
