// Fold lines: mountain or valley by the dihedral sign, flat folds left out, ends pulled back.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "foldkit/layout/folds.hpp"
#include "layout_fixtures.hpp"

using namespace foldkit;
using namespace foldkit::layout;

TEST(Folds, SignOfTheDihedralChoosesMountainOrValley) {
  EXPECT_EQ(fold_role(0.3), PathRole::Mountain);
  EXPECT_EQ(fold_role(-0.3), PathRole::Valley);
}

TEST(Folds, ATetrahedronHasThreeMountainFoldsStoppingShortOfTheCorners) {
  const auto ex = test::tetrahedron();
  const auto pieces = scaled_pieces(ex.unfolding, 20);
  FoldOptions o;
  o.inset_mm = 1;
  const auto folds = fold_lines(ex.unfolding, pieces[0], o);
  ASSERT_EQ(folds.size(), 3u);
  for (const FoldLine& f : folds) {
    EXPECT_EQ(f.role, PathRole::Mountain) << "a convex solid folds mountain everywhere";
    EXPECT_NEAR(norm(f.b - f.a), 20 - 2, 1e-9);
    EXPECT_FALSE(ex.unfolding.edges[f.edge].cut);
  }
}

TEST(Folds, OnRealMeshesEveryDrawnFoldIsBentEnoughAndEveryBentFoldIsDrawnOnce) {
  const auto& ex = test::unfolded_example("bob_350.obj");
  const auto pieces = scaled_pieces(ex.unfolding, 100);
  FoldOptions o;
  o.flat_fold_rad = 5 * M_PI / 180;
  std::vector<int> drawn(ex.unfolding.edges.size(), 0);
  for (const ScaledPiece& p : pieces)
    for (const FoldLine& f : fold_lines(ex.unfolding, p, o)) {
      const auto& e = ex.unfolding.edges[f.edge];
      EXPECT_GE(std::fabs(e.fold_angle), o.flat_fold_rad);
      EXPECT_EQ(f.role, e.fold_angle > 0 ? PathRole::Mountain : PathRole::Valley);
      // The fold lies on its edge, pulled back equally at both ends, by at most inset_mm, and keeps at
      // least half of the edge (a short edge is not scored away).
      const auto k = std::find(p.faces.begin(), p.faces.end(), e.face[0]) - p.faces.begin();
      ASSERT_LT(static_cast<std::size_t>(k), p.faces.size()) << "edge " << f.edge << " of another piece";
      const Vec2 a = p.triangles_mm[k][e.corner[0]], b = p.triangles_mm[k][(e.corner[0] + 1) % 3];
      const double length = norm(b - a);
      const Vec2 along = (b - a) / length;
      EXPECT_NEAR(cross(along, f.a - a), 0, 1e-9);
      EXPECT_NEAR(cross(along, f.b - a), 0, 1e-9);
      const double inset_a = dot(along, f.a - a), inset_b = dot(along, b - f.b);
      EXPECT_NEAR(inset_a, inset_b, 1e-9) << "edge " << f.edge;
      EXPECT_GT(inset_a, 0) << "edge " << f.edge;
      EXPECT_LE(inset_a, o.inset_mm + 1e-9) << "edge " << f.edge;
      EXPECT_GE(norm(f.b - f.a), 0.5 * length - 1e-9) << "edge " << f.edge;
      drawn[f.edge] += 1;
    }
  int flat = 0;
  for (std::size_t e = 0; e < drawn.size(); ++e) {
    const auto& edge = ex.unfolding.edges[e];
    const bool should = !edge.cut && std::fabs(edge.fold_angle) >= o.flat_fold_rad;
    EXPECT_EQ(drawn[e], should ? 1 : 0) << "edge " << e;
    flat += !edge.cut && !should;
  }
  EXPECT_GT(flat, 0) << "bob has near-flat folds that must be left out";
}
