// flatten() and check_unfolding(): congruent, unmirrored flat triangles, folds as a forest, and a
// checker that notices each kind of broken unfolding.
#include <gtest/gtest.h>

#include <cmath>

#include "foldkit/unfold/dual_graph.hpp"
#include "foldkit/unfold/mesh_io.hpp"
#include "foldkit/unfold/unfolding.hpp"
#include "test_paths.hpp"

using namespace foldkit;
using namespace foldkit::unfold;

namespace {

Mesh example(const std::string& name) {
  return load_mesh(test::example_mesh(name)).mesh;
}

void expect_congruent(const Mesh& mesh, const Unfolding& u) {
  for (int f = 0; f < mesh.num_faces(); ++f) {
    auto c = mesh.corners(f);
    for (int i = 0; i < 3; ++i) {
      double l3 = norm(c[(i + 1) % 3] - c[i]);
      double l2 = norm(u.flat[f][(i + 1) % 3] - u.flat[f][i]);
      ASSERT_NEAR(l2, l3, 1e-9 * l3) << mesh.name << " face " << f;
    }
    ASSERT_GT(signed_area(u.flat[f]), 0) << mesh.name << " face " << f << " is mirrored";
  }
}

}  // namespace

TEST(Flatten, EveryFlatTriangleIsCongruentAndCounterClockwiseOnRealMeshes) {
  for (const char* name : {"spot_350.obj", "fish_350.obj", "bob_350.obj", "penguin_500.obj"}) {
    Mesh mesh = example(name);
    Unfolding u = flatten(mesh, spanning_forest(mesh, min_perimeter_weights(mesh)));
    expect_congruent(mesh, u);
    EXPECT_EQ(u.piece_count, 1) << name << ": a spanning tree lays out as one (overlapping) piece";
  }
}

TEST(Flatten, FoldingEveryEdgeCutsTheEdgesThatCloseCycles) {
  Mesh mesh = example("bob_128.obj");
  Unfolding u = flatten(mesh, all_edges(mesh.num_edges(), EdgeState::Fold));
  int folds = 0;
  for (const auto& e : u.edges)
    folds += e.cut ? 0 : 1;
  EXPECT_EQ(folds, mesh.num_faces() - 1);
  expect_congruent(mesh, u);
}

TEST(Flatten, CuttingEveryEdgeGivesOnePiecePerFace) {
  Mesh mesh = example("spot_128.obj");
  Unfolding u = flatten(mesh, all_edges(mesh.num_edges(), EdgeState::Cut));
  EXPECT_EQ(u.piece_count, mesh.num_faces());
  EXPECT_EQ(u.seam_count(), mesh.num_edges());
  EXPECT_TRUE(check_unfolding(mesh, u).empty());
  auto pieces = u.piece_faces();
  ASSERT_EQ(pieces.size(), static_cast<std::size_t>(mesh.num_faces()));
  for (int f = 0; f < mesh.num_faces(); ++f)
    EXPECT_EQ(pieces[u.piece_of_face[f]], std::vector<int>{f});
}

TEST(Flatten, FoldEdgesCarryTheSignedDihedralAngleAndLength) {
  Mesh mesh = example("spot_350.obj");
  Unfolding u = flatten(mesh, spanning_forest(mesh, min_perimeter_weights(mesh)));
  int mountains = 0, valleys = 0;
  for (int e = 0; e < mesh.num_edges(); ++e) {
    EXPECT_DOUBLE_EQ(u.edges[e].length, edge_length(mesh, e));
    EXPECT_DOUBLE_EQ(u.edges[e].fold_angle, fold_angle(mesh, e));
    (u.edges[e].fold_angle > 0 ? mountains : valleys)++;
  }
  EXPECT_GT(mountains, valleys) << "a cow is mostly convex";
  EXPECT_GT(valleys, 0);
  EXPECT_GT(u.model_extent, 0);
}

TEST(CheckUnfolding, NoticesAMovedCornerAMirroredFaceAndOverlaps) {
  Mesh mesh = example("spot_128.obj");
  Unfolding good = flatten(mesh, all_edges(mesh.num_edges(), EdgeState::Cut));
  ASSERT_TRUE(check_unfolding(mesh, good).empty());

  Unfolding moved = good;
  moved.flat[5][1] = moved.flat[5][1] + Vec2{1e-3, 0};
  EXPECT_FALSE(check_unfolding(mesh, moved).empty());

  Unfolding mirrored = good;
  for (auto& p : mirrored.flat[7])
    p.x = -p.x;
  EXPECT_FALSE(check_unfolding(mesh, mirrored).empty());

  // A spanning tree flattened whole overlaps itself somewhere on a real mesh.
  Unfolding tree = flatten(mesh, spanning_forest(mesh, min_perimeter_weights(mesh)));
  auto problems = check_unfolding(mesh, tree);
  ASSERT_FALSE(problems.empty());
  EXPECT_NE(problems.front().find("overlap"), std::string::npos) << problems.front();
}

TEST(CheckUnfolding, NoticesAFoldBetweenTwoPieces) {
  Mesh mesh = example("spot_128.obj");
  Unfolding u = flatten(mesh, all_edges(mesh.num_edges(), EdgeState::Cut));
  u.edges[3].cut = false;
  EXPECT_FALSE(check_unfolding(mesh, u).empty());
}
