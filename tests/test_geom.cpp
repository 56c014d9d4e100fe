#include <gtest/gtest.h>

#include "foldkit/geom/predicates.hpp"

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

TEST(SegmentsCross, TouchingAtAnEndpointIsNotACrossing) {
  EXPECT_FALSE(segments_cross({0, 0}, {1, 0}, {1, 0}, {1, 1}, 1e-12));
  EXPECT_TRUE(segments_cross({0, 0}, {2, 0}, {1, -1}, {1, 1}, 1e-12));
}
