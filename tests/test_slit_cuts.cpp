// unfold/slit_cuts: parts cut open at their slits, one fold edge at a time.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "foldkit/geom/hull.hpp"
#include "foldkit/layout/layout.hpp"
#include "foldkit/unfold/parts.hpp"
#include "foldkit/unfold/slit_cuts.hpp"
#include "foldkit/unfold/slits.hpp"
#include "layout_fixtures.hpp"

using namespace foldkit;
using namespace foldkit::unfold;

namespace {

constexpr double kGapMm = 2.5;  // layout's narrowest tab and a little more (layout::narrow_slit_gap_mm)

// penguin_500 at 150 mm on A4, cut into parts as large as the sheet allows: parts that hold slits.
struct SplitPenguin {
  const test::UnfoldedExample& ex = test::unfolded_example("penguin_500.obj", Method::Search);
  PartOptions options;
  Unfolding parts;
  SplitPenguin() {
    options.room_mm = layout::piece_room_mm(layout::LayoutOptions{});
    options.mm_per_unit = 150 / ex.unfolding.model_extent;
    options.growth = PartGrowth::Tree;
    parts = split_into_parts(ex.mesh, ex.unfolding, options).unfolding;
    options.slit_gap_mm = kGapMm;
  }
};

int cut_edges(const Unfolding& u) {
  int n = 0;
  for (const UnfoldEdge& e : u.edges)
    n += e.cut && !e.boundary();
  return n;
}

}  // namespace

TEST(SlitCuts, NoPartHoldsBothSidesOfASlitAfterwardsAndEachPartCostsOneFoldEdge) {
  const SplitPenguin p;
  const double gap_units = kGapMm / p.options.mm_per_unit;
  ASSERT_GT(test::narrow_pairs_in_one_part(p.parts, p.parts, gap_units), 0)
      << "the penguin's parts hold slits";
  const Unfolding cut = cut_open_at_slits(p.ex.mesh, p.parts, p.options);
  EXPECT_EQ(check_unfolding(p.ex.mesh, cut), std::vector<std::string>{});
  EXPECT_EQ(test::narrow_pairs_in_one_part(p.parts, cut, gap_units), 0);
  EXPECT_GT(cut.piece_count, p.parts.piece_count);
  // A part's folds form a tree: every fold edge cut adds exactly one part, and every old cut stays.
  EXPECT_EQ(cut_edges(cut) - cut_edges(p.parts), cut.piece_count - p.parts.piece_count);
  for (std::size_t e = 0; e < cut.edges.size(); ++e)
    EXPECT_TRUE(!p.parts.edges[e].cut || cut.edges[e].cut) << "edge " << e;
}

TEST(SlitCuts, EveryNewPartLiesWithinOnePartItCameFrom) {
  const SplitPenguin p;
  const Unfolding cut = cut_open_at_slits(p.ex.mesh, p.parts, p.options);
  std::vector<int> came_from(static_cast<std::size_t>(cut.piece_count), -1);
  for (int f = 0; f < cut.num_faces(); ++f) {
    int& from = came_from[static_cast<std::size_t>(cut.piece_of_face[f])];
    if (from < 0) from = p.parts.piece_of_face[f];
    EXPECT_EQ(from, p.parts.piece_of_face[f]) << "face " << f;
  }
}

TEST(SlitCuts, FoldsInsideFlatFacesAndFoldsTheUserKeepsAreNeverCut) {
  const SplitPenguin p;
  Unfolding flat = p.parts;
  for (UnfoldEdge& e : flat.edges)
    e.inside_face = !e.cut;
  EXPECT_EQ(cut_open_at_slits(p.ex.mesh, flat, p.options).piece_count, p.parts.piece_count)
      << "every fold inside a flat face";
  PartOptions kept = p.options;
  kept.constraints.rule.assign(p.ex.mesh.num_edges(), EdgeRule::Free);
  for (int e = 0; e < p.ex.mesh.num_edges(); ++e)
    if (!p.parts.edges[e].cut) kept.constraints.rule[EdgeId(e)] = EdgeRule::MustFold;
  EXPECT_EQ(cut_open_at_slits(p.ex.mesh, p.parts, kept).piece_count, p.parts.piece_count)
      << "every fold kept by the user";
}

TEST(SlitCuts, WithoutAGapNothingIsCut) {
  SplitPenguin p;
  p.options.slit_gap_mm = 0;
  const Unfolding cut = cut_open_at_slits(p.ex.mesh, p.parts, p.options);
  EXPECT_EQ(cut.piece_count, p.parts.piece_count);
  EXPECT_EQ(cut_edges(cut), cut_edges(p.parts));
}

TEST(SlitCuts, OnlyThePartsAskedForAreCutOpen) {
  SplitPenguin p;
  const double gap_units = kGapMm / p.options.mm_per_unit;
  const std::vector<std::vector<int>> partners = narrow_seam_partners(p.parts, gap_units);
  std::vector<int> holding;  // parts holding a slit
  for (int f = 0; f < p.parts.num_faces(); ++f)
    if (!partners[f].empty()) holding.push_back(p.parts.piece_of_face[f]);
  std::sort(holding.begin(), holding.end());
  holding.erase(std::unique(holding.begin(), holding.end()), holding.end());
  ASSERT_GT(holding.size(), 1u) << "two parts or more hold slits";
  p.options.also_split = {holding.front()};
  const Unfolding cut = cut_open_at_slits(p.ex.mesh, p.parts, p.options);
  EXPECT_EQ(check_unfolding(p.ex.mesh, cut), std::vector<std::string>{});
  EXPECT_GT(cut.piece_count, p.parts.piece_count);
  for (std::size_t e = 0; e < cut.edges.size(); ++e) {
    if (p.parts.edges[e].cut || !cut.edges[e].cut) continue;
    for (int f : p.parts.edges[e].face) {
      if (f >= 0) {
        EXPECT_EQ(p.parts.piece_of_face[f], holding.front()) << "edge " << e << " cut in another part";
      }
    }
  }
  for (int f = 0; f < p.parts.num_faces(); ++f)
    for (int g : partners[f])
      if (p.parts.piece_of_face[f] != holding.front()) {
        EXPECT_EQ(cut.piece_of_face[f], cut.piece_of_face[g]) << "a slit of a part not asked for was parted";
      }
}
