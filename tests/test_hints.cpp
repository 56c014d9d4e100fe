// Assembly order: type-I zippers first, sharpest first, every seam exactly once.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "foldkit/layout/hints.hpp"
#include "layout_fixtures.hpp"

using namespace foldkit;
using namespace foldkit::layout;

namespace {
std::vector<Seam> seams_with_angles(std::vector<double> angles) {
  std::vector<Seam> seams;
  for (std::size_t i = 0; i < angles.size(); ++i)
    seams.push_back({static_cast<int>(i), angles[i], {}});
  return seams;
}
}  // namespace

TEST(Hints, NeighbouringPairsZipBeforeSharperSeamsElsewhere) {
  // Loop a b b^-1 c a^-1 c^-1: b is a zipper (type I) though flatter than a and c.
  const auto seams = seams_with_angles({1.5, 0.2, 1.0});
  const auto order = assembly_order({{0, 1, 1, 2, 0, 2}}, seams);
  ASSERT_EQ(order.size(), 3u);
  EXPECT_EQ(order[0], 1);
  // After b the loop is a c a^-1 c^-1: no zipper, the sharpest (a) goes next, then c zips.
  EXPECT_EQ(order[1], 0);
  EXPECT_EQ(order[2], 2);
}

TEST(Hints, AmongZippersTheSharpestGoesFirst) {
  const auto seams = seams_with_angles({0.1, 0.9, 0.5});
  const auto order = assembly_order({{0, 0, 1, 1, 2, 2}}, seams);
  EXPECT_EQ(order, (std::vector<int>{1, 2, 0}));
}

TEST(Hints, SeamsBetweenPiecesJoinTheirLoops) {
  // Two pieces joined by seam 0; then seam 1 zips across the joined loop. Boundary edges (-1) stay.
  const auto seams = seams_with_angles({0.3, 0.6});
  const auto order = assembly_order({{0, 1, -1}, {0, -1, 1}}, seams);
  ASSERT_EQ(order.size(), 2u);
  EXPECT_EQ(order[0], 1) << "the sharper seam first when nothing zips";
}

TEST(Hints, EverySeamOfARealUnfoldingGetsExactlyOneStep) {
  const auto& ex = test::unfolded_example("penguin_500.obj");
  const auto pieces = scaled_pieces(ex.unfolding, 1);
  const auto seams = find_seams(ex.unfolding, pieces);
  auto order = assembly_order(seam_loops(pieces, seams), seams);
  ASSERT_EQ(order.size(), seams.size());
  // Sharp first in the large: the first tenth is sharper on average than the last tenth.
  const std::size_t tenth = order.size() / 10;
  double first = 0, last = 0;
  for (std::size_t i = 0; i < tenth; ++i) {
    first += std::fabs(seams[order[i]].fold_angle_rad);
    last += std::fabs(seams[order[order.size() - 1 - i]].fold_angle_rad);
  }
  EXPECT_GT(first, last);
  std::sort(order.begin(), order.end());
  for (std::size_t i = 0; i < order.size(); ++i)
    ASSERT_EQ(order[i], static_cast<int>(i));
}
