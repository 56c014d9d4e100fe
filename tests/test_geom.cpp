#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "foldkit/geom/predicates.hpp"
#include "foldkit/geom/vec.hpp"

using namespace foldkit;

TEST(TrianglesOverlap, TrianglesSharingAnEdgeDoNotOverlap) {
  Triangle2 a{{{0, 0}, {1, 0}, {0, 1}}};
  Triangle2 b{{{1, 0}, {1, 1}, {0, 1}}};
  EXPECT_FALSE(triangles_overlap(a, b, 1e-9));
}

TEST(TrianglesOverlap, TrianglesSharingOnlyAVertexDoNotOverlap) {
  Triangle2 a{{{0, 0}, {1, 0}, {0, 1}}};
  Triangle2 b{{{1, 0}, {2, 0}, {2, 1}}};
  EXPECT_FALSE(triangles_overlap(a, b, 1e-9));
}

TEST(TrianglesOverlap, CrossingTrianglesOverlap) {
  Triangle2 a{{{0, 0}, {2, 0}, {0, 2}}};
  Triangle2 b{{{0.5, 0.5}, {3, 0.5}, {0.5, 3}}};
  EXPECT_TRUE(triangles_overlap(a, b, 1e-9));
}

TEST(TrianglesOverlap, StarOfDavidTrianglesOverlapThoughNoCornerIsInside) {
  Triangle2 a{{{0, 0}, {2, 0}, {1, 1.8}}};
  Triangle2 b{{{0, 1.2}, {1, -0.6}, {2, 1.2}}};
  EXPECT_TRUE(triangles_overlap(a, b, 1e-9));
}

TEST(TrianglesOverlap, ContainedTriangleOverlaps) {
  Triangle2 a{{{0, 0}, {10, 0}, {0, 10}}};
  Triangle2 b{{{1, 1}, {2, 1}, {1, 2}}};
  EXPECT_TRUE(triangles_overlap(a, b, 1e-9));
  EXPECT_TRUE(triangles_overlap(b, a, 1e-9));
}

// The separating-axis test as first written (one hypot and one division per corner): convex_overlap
// skips the hypot where the answer does not depend on it and must answer exactly as this does.
bool overlap_by_distances(const std::vector<Vec2>& a, const std::vector<Vec2>& b, double eps) {
  auto separated = [eps](const std::vector<Vec2>& p, const std::vector<Vec2>& q) {
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Vec2 e = p[(i + 1) % p.size()] - p[i];
      const double len = norm(e);
      if (len == 0) continue;
      double deepest = -1e300;
      for (Vec2 v : q)
        deepest = std::fmax(deepest, cross(e, v - p[i]) / len);
      if (deepest <= eps) return true;
    }
    return false;
  };
  return !separated(a, b) && !separated(b, a);
}

TEST(ConvexOverlap, AnswersAsTheDistanceFormOnShapesTouchingAtTheTolerance) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0, 1);
  const double tolerances[] = {1e-9, 1e-3, 0.0, -0.5, -1e-9, 0.25};
  long overlaps = 0, cases = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const double eps = tolerances[trial % std::size(tolerances)];
    // A triangle and a second one whose corner sits at eps (give or take a few ulps, or a little
    // more) from the line of the first one's edge: the cases where rounding could decide.
    const Vec2 p0{unit(rng) * 100, unit(rng) * 100};
    const double angle = unit(rng) * 6.283185307179586;
    const Vec2 along{std::cos(angle), std::sin(angle)}, inward{-along.y, along.x};
    const double length = 0.5 + unit(rng) * 50;
    std::vector<Vec2> a{p0, p0 + along * length,
                        p0 + along * (0.5 * length) + inward * (0.2 + unit(rng) * 30)};
    const int nudge = static_cast<int>(unit(rng) * 7) - 3;
    const double depth = trial % 3 == 0 ? eps + nudge * 1e-12 : eps * (1 + nudge * 1e-16) + (unit(rng) - 0.5);
    const Vec2 corner = p0 + along * (unit(rng) * length) + inward * depth;
    std::vector<Vec2> b{corner, corner - inward * (1 + unit(rng) * 20) - along * 3,
                        corner - inward * (1 + unit(rng) * 20) + along * 3};
    const bool expected = overlap_by_distances(a, b, eps);
    ASSERT_EQ(convex_overlap(a, b, eps), expected) << "trial " << trial << ", eps " << eps;
    ASSERT_EQ(convex_overlap(b, a, eps), overlap_by_distances(b, a, eps)) << "trial " << trial;
    overlaps += expected;
    ++cases;
  }
  // Both answers occur often, so the comparison above saw both sides of the tolerance.
  EXPECT_GT(overlaps, cases / 10);
  EXPECT_LT(overlaps, cases * 9 / 10);
}

TEST(SegmentsCross, TouchingAtAnEndpointIsNotACrossing) {
  EXPECT_FALSE(segments_cross({0, 0}, {1, 0}, {1, 0}, {1, 1}, 1e-12));
  EXPECT_TRUE(segments_cross({0, 0}, {2, 0}, {1, -1}, {1, 1}, 1e-12));
}

TEST(Box2, GrownMovesEverySideOutAndANegativeAmountMovesThemIn) {
  Box2 b;
  b.add(Vec2{1, 2});
  b.add(Vec2{4, 3});
  const Box2 out = grown(b, 0.5);
  EXPECT_EQ(out.min.x, 0.5);
  EXPECT_EQ(out.min.y, 1.5);
  EXPECT_EQ(out.max.x, 4.5);
  EXPECT_EQ(out.max.y, 3.5);
  const Box2 in = grown(b, -0.25);
  EXPECT_DOUBLE_EQ(in.width(), 2.5);
  EXPECT_DOUBLE_EQ(in.height(), 0.5);
  EXPECT_TRUE(grown(b, -1).empty()) << "moved in past its height";
}
