// Tool-path ordering: short pen-up travel, insides before the outlines around them, overcut.
#include <algorithm>
#include <random>

#include <gtest/gtest.h>

#include "foldkit/devices/path_order.hpp"

namespace foldkit::devices {
namespace {

ToolPath square(Vec2 min, double side) {
  return {{min, {min.x + side, min.y}, {min.x + side, min.y + side}, {min.x, min.y + side}}, true};
}

ToolPath segment(Vec2 a, Vec2 b) {
  return {{a, b}, false};
}

double length(const std::vector<Vec2>& pts) {
  double l = 0;
  for (std::size_t i = 1; i < pts.size(); ++i)
    l += norm(pts[i] - pts[i - 1]);
  return l;
}

// A 10 x 10 grid of short segments in a shuffled order (fixed seed).
std::vector<ToolPath> shuffled_grid() {
  std::vector<ToolPath> paths;
  for (int r = 0; r < 10; ++r)
    for (int c = 0; c < 10; ++c)
      paths.push_back(segment({c * 10.0, r * 10.0}, {c * 10.0 + 5, r * 10.0}));
  std::mt19937 rng(42);
  std::shuffle(paths.begin(), paths.end(), rng);
  return paths;
}

TEST(PathOrder, TakesEveryPathExactlyOnce) {
  const auto paths = shuffled_grid();
  const PathOrder order = order_paths(paths);
  ASSERT_EQ(order.paths.size(), paths.size());
  std::vector<std::size_t> seen;
  for (const OrderedPath& p : order.paths)
    seen.push_back(p.source);
  std::sort(seen.begin(), seen.end());
  for (std::size_t i = 0; i < seen.size(); ++i)
    EXPECT_EQ(seen[i], i);
}

TEST(PathOrder, CutsPenUpTravelOnAShuffledGridToNearTheBest) {
  const PathOrder order = order_paths(shuffled_grid());
  // Best possible: 100 segments 5 mm long, 5 mm gaps within a row (90 gaps) and 9 row changes of about
  // 10 mm in a serpentine: ~540 mm. A shuffled order travels thousands.
  EXPECT_GT(order.travel_before_mm, 3000);
  EXPECT_LT(order.travel_after_mm, 650);
  EXPECT_NEAR(order.travel_after_mm, pen_up_travel_mm(order.paths, {0, 0}), 1e-9);
}

TEST(PathOrder, NeverMakesAGoodInputOrderWorse) {
  std::vector<ToolPath> paths;
  for (int c = 0; c < 20; ++c)
    paths.push_back(segment({c * 3.0, 0}, {c * 3.0 + 2, 0}));
  const PathOrder order = order_paths(paths);
  EXPECT_LE(order.travel_after_mm, order.travel_before_mm + 1e-9);
  EXPECT_NEAR(order.travel_after_mm, 19.0, 1e-9);
}

TEST(PathOrder, DoesWhatLiesInsideBeforeTheOutlineAroundIt) {
  // Nested squares given outside-in, with a fold line inside the innermost: the order must be reversed.
  std::vector<ToolPath> paths{square({0, 0}, 100), square({10, 10}, 80), square({20, 20}, 60),
                              segment({30, 50}, {70, 50})};
  const PathOrder order = order_paths(paths);
  std::vector<std::size_t> pos(paths.size());
  for (std::size_t k = 0; k < order.paths.size(); ++k)
    pos[order.paths[k].source] = k;
  EXPECT_LT(pos[3], pos[2]);
  EXPECT_LT(pos[2], pos[1]);
  EXPECT_LT(pos[1], pos[0]);
}

TEST(PathOrder, MayIgnoreNestingWhenAskedTo) {
  // Without the constraint the nearest path (the big outline, at the origin) comes first.
  std::vector<ToolPath> paths{square({0, 0}, 100), square({40, 40}, 10)};
  PathOrderOptions o;
  o.inside_first = false;
  EXPECT_EQ(order_paths(paths, o).paths.front().source, 0u);
  EXPECT_EQ(order_paths(paths).paths.front().source, 1u);
}

TEST(PathOrder, ReversesOpenPathsAndPicksTheNearestStartVertex) {
  std::vector<ToolPath> paths{segment({50, 0}, {10, 0}), square({60, 60}, 10)};
  PathOrderOptions o;
  const PathOrder order = order_paths(paths, o);
  ASSERT_EQ(order.paths.size(), 2u);
  EXPECT_EQ(order.paths[0].source, 0u);
  EXPECT_TRUE(order.paths[0].reversed);
  EXPECT_EQ(order.paths[0].points_mm.front(), (Vec2{10, 0}));
  EXPECT_EQ(order.paths[1].start_vertex, 0u);  // (60, 60) is the corner nearest (50, 0)
  EXPECT_EQ(order.paths[1].points_mm.front(), order.paths[1].points_mm.back());
}

TEST(PathOrder, OvercutsClosedPathsByTheAskedLength) {
  PathOrderOptions o;
  o.overcut_mm = 3;
  const PathOrder order = order_paths({square({0, 0}, 10)}, o);
  ASSERT_EQ(order.paths.size(), 1u);
  EXPECT_NEAR(length(order.paths[0].points_mm), 43, 1e-9);
  EXPECT_EQ(order.paths[0].points_mm.back(), (Vec2{3, 0}));
}

TEST(PathOrder, CapsTheOvercutAtOneMoreRound) {
  const auto t = closed_trajectory(square({0, 0}, 10).points_mm, 2, 100);
  EXPECT_NEAR(length(t), 80, 1e-9);
  EXPECT_EQ(t.front(), (Vec2{10, 10}));
  EXPECT_EQ(t.back(), (Vec2{10, 10}));
  EXPECT_NEAR(length(closed_trajectory(square({0, 0}, 10).points_mm, 0, 0)), 40, 1e-9);
}

TEST(PathOrder, KeepsEmptyPathsAtTheEndAtNoCost) {
  std::vector<ToolPath> paths{ToolPath{}, segment({1, 0}, {2, 0})};
  const PathOrder order = order_paths(paths);
  ASSERT_EQ(order.paths.size(), 2u);
  EXPECT_EQ(order.paths.back().source, 0u);
  EXPECT_NEAR(order.travel_after_mm, 1, 1e-9);
}

TEST(PathOrder, IsDeterministic) {
  const PathOrder a = order_paths(shuffled_grid()), b = order_paths(shuffled_grid());
  ASSERT_EQ(a.paths.size(), b.paths.size());
  for (std::size_t i = 0; i < a.paths.size(); ++i) {
    EXPECT_EQ(a.paths[i].source, b.paths[i].source);
    EXPECT_EQ(a.paths[i].points_mm, b.paths[i].points_mm);
  }
}

TEST(LiesInside, CountsAFoldLineTouchingTheOutlineAtBothEnds) {
  EXPECT_TRUE(lies_inside(segment({0, 5}, {10, 5}), square({0, 0}, 10)));
}

TEST(LiesInside, RejectsPathsOutsideOnTheEdgeOrInsideAnOpenPath) {
  EXPECT_FALSE(lies_inside(segment({0, 0}, {10, 0}), square({0, 0}, 10)));  // along the edge
  EXPECT_FALSE(lies_inside(segment({5, 5}, {15, 5}), square({0, 0}, 10)));  // leaves it
  EXPECT_FALSE(lies_inside(square({0, 0}, 10), square({0, 0}, 10)));        // same size
  EXPECT_FALSE(lies_inside(segment({2, 2}, {3, 3}), {square({0, 0}, 10).points_mm, false}));
  EXPECT_TRUE(lies_inside(square({2, 2}, 3), square({0, 0}, 10)));
}

}  // namespace
}  // namespace foldkit::devices
