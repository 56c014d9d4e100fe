// Direction arrows: both copies of a seam point the same way along the 3D edge.
#include <gtest/gtest.h>

#include "foldkit/layout/arrows.hpp"
#include "layout_fixtures.hpp"

using namespace foldkit;
using namespace foldkit::layout;

TEST(Arrows, BothArrowsOfASeamPointFromTheSameMeshVertexToTheSameOther) {
  const auto& ex = test::unfolded_example("spot_350.obj");
  const auto pieces = scaled_pieces(ex.unfolding, 1);
  const auto seams = find_seams(ex.unfolding, pieces);
  const auto arrows = seam_arrows(pieces, seams);
  ASSERT_EQ(arrows.size(), 2 * seams.size());
  // For each seam, the mesh vertex nearest each arrow's tail must be the same on both sides.
  std::vector<std::array<int, 2>> tail_vertex(seams.size(), {-1, -1});
  for (const Arrow& a : arrows) {
    const OutlineEdge& e =
        pieces[a.piece]
            .outline_mm[seams[a.seam.index()].sides[a.side].loop][seams[a.seam.index()].sides[a.side].index];
    const int va = ex.mesh.faces[e.face][e.corner], vb = ex.mesh.faces[e.face][(e.corner + 1) % 3];
    tail_vertex[a.seam.index()][a.side] = norm(a.tail_mm - e.a) < norm(a.tail_mm - e.b) ? va : vb;
    EXPECT_GT(cross(e.b - e.a, a.tip_mm - e.a), 0) << "arrows lie inside their piece";
  }
  for (std::size_t s = 0; s < seams.size(); ++s)
    EXPECT_EQ(tail_vertex[s][0], tail_vertex[s][1]) << "seam " << s;
}
