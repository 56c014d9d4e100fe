// OverlapIndex: every query must return exactly the brute-force set of overlapping triangles of the
// same piece, through inserts, removals and moves; touching is never an overlap.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

#include "foldkit/unfold/overlap_index.hpp"

using namespace foldkit;
using namespace foldkit::unfold;

namespace {

Triangle2 random_triangle(std::mt19937_64& rng, double spread, double size) {
  std::uniform_real_distribution<double> pos(0, spread), d(-size, size);
  Vec2 c{pos(rng), pos(rng)};
  Triangle2 t{c + Vec2{d(rng), d(rng)}, c + Vec2{d(rng), d(rng)}, c + Vec2{d(rng), d(rng)}};
  if (signed_area(t) < 0) std::swap(t[1], t[2]);
  return t;
}

std::set<int> query_all(OverlapIndex& index, const Triangle2& t, int piece, int self) {
  std::set<int> found;
  index.query(
      t, piece, [self](int g) { return g == self; },
      [&](int g) {
        EXPECT_TRUE(found.insert(g).second) << "face " << g << " reported twice";
        return true;
      });
  return found;
}

}  // namespace

TEST(OverlapIndex, QueriesMatchBruteForceThroughInsertsRemovalsAndMoves) {
  std::mt19937_64 rng(7);
  const int n = 400;
  const double eps = 1e-9;
  std::vector<Triangle2> tri(n);
  std::vector<int> piece(n);
  // A few triangles far larger than the cell size exercise the list kept outside the grid.
  for (int f = 0; f < n; ++f) {
    tri[f] = random_triangle(rng, 30, f % 97 == 0 ? 40 : 1.5);
    piece[f] = f % 3;
  }
  OverlapIndex index(n, 1.5, eps);
  for (int f = 0; f < n; ++f)
    index.insert(f, piece[f], tri[f]);
  auto check_all = [&] {
    for (int f = 0; f < n; ++f) {
      if (!index.contains(f)) continue;
      std::set<int> expected;
      for (int g = 0; g < n; ++g)
        if (g != f && index.contains(g) && piece[g] == piece[f] && triangles_overlap(tri[f], tri[g], eps))
          expected.insert(g);
      ASSERT_EQ(query_all(index, tri[f], piece[f], f), expected) << "face " << f;
    }
  };
  check_all();
  std::uniform_int_distribution<int> pick(0, n - 1);
  for (int round = 0; round < 200; ++round) {
    int f = pick(rng);
    if (index.contains(f)) index.remove(f);
    if (round % 4 != 0) {
      tri[f] = random_triangle(rng, 30, round % 50 == 0 ? 40 : 1.5);
      piece[f] = pick(rng) % 3;
      index.insert(f, piece[f], tri[f]);
    }
  }
  check_all();
}

TEST(OverlapIndex, TrianglesSharingAnEdgeOrAVertexDoNotOverlap) {
  OverlapIndex index(3, 1.0, 1e-9);
  index.insert(0, 0, Triangle2{Vec2{0, 0}, Vec2{1, 0}, Vec2{0, 1}});
  index.insert(1, 0, Triangle2{Vec2{1, 0}, Vec2{1, 1}, Vec2{0, 1}});
  index.insert(2, 0, Triangle2{Vec2{1, 1}, Vec2{2, 1}, Vec2{1, 2}});
  for (int f = 0; f < 3; ++f)
    EXPECT_TRUE(query_all(index, index.triangle(f), 0, f).empty()) << "face " << f;
}

TEST(OverlapIndex, OverlapsAreOnlyReportedWithinTheQueriedPiece) {
  OverlapIndex index(2, 1.0, 1e-9);
  Triangle2 t{Vec2{0, 0}, Vec2{1, 0}, Vec2{0, 1}};
  index.insert(0, 0, t);
  index.insert(1, 1, t);
  EXPECT_EQ(query_all(index, t, 0, -1), std::set<int>{0});
  EXPECT_EQ(query_all(index, t, 1, -1), std::set<int>{1});
  EXPECT_TRUE(query_all(index, t, 2, -1).empty());
}
