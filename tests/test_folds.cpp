// Fold lines: mountain or valley by the dihedral sign, flat folds left out, ends pulled back.
#include <gtest/gtest.h>

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
      const double length = e.length * 100;
      EXPECT_NEAR(norm(f.b - f.a), length - 2 * std::min(o.inset_mm, 0.25 * length), 1e-6);
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
