// Piece outlines: closed loops of cut edges with the piece on their left, and the seams found on them.
#include <gtest/gtest.h>

#include <cmath>

#include "foldkit/layout/outline.hpp"
#include "foldkit/layout/polygon.hpp"
#include "layout_fixtures.hpp"

using namespace foldkit;
using namespace foldkit::layout;

TEST(Outline, ATetrahedronCutAtOneVertexIsOneTriangleOfSixUnitEdges) {
  const auto ex = test::tetrahedron();
  ASSERT_EQ(ex.unfolding.piece_count, 1);
  const auto pieces = scaled_pieces(ex.unfolding, 10);
  ASSERT_EQ(pieces.size(), 1u);
  ASSERT_EQ(pieces[0].outline_mm.size(), 1u);
  const OutlineLoop& loop = pieces[0].outline_mm[0];
  ASSERT_EQ(loop.size(), 6u);
  Polygon poly;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    EXPECT_NEAR(norm(loop[i].b - loop[i].a), 10, 1e-9);
    EXPECT_LT(norm(loop[i].b - loop[(i + 1) % loop.size()].a), 1e-9) << "the loop is closed";
    poly.push_back(loop[i].a);
  }
  // Four unit triangles (scaled by 10) laid out as one big triangle, counter-clockwise.
  EXPECT_NEAR(signed_area(poly), 4 * std::sqrt(3.0) / 4 * 100, 1e-6);
  EXPECT_NEAR(pieces[0].area_mm2, signed_area(poly), 1e-6);
  const auto seams = find_seams(ex.unfolding, pieces);
  ASSERT_EQ(seams.size(), 3u);
  for (const Seam& s : seams)
    for (const SeamSide& side : s.sides)
      EXPECT_EQ(loop[side.index].edge, s.edge);
}

TEST(Outline, EveryPieceOfARealUnfoldingHasOneClosedLoopEnclosingItsArea) {
  for (const char* name : {"spot_350.obj", "penguin_500.obj"}) {
    const auto& ex = test::unfolded_example(name);
    const auto pieces = scaled_pieces(ex.unfolding, 1.0);
    int sides = 0;
    for (const ScaledPiece& p : pieces) {
      ASSERT_EQ(p.outline_mm.size(), 1u) << name << " piece " << p.index << " is a disk";
      Polygon poly;
      for (const OutlineEdge& e : p.outline_mm[0]) {
        poly.push_back(e.a);
        EXPECT_TRUE(ex.unfolding.edges[e.edge].cut);
      }
      sides += static_cast<int>(p.outline_mm[0].size());
      EXPECT_NEAR(signed_area(poly), p.area_mm2, 1e-9 * std::max(1.0, p.area_mm2))
          << name << " piece " << p.index;
    }
    // Each glued seam shows up twice on the outlines, each boundary edge once.
    int expected = 0;
    for (const auto& e : ex.unfolding.edges)
      expected += e.cut ? (e.boundary() ? 1 : 2) : 0;
    EXPECT_EQ(sides, expected) << name;
    for (const Seam& s : find_seams(ex.unfolding, pieces))
      for (const SeamSide& side : s.sides)
        ASSERT_GE(side.piece, 0) << name << ": seam " << s.edge << " lost a side";
  }
}
