// Scale from a wanted size, and the largest scale at which a shape fits a rectangle at its best turn.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "foldkit/layout/scale.hpp"

using namespace foldkit;
using namespace foldkit::layout;

TEST(Scale, SizeOverExtentGivesMillimetresPerUnit) {
  EXPECT_DOUBLE_EQ(scale_for_size(2.0, 150), 75);
}

TEST(Scale, ARectangleIsTurnedWhereverThatLetsItGrow) {
  std::vector<Vec2> rect = {{0, 0}, {4, 0}, {4, 1}, {0, 1}};
  // In a square room a 4 x 1 bar fits best at 45 degrees, its bounding box (4 + 1) / sqrt(2) wide.
  EXPECT_NEAR(max_fit_scale(rect, {100, 100}), 100 / (5 / std::sqrt(2.0)), 1e-6);
  // In a narrow room it stands upright: 1 unit across 10 mm.
  EXPECT_NEAR(max_fit_scale(rect, {10, 100}), 10, 1e-6);
}

TEST(Scale, ALongDiagonalStickIsTurnedToLieAlongTheRoom) {
  // A thin stick at 45 degrees, length 10: its bounding box is 7.07 square, but turned it fits a
  // 100 x 20 room at scale ~10.2 (tilted by atan(0.2) to use the room's height).
  const double c = std::sqrt(0.5);
  std::vector<Vec2> stick = {{0, 0}, {10 * c, 10 * c}, {10 * c - 0.01, 10 * c + 0.01}, {-0.01, 0.01}};
  const double s = max_fit_scale(stick, {100, 20});
  EXPECT_GT(s, 10.1);
  EXPECT_LE(s, 10.2);
  const Vec2 along = rotated({c, c}, best_fit_angle(stick, {100, 20}));
  EXPECT_LT(std::fabs(along.y / along.x), 0.25) << "the stick lies almost along the room's length";
}

TEST(Scale, AnEmptyRoomFitsNothing) {
  std::vector<Vec2> tri = {{0, 0}, {1, 0}, {0, 1}};
  EXPECT_EQ(max_fit_scale(tri, {0, 10}), 0);
}
