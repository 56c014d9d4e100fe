// Flat faces: planar polygons of the file and runs of coplanar triangles are units no unfolder cuts.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <set>
#include <string>

#include "foldkit/unfold/flat_faces.hpp"
#include "foldkit/unfold/mesh_io.hpp"
#include "foldkit/unfold/unfold.hpp"
#include "test_paths.hpp"

using namespace foldkit;
using namespace foldkit::unfold;

namespace {

const char* const kLowPoly[] = {
    "barn.obj", "drum.obj",       "football.obj",    "l_block.obj", "rhombicuboctahedron.obj",
    "cube.obj", "cylinder12.obj", "dodecahedron.obj"};

std::filesystem::path lowpoly(const std::string& name) {
  return test::source_dir() / "tests" / "data" / "lowpoly" / name;
}

int file_faces(const std::filesystem::path& path) {
  std::ifstream in(path);
  int n = 0;
  for (std::string line; std::getline(in, line);)
    n += line.rfind("f ", 0) == 0;
  return n;
}

}  // namespace

TEST(FlatFaces, EveryTriangleKnowsTheFileFaceItCameFrom) {
  const LoadedMesh barn = load_mesh(lowpoly("barn.obj"));
  ASSERT_EQ(barn.mesh.face_polygon.size(), barn.mesh.faces.size());
  std::set<int> seen(barn.mesh.face_polygon.begin(), barn.mesh.face_polygon.end());
  EXPECT_EQ(static_cast<int>(seen.size()), file_faces(lowpoly("barn.obj")));
  EXPECT_EQ(*seen.begin(), 0);
  EXPECT_EQ(*seen.rbegin(), file_faces(lowpoly("barn.obj")) - 1);
}

TEST(FlatFaces, EachPlanarPolygonOfALowPolyModelIsOneFlatFace) {
  for (const char* name : kLowPoly) {
    const Mesh mesh = load_mesh(lowpoly(name)).mesh;
    const FlatFaces flat = find_flat_faces(mesh);
    EXPECT_EQ(flat.unit_count, file_faces(lowpoly(name))) << name;
    EXPECT_EQ(flat.non_planar_polygons, 0) << name;
    for (int f = 0; f < mesh.num_faces(); ++f)
      for (int g = 0; g < mesh.num_faces(); ++g)
        if (mesh.polygon_of(f) == mesh.polygon_of(g)) {
          EXPECT_EQ(flat.face_unit[f], flat.face_unit[g]) << name;
        }
  }
}

TEST(FlatFaces, NoUnfolderCutsInsideAFlatFace) {
  for (const char* name : kLowPoly)
    for (Method method : {Method::Mst, Method::Search, Method::Ga}) {
      const Mesh mesh = load_mesh(lowpoly(name)).mesh;
      UnfoldOptions options;
      options.method = method;
      options.threads = 1;
      options.time_limit_s = 20;
      const UnfoldResult r = unfold_mesh(mesh, options);
      EXPECT_TRUE(check_unfolding(mesh, r.unfolding).empty()) << name;
      const FlatFaces flat = find_flat_faces(mesh);
      for (int e = 0; e < mesh.num_edges(); ++e)
        if (flat.inside[e]) {
          EXPECT_FALSE(r.unfolding.edges[e].cut) << name << " method " << r.method << " edge " << e;
          EXPECT_TRUE(r.unfolding.edges[e].inside_face) << name;
        }
    }
}

TEST(FlatFaces, CoplanarTrianglesOfATriangulatedFileJoinIntoOneFace) {
  // A cube given as 12 triangles (two per side): 6 flat faces.
  std::vector<Vec3> v;
  for (int i = 0; i < 8; ++i)
    v.push_back({double(i >> 2 & 1), double(i >> 1 & 1), double(i & 1)});
  std::vector<std::array<int, 3>> f = {{0, 1, 3}, {0, 3, 2}, {4, 6, 7}, {4, 7, 5}, {0, 4, 5}, {0, 5, 1},
                                       {2, 3, 7}, {2, 7, 6}, {0, 2, 6}, {0, 6, 4}, {1, 5, 7}, {1, 7, 3}};
  const Mesh cube = make_mesh(v, f, "cube");
  const FlatFaces flat = find_flat_faces(cube);
  EXPECT_EQ(flat.unit_count, 6);
  EXPECT_EQ(std::count(flat.inside.begin(), flat.inside.end(), true), 6);
}

TEST(FlatFaces, APolygonBentBeyondTheFlatAngleFoldsAndOneWithinItDoesNot) {
  // A square bent along its diagonal by a small angle, closed by a tetrahedron-like cap is not needed:
  // an open mesh is enough.
  auto bent = [](double lift) {
    std::vector<Vec3> v = {{0, 0, 0}, {1, 0, 0}, {1, 1, lift}, {0, 1, 0}};
    Mesh m = make_mesh(v, {{0, 1, 3}, {1, 2, 3}}, "quad");
    m.face_polygon = {0, 0};
    return m;
  };
  const double deg = std::numbers::pi / 180;
  EXPECT_EQ(find_flat_faces(bent(std::tan(0.2 * deg)), 0.5 * deg).unit_count, 1);
  const FlatFaces folded = find_flat_faces(bent(std::tan(5 * deg)), 0.5 * deg);
  EXPECT_EQ(folded.unit_count, 2);
  EXPECT_EQ(folded.non_planar_polygons, 1);
  EXPECT_EQ(find_flat_faces(bent(std::tan(5 * deg)), 10 * deg).unit_count, 1);
}

TEST(FlatFaces, AFlatFaceStaysATreeOfTrianglesAroundAnInnerVertex) {
  // A flat hexagon fanned around its centre: six coplanar triangles around one vertex cannot all fold
  // together, so one edge stays between two flat faces.
  std::vector<Vec3> v = {{0, 0, 0}};
  std::vector<std::array<int, 3>> f;
  for (int k = 0; k < 6; ++k) {
    const double a = k * std::numbers::pi / 3;
    v.push_back({std::cos(a), std::sin(a), 0});
    f.push_back({0, 1 + k, 1 + (k + 1) % 6});
  }
  const FlatFaces flat = find_flat_faces(make_mesh(v, f, "hexagon"));
  const long inside = std::count(flat.inside.begin(), flat.inside.end(), true);
  EXPECT_EQ(inside, 6 - flat.unit_count);
  EXPECT_EQ(flat.unit_count, 2);
}
