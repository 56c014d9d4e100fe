// The pipeline's choice above unfold and layout: where the parts chosen from the default unfolding
// leave labels unclear or seams without a tab, the mesh is unfolded again other ways (seams where labels
// have room, then both preferences from the next seed) while the flaws stay, and the best prints.
#include <gtest/gtest.h>

#include <utility>

#include "choose_parts.hpp"
#include "foldkit/layout/layout.hpp"
#include "foldkit/unfold/mesh_io.hpp"
#include "pipeline.hpp"
#include "print_cuts.hpp"
#include "test_paths.hpp"

using namespace foldkit;

namespace {

layout::LayoutOptions at_150_mm() {
  layout::LayoutOptions o;
  o.size_mm = 150;
  return o;
}

// A mesh unfolded as `make` unfolds it at the size of `o` (cuts_for_print), one thread.
cli::UnfoldRun unfolded_for_print(const std::string& name, const layout::LayoutOptions& o) {
  cli::UnfoldRun run;
  run.loaded = unfold::load_mesh(test::example_mesh(name));
  run.options.threads = 1;
  run.options.cuts = cli::cuts_for_print(run.loaded.mesh, o, run.options.cuts);
  run.result = unfold::unfold_mesh(run.loaded.mesh, run.options);
  return run;
}

// The layout of the parts chosen from the run's own unfolding, and nothing else tried.
layout::LayoutResult first_choice(const cli::UnfoldRun& run, const layout::LayoutOptions& o) {
  cli::ChosenParts parts = cli::choose_parts(run.loaded.mesh, run.result.unfolding, o,
                                             cli::part_options_of(run.loaded.mesh, run.options));
  return parts.layout ? std::move(*parts.layout) : layout::layout_sheets(parts.unfolding, o);
}

}  // namespace

TEST(Pipeline, UnclearLabelsGetASecondUnfoldingWithSeamsWhereLabelsHaveRoomKeptWhenItHasFewerFlaws) {
  // fish_350 at 110 mm: its first unfolding leaves labels without a clear spot even on leaders (22
  // flaws); the second one's seams run where they have room (11).
  layout::LayoutOptions o = at_150_mm();
  o.size_mm = 110;
  cli::UnfoldRun run = unfolded_for_print("fish_350.obj", o);
  const layout::LayoutResult first = first_choice(run, o);
  ASSERT_GT(cli::flaws(first), cli::kFewFlawsShare * first.label_audit.labels)
      << "fish_350 at 110 mm leaves some labels unclear";
  const std::optional<layout::LayoutResult> chosen = cli::choose_and_note_parts(run, o);
  ASSERT_TRUE(chosen.has_value());
  EXPECT_EQ(run.options.cuts.prefer, unfold::SeamPreference::Balanced) << "the second unfolding printed";
  EXPECT_LE(chosen->sheets.size(), first.sheets.size());
  EXPECT_LT(cli::flaws(*chosen), cli::flaws(first));
  EXPECT_LT(chosen->label_audit.unclear(), first.label_audit.unclear());
  EXPECT_EQ(run.result.unfolding.piece_count, chosen->placements.size())
      << "the parts laid out are the run's";
}

TEST(Pipeline, ALayoutWithFewFlawsKeepsTheDefaultUnfolding) {
  const layout::LayoutOptions o = at_150_mm();
  cli::UnfoldRun run = unfolded_for_print("bob_350.obj", o);
  const layout::LayoutResult first = first_choice(run, o);
  ASSERT_LE(cli::flaws(first), cli::kFewFlawsShare * first.label_audit.labels);
  const std::optional<layout::LayoutResult> chosen = cli::choose_and_note_parts(run, o);
  EXPECT_EQ(run.options.cuts.prefer, unfold::SeamPreference::Short);
  ASSERT_TRUE(chosen.has_value());
  EXPECT_EQ(chosen->sheets.size(), first.sheets.size());
  EXPECT_EQ(cli::flaws(*chosen), cli::flaws(first));
}

TEST(Pipeline, WhereBothPreferencesLeaveLabelsUnclearTheNextSeedsUnfoldingPrintsWhenClearer) {
  // bob_350 at 85 mm: the default unfolding leaves 18 flaws, the seams with room more than the walk
  // from the next seed finds an unfolding with (8).
  layout::LayoutOptions o = at_150_mm();
  o.size_mm = 85;
  cli::UnfoldRun run = unfolded_for_print("bob_350.obj", o);
  const layout::LayoutResult first = first_choice(run, o);
  cli::UnfoldRun with_room;
  with_room.loaded = run.loaded;
  with_room.options = run.options;
  with_room.options.cuts.prefer = unfold::SeamPreference::Balanced;
  with_room.options.search.prefer_weighted_ties = true;
  with_room.result = unfold::unfold_mesh(with_room.loaded.mesh, with_room.options);
  const layout::LayoutResult second = first_choice(with_room, o);
  const std::optional<layout::LayoutResult> chosen = cli::choose_and_note_parts(run, o);
  ASSERT_TRUE(chosen.has_value());
  EXPECT_EQ(run.options.seed, 2u) << "an unfolding from the next seed printed";
  EXPECT_LE(chosen->sheets.size(), std::min(first.sheets.size(), second.sheets.size()));
  EXPECT_LT(cli::flaws(*chosen), cli::flaws(first));
  EXPECT_LT(cli::flaws(*chosen), cli::flaws(second));
  EXPECT_EQ(run.result.unfolding.piece_count, chosen->placements.size())
      << "the parts laid out are the run's";
}

TEST(Pipeline, PartsCloseUpOnlyWhereNoColourBleedsIntoTheGap) {
  // Spot with its texture prints in colour, and its bleed (1 mm past every cut line by default) needs
  // the whole 2 mm between parts; printed white, or a white model, the gap may close to 1 mm.
  cli::ChooseOptions closer;
  closer.closer_spacing_mm = cli::kCloserSpacing_mm;
  const unfold::Mesh textured =
      unfold::load_mesh(test::example_mesh("spot_textured/spot_triangulated.obj")).mesh;
  const unfold::Mesh white = unfold::load_mesh(test::example_mesh("spot_128.obj")).mesh;
  const layout::FillOptions fills;
  EXPECT_EQ(cli::bleed_room(closer, textured, fills).closer_spacing_mm, layout::fill_spacing_mm(fills));
  EXPECT_GE(layout::fill_spacing_mm(fills), layout::PackOptions{}.spacing_mm);
  EXPECT_EQ(cli::bleed_room(closer, textured, std::nullopt).closer_spacing_mm, cli::kCloserSpacing_mm);
  EXPECT_EQ(cli::bleed_room(closer, white, fills).closer_spacing_mm, cli::kCloserSpacing_mm);
  EXPECT_FALSE(cli::bleed_room({}, textured, fills).closer_spacing_mm.has_value());
}

namespace {

// Whether choosing the parts of `name` at `size_mm` unfolds it another way (its progress says so).
bool tries_another_unfolding(const std::string& name, double size_mm) {
  layout::LayoutOptions o = at_150_mm();
  o.size_mm = size_mm;
  bool another = false;
  o.progress = [&another](const layout::LayoutProgress& p) {
    another = another || p.stage.rfind("another unfolding", 0) == 0;
  };
  cli::UnfoldRun run = unfolded_for_print(name, o);
  const layout::LayoutResult first = first_choice(run, o);
  EXPECT_GT(cli::flaws(first), cli::kFewFlawsShare * first.label_audit.labels) << name << " has flaws";
  cli::choose_and_note_parts(run, o);
  return another;
}

}  // namespace

TEST(Pipeline, WhereOnlyTheSizeCanMendTheLabelsNoOtherUnfoldingIsTried) {
  // spot_128 at 30 mm: faces of a few millimetres, most labels unclear whatever the seams.
  layout::LayoutOptions o = at_150_mm();
  o.size_mm = 30;
  const layout::LayoutResult first = first_choice(unfolded_for_print("spot_128.obj", o), o);
  ASSERT_GT(cli::flaws(first), cli::kOnlyTheSizeMendsShare * first.label_audit.labels);
  EXPECT_FALSE(tries_another_unfolding("spot_128.obj", 30));
  // fish_350 at 110 mm, a few labels unclear: the other unfoldings are tried.
  EXPECT_TRUE(tries_another_unfolding("fish_350.obj", 110));
}
