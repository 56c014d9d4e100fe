// Boundary loops are counted by walking boundary edges tail to head: in a vertex-manifold mesh each
// boundary vertex has exactly one outgoing boundary edge, so the walk is a permutation of cycles.
#include "foldkit/unfold/mesh_stats.hpp"

#include <algorithm>
#include <cmath>

#include "foldkit/unfold/curvature.hpp"

namespace foldkit::unfold {

std::vector<int> face_components(const Mesh& mesh) {
  std::vector<int> comp(mesh.faces.size(), -1);
  std::vector<int> stack;
  int next = 0;
  for (int seed = 0; seed < mesh.num_faces(); ++seed) {
    if (comp[seed] >= 0) continue;
    comp[seed] = next;
    stack.assign(1, seed);
    while (!stack.empty()) {
      const int f = stack.back();
      stack.pop_back();
      for (int e : mesh.face_edges[f]) {
        const MeshEdge& edge = mesh.edges[e];
        const int g = edge.face[0] == f ? edge.face[1] : edge.face[0];
        if (g >= 0 && comp[g] < 0) {
          comp[g] = next;
          stack.push_back(g);
        }
      }
    }
    ++next;
  }
  return comp;
}

MeshStats compute_mesh_stats(const Mesh& mesh, double flat_tolerance_rad) {
  MeshStats s;
  s.faces = mesh.num_faces();
  s.vertices = mesh.num_vertices();
  s.edges = mesh.num_edges();
  const std::vector<int> comp = face_components(mesh);
  s.components = comp.empty() ? 0 : *std::max_element(comp.begin(), comp.end()) + 1;
  s.per_component.resize(s.components);
  std::vector<int> vertex_comp(mesh.vertices.size(), -1);
  for (int f = 0; f < s.faces; ++f) {
    s.per_component[comp[f]].faces++;
    for (int v : mesh.faces[f])
      vertex_comp[v] = comp[f];
  }
  for (int c : vertex_comp)
    if (c >= 0) s.per_component[c].vertices++;

  // Each boundary edge as its face traverses it: tail -> head.
  std::vector<int> next_on_boundary(mesh.vertices.size(), -1);
  for (const MeshEdge& e : mesh.edges) {
    const int c = comp[e.face[0]];
    s.per_component[c].edges++;
    if (!e.boundary()) continue;
    ++s.boundary_edges;
    const auto& t = mesh.faces[e.face[0]];
    next_on_boundary[t[e.corner[0]]] = t[(e.corner[0] + 1) % 3];
  }
  std::vector<char> seen(mesh.vertices.size(), 0);
  for (int v = 0; v < s.vertices; ++v) {
    if (next_on_boundary[v] < 0 || seen[v]) continue;
    s.per_component[vertex_comp[v]].boundary_loops++;
    for (int w = v; w >= 0 && !seen[w]; w = next_on_boundary[w])
      seen[w] = 1;
  }
  for (ComponentStats& c : s.per_component) {
    c.euler_characteristic = c.vertices - c.edges + c.faces;
    c.genus = (2 - c.euler_characteristic - c.boundary_loops) / 2;
    c.closed = c.boundary_loops == 0;
    s.boundary_loops += c.boundary_loops;
    s.genus += c.genus;
    s.euler_characteristic += c.euler_characteristic;
  }
  s.closed = s.boundary_edges == 0;

  for (VertexClass k : classify_vertices(mesh, flat_tolerance_rad)) {
    switch (k) {
      case VertexClass::Elliptic:
        ++s.elliptic_vertices;
        break;
      case VertexClass::Hyperbolic:
        ++s.hyperbolic_vertices;
        break;
      case VertexClass::Flat:
        ++s.flat_vertices;
        break;
      case VertexClass::Boundary:
        ++s.boundary_vertices;
        break;
    }
  }
  if (!mesh.vertices.empty()) {
    s.bbox_min = s.bbox_max = mesh.vertices[0];
    for (const Vec3& p : mesh.vertices) {
      s.bbox_min = {std::min(s.bbox_min.x, p.x), std::min(s.bbox_min.y, p.y), std::min(s.bbox_min.z, p.z)};
      s.bbox_max = {std::max(s.bbox_max.x, p.x), std::max(s.bbox_max.y, p.y), std::max(s.bbox_max.z, p.z)};
    }
  }
  for (int f = 0; f < s.faces; ++f)
    s.surface_area += face_area(mesh, f);
  return s;
}

}  // namespace foldkit::unfold
