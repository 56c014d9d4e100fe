// Silhouette registration marks: square top-left, L brackets top-right and bottom-left, at the inset.
#include <gtest/gtest.h>

#include "foldkit/layout/polygon.hpp"
#include "foldkit/layout/regmarks.hpp"

using namespace foldkit;
using namespace foldkit::layout;

TEST(RegMarks, TheSilhouetteConventionOnA4) {
  const Vec2 a4{210, 297};
  const auto marks = regmark_paths(a4);
  ASSERT_EQ(marks.size(), 3u);
  // Filled 5 mm square with its outer corner 10 mm from the top-left corner.
  EXPECT_TRUE(marks[0].filled);
  EXPECT_TRUE(marks[0].closed);
  const Box2 square = bounds_of(marks[0].points_mm);
  EXPECT_DOUBLE_EQ(square.min.x, 10);
  EXPECT_DOUBLE_EQ(square.min.y, 10);
  EXPECT_DOUBLE_EQ(square.width(), 5);
  EXPECT_DOUBLE_EQ(square.height(), 5);
  // Top-right bracket: its outer edges (stroke included) at 10 mm from the top and right, 20 mm arms.
  const Box2 tr = bounds_of(marks[1].points_mm);
  EXPECT_NEAR(tr.max.x + 0.25, 200, 1e-9);
  EXPECT_NEAR(tr.min.y - 0.25, 10, 1e-9);
  EXPECT_NEAR(tr.width() + 0.25, 20, 1e-9);
  EXPECT_NEAR(tr.height() + 0.25, 20, 1e-9);
  // Bottom-left bracket.
  const Box2 bl = bounds_of(marks[2].points_mm);
  EXPECT_NEAR(bl.min.x - 0.25, 10, 1e-9);
  EXPECT_NEAR(bl.max.y + 0.25, 287, 1e-9);
  for (const Path& p : marks)
    EXPECT_EQ(p.role, PathRole::RegMark);
}

TEST(RegMarks, KeepOutZonesContainTheMarksWithClearance) {
  RegMarkOptions o;
  o.inset_mm = 15;
  o.arm_mm = 25;
  o.clearance_mm = 4;
  const auto marks = regmark_paths({300, 300}, o);
  const auto zones = regmark_keep_out({300, 300}, o);
  ASSERT_EQ(zones.size(), marks.size());
  for (std::size_t i = 0; i < marks.size(); ++i)
    for (Vec2 v : marks[i].points_mm) {
      EXPECT_GE(v.x, zones[i].min.x + 4 - 1e-9);
      EXPECT_LE(v.x, zones[i].max.x - 4 + 1e-9);
      EXPECT_GE(v.y, zones[i].min.y + 4 - 1e-9);
      EXPECT_LE(v.y, zones[i].max.y - 4 + 1e-9);
    }
  const Box2 reach = regmark_cut_area({300, 300}, o);
  EXPECT_DOUBLE_EQ(reach.min.x, 15);
  EXPECT_DOUBLE_EQ(reach.max.y, 285);
}
