// Angle sums, defects and vertex classes; Gauss-Bonnet on real meshes.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <numeric>

#include "foldkit/unfold/curvature.hpp"
#include "foldkit/unfold/mesh_io.hpp"
#include "foldkit/unfold/mesh_stats.hpp"
#include "test_paths.hpp"

using namespace foldkit;
using namespace foldkit::unfold;

namespace {

Mesh octahedron() {
  std::vector<Vec3> v{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  return make_mesh(v,
                   {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}},
                   "octahedron");
}

// A hexagonal fan around vertex 0 at the origin whose rim goes up and down by `wave`.
Mesh fan(double wave) {
  std::vector<Vec3> v{{0, 0, 0}};
  for (int i = 0; i < 6; ++i) {
    const double a = i * std::numbers::pi / 3;
    v.push_back({std::cos(a), std::sin(a), (i % 2 ? wave : -wave)});
  }
  std::vector<std::array<int, 3>> f;
  for (int i = 0; i < 6; ++i)
    f.push_back({0, 1 + i, 1 + (i + 1) % 6});
  return make_mesh(v, f, "fan");
}

double total_defect(const Mesh& m) {
  const auto d = angle_defects(m);
  return std::accumulate(d.begin(), d.end(), 0.0);
}

}  // namespace

TEST(AngleSums, EachOctahedronVertexSeesFourEquilateralCorners) {
  for (double s : angle_sums(octahedron()))
    EXPECT_NEAR(s, 4 * std::numbers::pi / 3, 1e-12);
}

TEST(AngleDefects, OctahedronVerticesAreAllElliptic) {
  Mesh m = octahedron();
  for (double d : angle_defects(m))
    EXPECT_NEAR(d, 2 * std::numbers::pi / 3, 1e-12);
  for (VertexClass c : classify_vertices(m))
    EXPECT_EQ(c, VertexClass::Elliptic);
}

TEST(ClassifyVertices, PlanarFanCentreIsFlatAndItsRimIsBoundary) {
  Mesh m = fan(0.0);
  const auto classes = classify_vertices(m);
  EXPECT_EQ(classes[0], VertexClass::Flat);
  for (int v = 1; v < 7; ++v)
    EXPECT_EQ(classes[v], VertexClass::Boundary);
  EXPECT_NEAR(angle_defects(m)[0], 0.0, 1e-12);
}

TEST(ClassifyVertices, WavyFanCentreIsASaddle) {
  Mesh m = fan(0.3);
  EXPECT_LT(angle_defects(m)[0], 0.0);
  EXPECT_EQ(classify_vertices(m)[0], VertexClass::Hyperbolic);
}

TEST(ClassifyVertices, ToleranceDecidesWhatCountsAsFlat) {
  Mesh m = fan(1e-4);
  EXPECT_EQ(classify_vertices(m, 1e-3)[0], VertexClass::Flat);
  EXPECT_EQ(classify_vertices(m, 1e-12)[0], VertexClass::Hyperbolic);
}

TEST(AngleDefects, BoundaryVertexOfAFlatDiskHasPiMinusItsAngle) {
  // The rim vertices of a flat hexagon each see two 60-degree corners: pi - 2pi/3.
  Mesh m = fan(0.0);
  for (int v = 1; v < 7; ++v)
    EXPECT_NEAR(angle_defects(m)[v], std::numbers::pi / 3, 1e-12);
  EXPECT_NEAR(total_defect(m), 2 * std::numbers::pi, 1e-9);  // a disk: chi = 1
}

TEST(GaussBonnet, HoldsOnTheBundledExamples) {
  for (const char* name :
       {"spot_128.obj", "bob_128.obj", "spot_350.obj", "fish_350.obj", "penguin_500.obj"}) {
    Mesh m = load_mesh(test::example_mesh(name)).mesh;
    const MeshStats s = compute_mesh_stats(m);
    EXPECT_NEAR(total_defect(m), 2 * std::numbers::pi * s.euler_characteristic, 1e-8) << name;
  }
}

TEST(GaussBonnet, HoldsOnCorpusMeshesOfSeveralGenera) {
  if (!test::shared_meshes()) GTEST_SKIP() << "../shared/meshes not present";
  for (const char* name : {"double_torus_128.obj", "threeholes_350.obj", "tricky/open_hole.obj",
                           "tricky/two_components.obj", "tricky/quads_ngons.obj"}) {
    Mesh m = load_mesh(*test::shared_meshes() / name).mesh;
    const MeshStats s = compute_mesh_stats(m);
    EXPECT_NEAR(total_defect(m), 2 * std::numbers::pi * s.euler_characteristic, 1e-8) << name;
  }
}
