// OpenMesh's quadric decimater on a TriMesh copy; the result goes back through make_mesh so that the
// decimated mesh meets the same contract as a loaded one. Texture coordinates and materials ride along
// as face properties keyed by vertex (faces that survive a collapse keep their handles and properties,
// halfedges do not), and a module of our own allows only collapses that keep them meaningful.
#include "foldkit/unfold/decimate.hpp"

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModBaseT.hh>
#include <OpenMesh/Tools/Decimater/ModNormalFlippingT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>

#include <cmath>
#include <optional>
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

/// A face's texture coordinates by vertex, and its material.
struct FaceColour {
  std::array<int, 3> vertex{-1, -1, -1};
  std::array<Vec2, 3> uv{};
  int material = -1;
  Vec2 uv_at(int v) const {
    for (int i = 0; i < 3; ++i)
      if (vertex[i] == v) return uv[i];
    return {};
  }
  void move_corner(int from, int to, Vec2 new_uv) {
    for (int i = 0; i < 3; ++i)
      if (vertex[i] == from) {
        vertex[i] = to;
        uv[i] = new_uv;
      }
  }
};

double uv_area(const std::array<Vec2, 3>& t) {
  return 0.5 * cross(t[1] - t[0], t[2] - t[0]);
}

// Twice the UV area a face may shrink to before a collapse counts as folding its texture over: far below
// a texel of a 4096-pixel image.
constexpr double kMinUvArea = 1e-12;

/// Keeps texture seams and material borders: a collapse of v0 into v1 is allowed only when every face
/// around v0 finds v1's coordinates in its own chart (the same texture coordinates at v0 and the same
/// material as one of the two faces on the collapsing edge) and no face's texture turns over.
template <class MeshT>
class ModTextureSeamsT : public OpenMesh::Decimater::ModBaseT<MeshT> {
 public:
  DECIMATING_MODULE(ModTextureSeamsT, MeshT, TextureSeams);

  explicit ModTextureSeamsT(MeshT& mesh) : Base(mesh, true) {}

  void set_property(OpenMesh::FPropHandleT<FaceColour> prop) { prop_ = prop; }

  float collapse_priority(const CollapseInfo& ci) override {
    return moves(ci) ? float(Base::LEGAL_COLLAPSE) : float(Base::ILLEGAL_COLLAPSE);
  }

  void preprocess_collapse(const CollapseInfo& ci) override {
    const std::optional<std::vector<Move>> plan = moves(ci);
    if (!plan) return;  // not reached: the decimater only collapses what collapse_priority allowed
    for (const Move& m : *plan)
      Base::mesh().property(prop_, m.face).move_corner(ci.v0.idx(), ci.v1.idx(), m.uv);
  }

 private:
  struct Move {
    typename Mesh::FaceHandle face;
    Vec2 uv;
  };

  static bool same_chart(const FaceColour& a, const FaceColour& b, int v) {
    return a.material == b.material && a.uv_at(v) == b.uv_at(v);
  }

  // The new coordinates of v0's corner in each face that survives, or nullopt when the collapse would
  // tear a seam or turn a face's texture over.
  std::optional<std::vector<Move>> moves(const CollapseInfo& ci) {
    const Mesh& mesh = Base::mesh();
    const int v0 = ci.v0.idx(), v1 = ci.v1.idx();
    std::vector<const FaceColour*> edge_faces;
    for (auto f : {ci.fl, ci.fr})
      if (f.is_valid()) edge_faces.push_back(&mesh.property(prop_, f));
    std::vector<Move> out;
    for (auto f : mesh.vf_range(ci.v0)) {
      if (f == ci.fl || f == ci.fr) continue;
      const FaceColour& c = mesh.property(prop_, f);
      const FaceColour* chart = nullptr;
      for (const FaceColour* e : edge_faces)
        if (same_chart(*e, c, v0)) {
          if (chart && chart->uv_at(v1) != e->uv_at(v1)) return std::nullopt;  // the seam ends at v0
          chart = e;
        }
      if (!chart) return std::nullopt;  // v0's corner here is on another chart or material
      FaceColour after = c;
      after.move_corner(v0, v1, chart->uv_at(v1));
      const double before_area = uv_area(c.uv), after_area = uv_area(after.uv);
      if (std::abs(before_area) > kMinUvArea &&
          (after_area * before_area <= 0 || std::abs(after_area) <= kMinUvArea))
        return std::nullopt;
      out.push_back({f, chart->uv_at(v1)});
    }
    return out;
  }

  OpenMesh::FPropHandleT<FaceColour> prop_;
};

}  // namespace

Mesh decimate(const Mesh& mesh, int max_faces) {
  if (mesh.num_faces() <= max_faces || max_faces < 1) return mesh;
  const bool coloured = !mesh.face_uv.empty() || !mesh.face_material.empty();
  TriMesh tri;
  std::vector<TriMesh::VertexHandle> handles;
  handles.reserve(mesh.vertices.size());
  for (const Vec3& p : mesh.vertices)
    handles.push_back(tri.add_vertex({p.x, p.y, p.z}));
  OpenMesh::FPropHandleT<FaceColour> colour_prop;
  tri.add_property(colour_prop);
  for (int f = 0; f < mesh.num_faces(); ++f) {
    const auto& t = mesh.faces[f];
    const auto fh = tri.add_face(handles[t[0]], handles[t[1]], handles[t[2]]);
    FaceColour& c = tri.property(colour_prop, fh);
    c.vertex = t;
    if (!mesh.face_uv.empty()) c.uv = mesh.face_uv[f];
    if (!mesh.face_material.empty()) c.material = mesh.face_material[f];
  }

  OpenMesh::Decimater::DecimaterT<TriMesh> decimater(tri);
  OpenMesh::Decimater::ModQuadricT<TriMesh>::Handle quadric;
  OpenMesh::Decimater::ModNormalFlippingT<TriMesh>::Handle flipping;
  typename ModTextureSeamsT<TriMesh>::Handle seams;
  decimater.add(quadric);
  decimater.add(flipping);
  decimater.module(flipping).set_max_normal_deviation(kMaxNormalDeviationDeg);
  if (coloured) {
    decimater.add(seams);
    decimater.module(seams).set_property(colour_prop);
  }
  decimater.initialize();
  decimater.decimate_to_faces(0, static_cast<std::size_t>(max_faces));

  // Read out before garbage collection: the face property names vertices by their original numbers.
  std::vector<int> new_index(tri.n_vertices(), -1);
  std::vector<Vec3> vertices;
  for (auto v : tri.vertices()) {  // skips deleted vertices
    const auto& p = tri.point(v);
    new_index[v.idx()] = static_cast<int>(vertices.size());
    vertices.push_back({p[0], p[1], p[2]});
  }
  std::vector<std::array<int, 3>> faces;
  std::vector<std::array<Vec2, 3>> face_uv;
  std::vector<int> face_material;
  for (auto f : tri.faces()) {
    const FaceColour& c = tri.property(colour_prop, f);
    std::array<int, 3> t{};
    std::array<Vec2, 3> uv{};
    int i = 0;
    for (auto v : tri.fv_range(f)) {
      uv[i] = c.uv_at(v.idx());
      t[i++] = new_index[v.idx()];
    }
    faces.push_back(t);
    face_uv.push_back(uv);
    face_material.push_back(c.material);
  }
  Mesh out = make_mesh(std::move(vertices), std::move(faces), mesh.name);
  if (!mesh.face_uv.empty()) out.face_uv = std::move(face_uv);
  if (!mesh.face_material.empty()) out.face_material = std::move(face_material);
  out.materials = mesh.materials;
  return out;
}

}  // namespace foldkit::unfold
