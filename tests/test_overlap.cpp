// overlapping_pairs(): touching is never an overlap, crossing always is, and the grid finds exactly
// what comparing every pair finds.
#include <gtest/gtest.h>

#include <random>

#include "foldkit/unfold/overlap.hpp"

using namespace foldkit;
using namespace foldkit::unfold;

TEST(Overlap, TrianglesSharingAnEdgeOrAVertexDoNotOverlap) {
  std::vector<Triangle2> flat = {
      {{{0, 0}, {1, 0}, {0, 1}}}, {{{1, 0}, {1, 1}, {0, 1}}}, {{{1, 1}, {2, 1}, {1, 2}}}};
  EXPECT_TRUE(overlapping_pairs(flat, {0, 0, 0}).empty());
}

TEST(Overlap, CrossingTrianglesOfOnePieceOverlapAndOfTwoPiecesDoNot) {
  std::vector<Triangle2> flat = {{{{0, 0}, {2, 0}, {0, 2}}}, {{{0.5, 0.5}, {3, 0.5}, {0.5, 3}}}};
  auto same = overlapping_pairs(flat, {0, 0});
  ASSERT_EQ(same.size(), 1u);
  EXPECT_EQ(same[0], (FacePair{0, 1}));
  EXPECT_TRUE(overlapping_pairs(flat, {0, 1}).empty());
}

TEST(Overlap, ATriangleInsideAnotherOverlapsIt) {
  std::vector<Triangle2> flat = {{{{0, 0}, {10, 0}, {0, 10}}}, {{{1, 1}, {2, 1}, {1, 2}}}};
  EXPECT_EQ(overlapping_pairs(flat, {0, 0}).size(), 1u);
}

TEST(Overlap, TheGridFindsExactlyTheOverlapsThatComparingAllPairsFinds) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> pos(0, 100), size(0.5, 6);
  std::vector<Triangle2> flat;
  std::vector<int> piece;
  for (int i = 0; i < 600; ++i) {
    Vec2 o{pos(rng), pos(rng)};
    Triangle2 t{o, o + Vec2{size(rng), 0.3 * size(rng)}, o + Vec2{0.2 * size(rng), size(rng)}};
    if (signed_area(t) < 0) std::swap(t[1], t[2]);
    flat.push_back(t);
    piece.push_back(i % 3);
  }
  flat.push_back({{{-50, -50}, {150, -40}, {-40, 150}}});  // one huge triangle spanning many cells
  piece.push_back(0);
  const double eps = overlap_tolerance(flat);
  std::vector<FacePair> brute;
  for (int a = 0; a < static_cast<int>(flat.size()); ++a)
    for (int b = a + 1; b < static_cast<int>(flat.size()); ++b)
      if (piece[a] == piece[b] && triangles_overlap(flat[a], flat[b], eps)) brute.push_back({a, b});
  EXPECT_GT(brute.size(), 100u);
  EXPECT_EQ(overlapping_pairs(flat, piece, eps), brute);
}
