// OpenMesh's quadric decimater on a TriMesh copy; the result goes back through make_mesh so that the
// decimated mesh meets the same contract as a loaded one.
#include "foldkit/unfold/decimate.hpp"

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModNormalFlippingT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>

#include <vector>

namespace foldkit::unfold {
namespace {

struct Traits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using TriMesh = OpenMesh::TriMesh_ArrayKernelT<Traits>;

// Largest angle a collapse may turn a face normal by: beyond it the decimated surface starts to fold
// over itself, which no unfolding can make up for.
constexpr double kMaxNormalDeviationDeg = 60.0;

}  // namespace

Mesh decimate(const Mesh& mesh, int max_faces) {
  if (mesh.num_faces() <= max_faces || max_faces < 1) return mesh;
  TriMesh tri;
  std::vector<TriMesh::VertexHandle> handles;
  handles.reserve(mesh.vertices.size());
  for (const Vec3& p : mesh.vertices)
    handles.push_back(tri.add_vertex({p.x, p.y, p.z}));
  for (const auto& f : mesh.faces)
    tri.add_face(handles[f[0]], handles[f[1]], handles[f[2]]);

  OpenMesh::Decimater::DecimaterT<TriMesh> decimater(tri);
  OpenMesh::Decimater::ModQuadricT<TriMesh>::Handle quadric;
  OpenMesh::Decimater::ModNormalFlippingT<TriMesh>::Handle flipping;
  decimater.add(quadric);
  decimater.add(flipping);
  decimater.module(flipping).set_max_normal_deviation(kMaxNormalDeviationDeg);
  decimater.initialize();
  decimater.decimate_to_faces(0, static_cast<std::size_t>(max_faces));
  tri.garbage_collection();

  std::vector<Vec3> vertices;
  vertices.reserve(tri.n_vertices());
  for (auto v : tri.vertices()) {
    const auto& p = tri.point(v);
    vertices.push_back({p[0], p[1], p[2]});
  }
  std::vector<std::array<int, 3>> faces;
  faces.reserve(tri.n_faces());
  for (auto f : tri.faces()) {
    std::array<int, 3> t{};
    int i = 0;
    for (auto v : tri.fv_range(f))
      t[i++] = v.idx();
    faces.push_back(t);
  }
  return make_mesh(std::move(vertices), std::move(faces), mesh.name);
}

}  // namespace foldkit::unfold
