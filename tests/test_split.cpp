// Splitting pieces too large for the paper: parts fit, cuts only grow, nothing else changes.
#include <gtest/gtest.h>

#include <algorithm>

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

namespace {
long sheets_with_pieces(const LayoutResult& r) {
  return std::count_if(r.sheet_stats.begin(), r.sheet_stats.end(),
                       [](const SheetStats& s) { return s.pieces > 0; });
}
}  // namespace

TEST(Split, SmallerPartsAreKeptWhenTheySaveASheet) {
  const auto& ex = test::unfolded_example("spot_350.obj", unfold::Method::Search);
  LayoutOptions o;
  o.size_mm = 150;
  const SplitResult largest = split_to_fit(ex.mesh, ex.unfolding, o, 1.0, SplitGrowth::Tree);
  const LayoutResult plain = layout_sheets(largest.unfolding, o);
  const SplitLayout chosen = split_and_layout(ex.mesh, ex.unfolding, o);
  EXPECT_TRUE(unfold::check_unfolding(ex.mesh, chosen.split.unfolding).empty());
  EXPECT_LT(sheets_with_pieces(chosen.layout), sheets_with_pieces(plain))
      << "spot at 150 mm: parts as large as A4 allows take " << sheets_with_pieces(plain) << " sheets";
  EXPECT_LE(chosen.split.unfolding.piece_count, largest.unfolding.piece_count + 8)
      << "a sheet saved is worth at most 8 more parts";
  for (std::size_t e = 0; e < ex.unfolding.edges.size(); ++e) {
    if (ex.unfolding.edges[e].cut) {
      EXPECT_TRUE(chosen.split.unfolding.edges[e].cut) << "an old cut was glued back";
    }
  }
}

TEST(Split, ALayoutThatCannotSaveASheetKeepsTheLargestParts) {
  const auto& ex = test::unfolded_example("penguin_500.obj", unfold::Method::Search);
  LayoutOptions o;
  o.size_mm = 150;
  const SplitResult largest = split_to_fit(ex.mesh, ex.unfolding, o, 1.0, SplitGrowth::Tree);
  const SplitLayout chosen = split_and_layout(ex.mesh, ex.unfolding, o);
  EXPECT_EQ(chosen.split.unfolding.piece_count, largest.unfolding.piece_count);
}

TEST(Split, EveryGrowthGivesPartsThatFitAtEveryRoomFraction) {
  const auto& ex = test::unfolded_example("fish_350.obj", unfold::Method::Search);
  LayoutOptions o;
  o.size_mm = 200;
  const double scale = 200 / ex.unfolding.model_extent;
  for (SplitGrowth growth : {SplitGrowth::Tree, SplitGrowth::Round, SplitGrowth::Fewest})
    for (double fraction : {1.0, 0.7, 0.5}) {
      const SplitResult split = split_to_fit(ex.mesh, ex.unfolding, o, fraction, growth);
      EXPECT_TRUE(unfold::check_unfolding(ex.mesh, split.unfolding).empty());
      EXPECT_EQ(split.unfolding.piece_count,
                ex.unfolding.piece_count - split.split_pieces + split.new_pieces);
      for (const auto& faces : split.unfolding.piece_faces()) {
        std::vector<Vec2> points;
        for (int f : faces)
          points.insert(points.end(), split.unfolding.flat[f].begin(), split.unfolding.flat[f].end());
        EXPECT_GE(max_fit_scale(points, piece_room_mm(o) * fraction), scale * (1 - 1e-9));
      }
    }
}
