// make_mesh connectivity and checks, and the per-element geometry of mesh.hpp.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "foldkit/error.hpp"
#include "foldkit/unfold/mesh.hpp"
#include "foldkit/unfold/mesh_io.hpp"
#include "test_paths.hpp"

using namespace foldkit;
using namespace foldkit::unfold;

namespace {

// Regular octahedron, counter-clockwise seen from outside.
Mesh octahedron() {
  std::vector<Vec3> v{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  std::vector<std::array<int, 3>> f{{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                    {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return make_mesh(v, f, "octahedron");
}

// Two triangles sharing edge 0-1, bent by `lift` at the far corner of the second one.
Mesh hinge(double lift) {
  std::vector<Vec3> v{{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, lift}};
  return make_mesh(v, {{0, 1, 2}, {1, 0, 3}}, "hinge");
}

void expect_rejected(std::vector<Vec3> v, std::vector<std::array<int, 3>> f, const std::string& needle) {
  try {
    make_mesh(std::move(v), std::move(f), "m.obj");
    FAIL() << "expected an InputError containing '" << needle << "'";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "m.obj");
    EXPECT_NE(e.problem().find(needle), std::string::npos) << e.what();
  }
}

}  // namespace

TEST(MakeMesh, OctahedronHasTwelveInteriorEdges) {
  Mesh m = octahedron();
  EXPECT_EQ(m.num_edges(), 12);
  for (const MeshEdge& e : m.edges) {
    EXPECT_FALSE(e.boundary());
    EXPECT_LT(e.v[0], e.v[1]);
  }
}

TEST(MakeMesh, FaceEdgesAndCornersAgreeWithTheFaces) {
  Mesh m = load_mesh(test::example_mesh("bob_128.obj")).mesh;
  for (int f = 0; f < m.num_faces(); ++f)
    for (int i = 0; i < 3; ++i) {
      const MeshEdge& e = m.edges[m.face_edges[f][i]];
      const int k = e.face[0] == f ? 0 : 1;
      ASSERT_EQ(e.face[k], f);
      EXPECT_EQ(e.corner[k], i);
      const int a = m.faces[f][i], b = m.faces[f][(i + 1) % 3];
      EXPECT_EQ(std::min(a, b), e.v[0]);
      EXPECT_EQ(std::max(a, b), e.v[1]);
    }
}

TEST(MakeMesh, InteriorEdgesAreTraversedInOppositeDirections) {
  Mesh m = load_mesh(test::example_mesh("spot_128.obj")).mesh;
  for (const MeshEdge& e : m.edges) {
    ASSERT_FALSE(e.boundary());
    const auto& t0 = m.faces[e.face[0]];
    const auto& t1 = m.faces[e.face[1]];
    EXPECT_EQ(t0[e.corner[0]], t1[(e.corner[1] + 1) % 3]);
    EXPECT_EQ(t1[e.corner[1]], t0[(e.corner[0] + 1) % 3]);
  }
}

TEST(MakeMesh, OpenTriangleHasThreeBoundaryEdges) {
  Mesh m = make_mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}, "t");
  ASSERT_EQ(m.num_edges(), 3);
  for (const MeshEdge& e : m.edges)
    EXPECT_TRUE(e.boundary());
}

TEST(MakeMesh, RejectsAnIndexOutOfRange) {
  expect_rejected({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 3}}, "references vertex 4");
}

TEST(MakeMesh, RejectsANonFiniteCoordinate) {
  expect_rejected({{0, 0, 0}, {1, NAN, 0}, {0, 1, 0}}, {{0, 1, 2}}, "non-finite");
}

TEST(MakeMesh, RejectsAFaceUsingAVertexTwice) {
  expect_rejected({{0, 0, 0}, {1, 0, 0}}, {{0, 1, 1}}, "twice");
}

TEST(MakeMesh, RejectsAnEdgeWithThreeFaces) {
  expect_rejected({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}}, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}},
                  "non-manifold edge");
}

TEST(MakeMesh, RejectsInconsistentOrientation) {
  expect_rejected({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}}, {{0, 1, 2}, {0, 1, 3}}, "orientation");
}

TEST(MakeMesh, RejectsAVertexWhoseFacesFormTwoFans) {
  // Two triangles touching only at vertex 0.
  expect_rejected({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}}, {{0, 1, 2}, {0, 3, 4}},
                  "non-manifold vertex 1");
}

TEST(MakeMesh, RejectsAVertexUsedByNoFace) {
  expect_rejected({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 5, 5}}, {{0, 1, 2}}, "no face");
}

TEST(MeshGeometry, AreaNormalAndLengthOfARightTriangle) {
  Mesh m = make_mesh({{0, 0, 0}, {3, 0, 0}, {0, 4, 0}}, {{0, 1, 2}}, "t");
  EXPECT_DOUBLE_EQ(face_area(m, 0), 6.0);
  const Vec3 n = face_normal(m, 0);
  EXPECT_DOUBLE_EQ(n.z, 1.0);
  double total = 0;
  for (int e = 0; e < 3; ++e)
    total += edge_length(m, e);
  EXPECT_DOUBLE_EQ(total, 12.0);
}

TEST(FoldAngle, EveryEdgeOfAConvexOctahedronIsAMountain) {
  Mesh m = octahedron();
  const double expected = std::numbers::pi - std::acos(-1.0 / 3.0);  // pi minus the dihedral angle
  for (int e = 0; e < m.num_edges(); ++e)
    EXPECT_NEAR(fold_angle(m, e), expected, 1e-12);
}

TEST(FoldAngle, CoplanarFacesGiveZero) {
  EXPECT_NEAR(fold_angle(hinge(0.0), 0), 0.0, 1e-15);
}

TEST(FoldAngle, SignFollowsConvexity) {
  // Normals point to +z; lifting the far corner up bends the surface towards its front: a valley.
  Mesh up = hinge(1.0), down = hinge(-1.0);
  int e_up = -1, e_down = -1;
  for (int e = 0; e < up.num_edges(); ++e)
    if (!up.edges[e].boundary()) e_up = e;
  for (int e = 0; e < down.num_edges(); ++e)
    if (!down.edges[e].boundary()) e_down = e;
  EXPECT_NEAR(fold_angle(up, e_up), -std::numbers::pi / 4, 1e-12);
  EXPECT_NEAR(fold_angle(down, e_down), std::numbers::pi / 4, 1e-12);
}

TEST(FoldAngle, BoundaryEdgesGiveZero) {
  Mesh m = hinge(1.0);
  for (int e = 0; e < m.num_edges(); ++e) {
    if (m.edges[e].boundary()) {
      EXPECT_EQ(fold_angle(m, e), 0.0);
    }
  }
}

TEST(FoldAngle, ClosedRealMeshIsMostlyConvexByLength) {
  // Total mean curvature of a closed outward surface is positive: mountains outweigh valleys.
  Mesh m = load_mesh(test::example_mesh("spot_350.obj")).mesh;
  double weighted = 0;
  for (int e = 0; e < m.num_edges(); ++e)
    weighted += fold_angle(m, e) * edge_length(m, e);
  EXPECT_GT(weighted, 0.0);
}
