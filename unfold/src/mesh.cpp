// make_mesh builds edge connectivity with a hash map keyed by vertex pair and checks manifoldness with a
// union-find over face corners (two corners of one vertex join when the faces share an edge through it).
#include "foldkit/unfold/mesh.hpp"

#include <cmath>
#include <cstdint>
#include <numeric>
#include <unordered_map>

#include "foldkit/error.hpp"
#include "foldkit/unfold/disjoint_sets.hpp"

namespace foldkit::unfold {
namespace {

std::uint64_t edge_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

// 1-based numbers in messages, as in the OBJ/OFF files users look at.
std::string vnum(int v) {
  return std::to_string(v + 1);
}

// Finite coordinates; faces with three distinct vertices in range.
void check_vertices_and_faces(const Mesh& mesh) {
  const int nv = mesh.num_vertices();
  for (int v = 0; v < nv; ++v) {
    const Vec3 p = mesh.vertices[v];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw InputError(mesh.name, "vertex " + vnum(v) + " has a non-finite coordinate");
  }
  for (int f = 0; f < mesh.num_faces(); ++f) {
    const auto& t = mesh.faces[f];
    for (int i = 0; i < 3; ++i)
      if (t[i] < 0 || t[i] >= nv)
        throw InputError(mesh.name, "face " + std::to_string(f + 1) + " references vertex " +
                                        std::to_string(t[i] + 1) + " (only " + std::to_string(nv) +
                                        " vertices)");
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
      throw InputError(mesh.name, "face " + std::to_string(f + 1) + " uses a vertex twice");
  }
}

// Builds mesh.edges and mesh.face_edges; every edge in at most two faces, traversed in opposite
// directions.
void build_edges(Mesh& mesh) {
  const int nf = mesh.num_faces();
  std::unordered_map<std::uint64_t, int> edge_of;
  edge_of.reserve(static_cast<std::size_t>(nf) * 2);
  mesh.face_edges.assign(nf, {-1, -1, -1});
  for (int f = 0; f < nf; ++f) {
    for (int i = 0; i < 3; ++i) {
      const int a = mesh.faces[f][i], b = mesh.faces[f][(i + 1) % 3];
      auto [it, inserted] = edge_of.try_emplace(edge_key(a, b), mesh.num_edges());
      if (inserted) {
        MeshEdge e;
        e.v = {std::min(a, b), std::max(a, b)};
        e.face[0] = f;
        e.corner[0] = i;
        mesh.edges.push_back(e);
      } else {
        MeshEdge& e = mesh.edges[it->second];
        if (e.face[1] >= 0)
          throw InputError(mesh.name, "non-manifold edge between vertices " + vnum(e.v[0]) + " and " +
                                          vnum(e.v[1]) + " (more than two faces)");
        const auto& other = mesh.faces[e.face[0]];
        if (other[e.corner[0]] == a)
          throw InputError(mesh.name, "inconsistent face orientation at the edge between vertices " +
                                          vnum(e.v[0]) + " and " + vnum(e.v[1]));
        e.face[1] = f;
        e.corner[1] = i;
      }
      mesh.face_edges[f][i] = it->second;
    }
  }
}

// Every vertex in some face, and its faces one fan. Corner c = 3f+i; corners of one vertex in faces
// adjacent across an edge through it join one fan.
void check_vertex_fans(const Mesh& mesh) {
  const int nv = mesh.num_vertices(), nf = mesh.num_faces();
  DisjointSets fans(3 * nf);
  for (const MeshEdge& e : mesh.edges) {
    if (e.boundary()) continue;
    for (int k = 0; k < 2; ++k) {
      const int v = e.v[k];
      int c[2];
      for (int s = 0; s < 2; ++s) {
        const auto& t = mesh.faces[e.face[s]];
        const int i = t[0] == v ? 0 : t[1] == v ? 1 : 2;
        c[s] = 3 * e.face[s] + i;
      }
      fans.join(c[0], c[1]);
    }
  }
  std::vector<int> fan_of_vertex(nv, -1);
  for (int c = 0; c < 3 * nf; ++c) {
    const int v = mesh.faces[c / 3][c % 3];
    const int r = fans.find(c);
    if (fan_of_vertex[v] < 0) {
      fan_of_vertex[v] = r;
    } else if (fan_of_vertex[v] != r) {
      throw InputError(mesh.name, "non-manifold vertex " + vnum(v) + " (its faces form several fans)");
    }
  }
  for (int v = 0; v < nv; ++v)
    if (fan_of_vertex[v] < 0) throw InputError(mesh.name, "vertex " + vnum(v) + " belongs to no face");
}

}  // namespace

Mesh make_mesh(std::vector<Vec3> vertices, std::vector<std::array<int, 3>> faces, std::string name) {
  Mesh mesh;
  mesh.vertices = std::move(vertices);
  mesh.faces = std::move(faces);
  mesh.name = std::move(name);
  check_vertices_and_faces(mesh);
  build_edges(mesh);
  check_vertex_fans(mesh);
  return mesh;
}

double edge_length(const Mesh& mesh, int e) {
  const MeshEdge& edge = mesh.edges[e];
  return norm(mesh.vertices[edge.v[1]] - mesh.vertices[edge.v[0]]);
}

Vec3 face_normal(const Mesh& mesh, int f) {
  const auto c = mesh.corners(f);
  return normalized(cross(c[1] - c[0], c[2] - c[0]));
}

MeshBounds bounds_of(const Mesh& mesh) {
  if (mesh.vertices.empty()) return {};
  MeshBounds b{mesh.vertices.front(), mesh.vertices.front()};
  for (const Vec3& p : mesh.vertices) {
    b.lo = {std::min(b.lo.x, p.x), std::min(b.lo.y, p.y), std::min(b.lo.z, p.z)};
    b.hi = {std::max(b.hi.x, p.x), std::max(b.hi.y, p.y), std::max(b.hi.z, p.z)};
  }
  return b;
}

double face_area(const Mesh& mesh, int f) {
  const auto c = mesh.corners(f);
  return 0.5 * norm(cross(c[1] - c[0], c[2] - c[0]));
}

double fold_angle(const Mesh& mesh, int e) {
  const MeshEdge& edge = mesh.edges[e];
  if (edge.boundary()) return 0.0;
  const Vec3 n0 = face_normal(mesh, edge.face[0]);
  const Vec3 n1 = face_normal(mesh, edge.face[1]);
  // The edge direction as face 0 traverses it: with outward CCW normals, n0 x n1 points along it
  // where the surface is convex, against it where concave.
  const auto& t0 = mesh.faces[edge.face[0]];
  const Vec3 a = mesh.vertices[t0[edge.corner[0]]];
  const Vec3 b = mesh.vertices[t0[(edge.corner[0] + 1) % 3]];
  const Vec3 dir = normalized(b - a);
  const double sin_angle = dot(cross(n0, n1), dir);
  const double cos_angle = dot(n0, n1);
  return std::atan2(sin_angle, cos_angle);
}

}  // namespace foldkit::unfold
