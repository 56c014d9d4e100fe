// The layout's polygon toolkit: areas, hulls, convex overlap with tolerance, union/offset/intersection.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "foldkit/layout/polygon.hpp"

using namespace foldkit;
using namespace foldkit::layout;

namespace {
Polygon square(double x, double y, double s) {
  return {{x, y}, {x + s, y}, {x + s, y + s}, {x, y + s}};
}
}  // namespace

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
