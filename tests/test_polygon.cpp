// The layout's polygon toolkit: areas, hulls, convex overlap with tolerance, union/offset/intersection.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "foldkit/layout/polygon.hpp"

using namespace foldkit;
using namespace foldkit::layout;

namespace {
Polygon square(double x, double y, double s) {
  return {{x, y}, {x + s, y}, {x + s, y + s}, {x, y + s}};
}

// inside_convex as first written (a hypot and a division per edge): the fast form must agree with it.
bool inside_by_distances(const Polygon& polygon, Vec2 p, double inset) {
  for (std::size_t i = 0, n = polygon.size(); i < n; ++i) {
    const Vec2 e = polygon[(i + 1) % n] - polygon[i];
    const double len = norm(e);
    if (len == 0) continue;
    if (cross(e, p - polygon[i]) / len < inset) return false;
  }
  return true;
}
}  // namespace

TEST(Polygon, InsideConvexAnswersAsTheDistanceFormForPointsAtTheInset) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0, 1);
  const double insets[] = {0.0, 0.15, -0.15, 1e-9};
  long inside = 0, cases = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const double inset = insets[trial % std::size(insets)];
    const double angle = unit(rng) * 2 * std::numbers::pi;
    const Vec2 along{std::cos(angle), std::sin(angle)}, inward{-along.y, along.x};
    const Vec2 a{unit(rng) * 100, unit(rng) * 100};
    const double length = 0.5 + unit(rng) * 40;
    const Polygon triangle{a, a + along * length, a + along * (0.5 * length) + inward * (1 + unit(rng) * 30)};
    // A point at the inset from the first edge, give or take a few ulps, or a little more.
    const int nudge = static_cast<int>(unit(rng) * 7) - 3;
    const double depth =
        trial % 2 ? inset + nudge * 1e-12 : inset * (1 + nudge * 1e-16) + 0.3 * (unit(rng) - 0.5);
    const Vec2 p = a + along * (0.3 * length) + inward * depth;
    const bool expected = inside_by_distances(triangle, p, inset);
    ASSERT_EQ(inside_convex(triangle, p, inset), expected) << "trial " << trial << ", inset " << inset;
    inside += expected;
    ++cases;
  }
  // Both answers occur often, so the comparison saw both sides of the inset.
  EXPECT_GT(inside, cases / 10);
  EXPECT_LT(inside, cases * 9 / 10);
}

TEST(Polygon, SignedAreaIsPositiveCounterClockwise) {
  Polygon sq = square(0, 0, 2);
  EXPECT_DOUBLE_EQ(signed_area(sq), 4);
  std::reverse(sq.begin(), sq.end());
  EXPECT_DOUBLE_EQ(signed_area(sq), -4);
}

TEST(Polygon, ConvexOverlapIgnoresTouchingButSeesCrossings) {
  EXPECT_FALSE(convex_overlap(square(0, 0, 1), square(1, 0, 1), 1e-9)) << "sharing an edge";
  EXPECT_FALSE(convex_overlap(square(0, 0, 1), square(1, 1, 1), 1e-9)) << "sharing a corner";
  EXPECT_TRUE(convex_overlap(square(0, 0, 1), square(0.9, 0.5, 1), 1e-9));
  EXPECT_TRUE(convex_overlap(square(0, 0, 1), square(1.1, 0, 1), -0.2)) << "closer than the clearance";
  const std::array<Vec2, 2> segment{Vec2{-1, 0.5}, Vec2{2, 0.5}};
  EXPECT_TRUE(convex_overlap(square(0, 0, 1), segment, 1e-9)) << "a line through the square";
}

TEST(Polygon, HullDropsInnerAndCollinearPoints) {
  Polygon hull = convex_hull({{0, 0}, {1, 0}, {2, 0}, {2, 2}, {1, 1}, {0, 2}});
  EXPECT_EQ(hull.size(), 4u);
  EXPECT_DOUBLE_EQ(signed_area(hull), 4);
}

TEST(Polygon, UnionOffsetAndIntersectionAreas) {
  const std::vector<Polygon> two = {square(0, 0, 2), square(1, 0, 2)};
  EXPECT_NEAR(total_area(polygon_union(two)), 6, 1e-9);
  const std::vector<Polygon> one = {square(0, 0, 2)};
  // Grown by r: area + perimeter * r + pi r^2.
  EXPECT_NEAR(total_area(polygon_offset(one, 0.5, 0.001)), 4 + 8 * 0.5 + std::numbers::pi * 0.25, 0.01);
  const std::vector<Polygon> a = {square(0, 0, 2)}, b = {square(1, 1, 2)};
  EXPECT_NEAR(intersection_area(a, b), 1, 1e-9);
  const std::vector<Polygon> c = {square(2, 0, 2)};
  EXPECT_NEAR(intersection_area(a, c), 0, 1e-12);
}
