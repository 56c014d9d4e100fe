// The box grid finds exactly the items whose boxes overlap a query, inside its region or not.
#include <gtest/gtest.h>

#include <random>
#include <set>

#include "foldkit/layout/box_grid.hpp"

using namespace foldkit;
using namespace foldkit::layout;

namespace {

Box2 random_box(std::mt19937& rng, double lo, double hi, double max_size) {
  std::uniform_real_distribution<double> at(lo, hi), size(0, max_size);
  const Vec2 min{at(rng), at(rng)};
  return Box2{min, min + Vec2{size(rng), size(rng)}};
}

}  // namespace

TEST(BoxGrid, AQueryVisitsExactlyTheOverlappingItemsOnceEach) {
  std::mt19937 rng(12345);
  // The region is smaller than where items and queries lie: border cells must catch the rest.
  BoxGrid grid(Box2{{0, 0}, {100, 100}}, 4);
  std::vector<Box2> boxes;
  for (int i = 0; i < 2000; ++i) {
    boxes.push_back(random_box(rng, -30, 130, i % 50 == 0 ? 60 : 6));
    grid.insert(i, boxes.back());
  }
  for (int q = 0; q < 300; ++q) {
    const Box2 query = random_box(rng, -40, 140, 20);
    std::multiset<int> seen;
    grid.visit(query, [&](int id) {
      seen.insert(id);
      return true;
    });
    std::multiset<int> expected;
    for (int i = 0; i < static_cast<int>(boxes.size()); ++i)
      if (boxes[i].overlaps(query)) expected.insert(i);
    ASSERT_EQ(seen, expected) << "query " << q;
  }
}

TEST(BoxGrid, AVisitStopsWhenAskedAndSaysSo) {
  BoxGrid grid(Box2{{0, 0}, {10, 10}}, 1);
  for (int i = 0; i < 5; ++i)
    grid.insert(i, Box2{{1, 1}, {2, 2}});
  int calls = 0;
  EXPECT_FALSE(grid.visit(Box2{{0, 0}, {3, 3}}, [&](int) { return ++calls < 2; }));
  EXPECT_EQ(calls, 2);
  EXPECT_TRUE(grid.visit(Box2{{5, 5}, {6, 6}}, [&](int) { return false; }));
}

TEST(BoxGrid, AHugeRegionIsCoarsenedToABoundedNumberOfCells) {
  // 1 km at 4 mm cells would be 6e10 cells; the grid caps its side instead and still answers.
  BoxGrid grid(Box2{{0, 0}, {1e6, 1e6}}, 4, 64);
  grid.insert(0, Box2{{5e5, 5e5}, {5e5 + 1, 5e5 + 1}});
  int found = 0;
  grid.visit(Box2{{5e5, 5e5}, {5e5 + 2, 5e5 + 2}}, [&](int) { return ++found, true; });
  EXPECT_EQ(found, 1);
}
