// Splitting pieces too large for the paper: parts fit, cuts only grow, nothing else changes.
#include <gtest/gtest.h>

#include "foldkit/layout/outline.hpp"
#include "foldkit/layout/scale.hpp"
#include "foldkit/layout/split.hpp"
#include "layout_fixtures.hpp"

using namespace foldkit;
using namespace foldkit::layout;

TEST(Split, AOnePieceUnfoldingTooLargeForA4IsCutIntoPartsThatFitAndLayOut) {
  const auto& ex = test::unfolded_example("spot_350.obj", unfold::Method::Search);
  LayoutOptions o;
  o.size_mm = 160;
  const SplitResult split = split_to_fit(ex.mesh, ex.unfolding, o);
  if (ex.unfolding.piece_count == 1) {
    EXPECT_EQ(split.split_pieces, 1);
  }
  ASSERT_GT(split.split_pieces, 0) << "spot at 160 mm does not fit A4 in one piece";
  const unfold::Unfolding& u = split.unfolding;
  EXPECT_TRUE(unfold::check_unfolding(ex.mesh, u).empty());
  EXPECT_GT(u.piece_count, ex.unfolding.piece_count);
  for (std::size_t e = 0; e < u.edges.size(); ++e) {
    if (ex.unfolding.edges[e].cut) {
      EXPECT_TRUE(u.edges[e].cut) << "an old cut was glued back";
    }
  }
  const double scale = 160 / u.model_extent;
  for (const auto& faces : u.piece_faces()) {
    std::vector<Vec2> points;
    for (int f : faces)
      points.insert(points.end(), u.flat[f].begin(), u.flat[f].end());
    EXPECT_GE(max_fit_scale(points, piece_room_mm(o)), scale);
  }
  EXPECT_NO_THROW(layout_sheets(u, o));
}

TEST(Split, PiecesThatFitAndFitModeAreLeftAlone) {
  const auto& ex = test::unfolded_example("bob_350.obj");
  LayoutOptions o;
  o.size_mm = 120;
  const SplitResult small = split_to_fit(ex.mesh, ex.unfolding, o);
  EXPECT_EQ(small.split_pieces, 0);
  EXPECT_EQ(small.unfolding.piece_count, ex.unfolding.piece_count);
  o.size_mm.reset();
  o.fit = true;
  const auto& one = test::unfolded_example("bob_350.obj", unfold::Method::Search);
  EXPECT_EQ(split_to_fit(one.mesh, one.unfolding, o).split_pieces, 0);
}
