// plan_job: which tool does what, pass order, order within a pass, device units, bounds checks,
// registration marks and statistics.
#include <gtest/gtest.h>

#include "device_fixtures.hpp"
#include "foldkit/devices/plan.hpp"
#include "foldkit/error.hpp"
#include "sample_sheets.hpp"
#include "test_paths.hpp"

namespace foldkit::devices {
namespace {

using foldkit::test::builtin_profiles;

using foldkit::test::pen_font;

const Pass* find_pass(const Job& job, PassKind kind) {
  for (const Pass& p : job.passes)
    if (p.kind == kind) return &p;
  return nullptr;
}

std::string plan_error(const Sheet& s, const std::string& device, const PlanOptions& o = {}) {
  try {
    (void)plan_job(s, builtin_profiles().device(device), builtin_profiles().medium("copy-80"), o);
  } catch (const DeviceError& e) {
    return e.what();
  }
  return "";
}

TEST(Plan, DrawsLabelsFirstScoresFoldsThenCutsOutlinesLast) {
  PlanOptions o;
  o.draw_labels = true;
  o.font = &pen_font();
  const Job job = plan_job(test::two_piece_sheet(), builtin_profiles().device("cameo4"),
                           builtin_profiles().medium("copy-80"), o);
  ASSERT_EQ(job.passes.size(), 3u);
  EXPECT_EQ(job.passes[0].kind, PassKind::Draw);
  EXPECT_EQ(job.passes[0].tool, ToolKind::Pen);
  EXPECT_EQ(job.passes[1].kind, PassKind::Score);
  EXPECT_EQ(job.passes[2].kind, PassKind::Cut);
  EXPECT_EQ(job.passes[2].tool, ToolKind::Blade);
  // The label path and the strokes of "A1" are drawn; hints are never drawn or cut.
  EXPECT_GT(job.passes[0].strokes.size(), 2u);
  for (const Pass& p : job.passes)
    for (const Stroke& s : p.strokes)
      EXPECT_NE(s.role, PathRole::Hint);
}

TEST(Plan, CutsAHoleBeforeTheOutlineAroundIt) {
  const Job job = plan_job(test::two_piece_sheet(), builtin_profiles().device("test"),
                           builtin_profiles().medium("copy-80"));
  const Pass* cut = find_pass(job, PassKind::Cut);
  ASSERT_NE(cut, nullptr);
  std::size_t hole = 99, outline = 99;
  for (std::size_t i = 0; i < cut->strokes.size(); ++i) {
    if (cut->strokes[i].source == 4) hole = i;
    if (cut->strokes[i].source == 1) outline = i;
  }
  ASSERT_LT(hole, cut->strokes.size());
  ASSERT_LT(outline, cut->strokes.size());
  EXPECT_LT(hole, outline);
}

TEST(Plan, UsesTheScoringToolWhenTheDeviceHasOne) {
  const Job job = plan_job(test::two_piece_sheet(), builtin_profiles().device("cameo4"),
                           builtin_profiles().medium("cardstock-220"));
  const Pass* score = find_pass(job, PassKind::Score);
  ASSERT_NE(score, nullptr);
  EXPECT_EQ(score->tool, ToolKind::Scorer);
  EXPECT_EQ(score->holder, 2);
  EXPECT_EQ(score->strokes.size(), 2u);
  EXPECT_TRUE(job.notes.empty());
}

TEST(Plan, FallsBackToAReducedForceBladeWhenThePenTakesTheScorersHolder) {
  PlanOptions o;
  o.draw_labels = true;
  o.font = &pen_font();
  const Job job = plan_job(test::two_piece_sheet(), builtin_profiles().device("cameo4"),
                           builtin_profiles().medium("cardstock-220"), o);
  const Pass* score = find_pass(job, PassKind::Score);
  const Pass* cut = find_pass(job, PassKind::Cut);
  ASSERT_NE(score, nullptr);
  ASSERT_NE(cut, nullptr);
  EXPECT_EQ(score->tool, ToolKind::Blade);
  EXPECT_LT(score->force_step, cut->force_step);
  ASSERT_EQ(job.notes.size(), 1u);
  EXPECT_NE(job.notes[0].find("reduced-force"), std::string::npos);
}

TEST(Plan, PerforatesFoldsOnThickCardWithoutAScorer) {
  const Sheet sheet = test::two_piece_sheet();
  const Job job =
      plan_job(sheet, builtin_profiles().device("portrait3"), builtin_profiles().medium("cardstock-300"));
  const Pass* perf = find_pass(job, PassKind::Perforate);
  ASSERT_NE(perf, nullptr);
  // The 30 mm mountain fold in 2.5 mm dashes with 1 mm gaps: 8 dashes, both ends left standing.
  std::size_t mountain_dashes = 0;
  for (const Stroke& s : perf->strokes) {
    if (s.role != PathRole::Mountain) continue;
    ++mountain_dashes;
    EXPECT_NEAR(stroke_length_mm(s, 20), 2.5, 0.1);
  }
  EXPECT_EQ(mountain_dashes, 8u);
  // Two passes through 300 gsm card.
  std::size_t cuts = 0;
  for (const Pass& p : job.passes)
    cuts += p.kind == PassKind::Cut;
  EXPECT_EQ(cuts, 2u);
}

TEST(Plan, LeavesFoldsAloneWhenAskedTo) {
  PlanOptions o;
  o.fold_method = FoldMethod::None;
  const Job job = plan_job(test::two_piece_sheet(), builtin_profiles().device("cameo4"),
                           builtin_profiles().medium("copy-80"), o);
  EXPECT_EQ(find_pass(job, PassKind::Score), nullptr);
  EXPECT_EQ(find_pass(job, PassKind::Perforate), nullptr);
}

TEST(Plan, ConvertsToDeviceUnitsInTheDevicesAxisOrder) {
  Sheet s;
  s.paths.push_back(test::line_path(PathRole::Cut, {10, 20}, {30, 20}));
  PlanOptions o;
  o.order = false;
  const Job job = plan_job(s, builtin_profiles().device("test"), builtin_profiles().medium("copy-80"), o);
  ASSERT_EQ(job.passes.size(), 1u);
  ASSERT_EQ(job.passes[0].strokes.size(), 1u);
  const auto& pts = job.passes[0].strokes[0].points;
  EXPECT_EQ(pts.front(), (DevicePoint{400, 200}));  // feed (y) first, 20 units per mm
  EXPECT_EQ(pts.back(), (DevicePoint{400, 600}));
  EXPECT_EQ(job.window_max, (DevicePoint{3000, 2400}));
}

TEST(Plan, AddsTheOvercutToClosedCuts) {
  Sheet s;
  s.paths.push_back(test::rect_path(PathRole::Cut, {10, 10}, {30, 30}));
  PlanOptions o;
  o.overcut_mm = 1.5;
  const Job job = plan_job(s, builtin_profiles().device("test"), builtin_profiles().medium("copy-80"), o);
  EXPECT_NEAR(stroke_length_mm(job.passes[0].strokes[0], 20), 81.5, 1e-9);
  EXPECT_NEAR(job.stats.cut_length_mm, 81.5, 1e-9);
}

TEST(Plan, NamesTheFirstStrokeOutsideTheCuttingArea) {
  Sheet s = test::two_piece_sheet();
  s.paths.push_back(test::rect_path(PathRole::Cut, {100, 10}, {130, 20}, 7));
  const std::string e = plan_error(s, "test");
  EXPECT_EQ(e,
            "stroke 4 of the cut pass (cut path 8 (piece 7)) leaves the cutting area of Test GP-GL plotter "
            "with mat test-mat at (130.00, 10.00) mm; allowed 0.00..120.00 x 0.00..150.00 mm");
}

TEST(Plan, ChecksDrawAndScoreStrokesToo) {
  Sheet s = test::two_piece_sheet();
  s.paths.push_back(test::line_path(PathRole::Valley, {10, 10}, {10, 151}, 0));
  EXPECT_NE(plan_error(s, "test").find("of the score pass (valley path 8 (piece 0))"), std::string::npos);
}

TEST(Plan, RejectsPointsThatAreNotNumbers) {
  Sheet s;
  s.paths.push_back(test::line_path(PathRole::Cut, {10, 10}, {std::nan(""), 10}));
  EXPECT_NE(plan_error(s, "test").find("not a number"), std::string::npos);
}

TEST(Plan, RejectsAnUnknownMat) {
  PlanOptions o;
  o.mat = "24x24";
  EXPECT_NE(
      plan_error(test::two_piece_sheet(), "cameo4", o).find("no mat \"24x24\" (known: 12x12, 12x24, none)"),
      std::string::npos);
}

TEST(Plan, PlacesPrintAndCutJobsRelativeToTheTopLeftMark) {
  Sheet s = test::two_piece_sheet({20, 20});
  test::add_regmarks(s, {5, 8}, {110, 60});
  PlanOptions o;
  o.regmarks = true;
  o.order = false;
  const Job job = plan_job(s, builtin_profiles().device("test"), builtin_profiles().medium("copy-80"), o);
  ASSERT_TRUE(job.regmarks.has_value());
  EXPECT_EQ(job.regmarks->origin_a, 160);  // 8 mm down the feed
  EXPECT_EQ(job.regmarks->origin_b, 100);  // 5 mm across
  EXPECT_EQ(job.regmarks->extent_a, 1040);
  EXPECT_EQ(job.regmarks->extent_b, 2100);
  // The second piece's outline starts at page (70, 20): (12, 65) mm from the mark.
  const Pass* cut = find_pass(job, PassKind::Cut);
  ASSERT_NE(cut, nullptr);
  EXPECT_EQ(cut->strokes[0].points[0], (DevicePoint{240, 1300}));
  // The window is the machine's, set before the search; the search starts 10 mm before the mark
  // (clamped at the machine's edge) and describes the printed marks (20 mm arms, 0.5 mm lines).
  EXPECT_EQ(job.window_min, (DevicePoint{0, 0}));
  EXPECT_EQ(job.regmarks->start_a, 0);
  EXPECT_EQ(job.regmarks->start_b, 0);
  EXPECT_EQ(job.regmarks->arm_length, 400);
  EXPECT_EQ(job.regmarks->stroke, 10);
}

TEST(Plan, RefusesRegistrationMarksOnADeviceWithoutASensorOrASheetWithoutMarks) {
  PlanOptions o;
  o.regmarks = true;
  EXPECT_NE(plan_error(test::two_piece_sheet(), "ce6000", o).find("cannot search registration marks"),
            std::string::npos);
  EXPECT_NE(plan_error(test::two_piece_sheet(), "cameo4", o).find("no registration marks"),
            std::string::npos);
}

TEST(Plan, OrderingNeverIncreasesPenUpTravel) {
  for (const char* id : {"cameo4", "roland-gx24", "generic-hpgl"}) {
    const Job job = plan_job(test::two_piece_sheet(), builtin_profiles().device(id),
                             builtin_profiles().medium("copy-80"));
    EXPECT_LE(job.stats.travel_after_mm, job.stats.travel_before_mm + 1e-9) << id;
    EXPECT_GT(job.stats.estimated_s, 0) << id;
  }
  PlanOptions unordered;
  unordered.order = false;
  const Job job = plan_job(test::two_piece_sheet(), builtin_profiles().device("cameo4"),
                           builtin_profiles().medium("copy-80"), unordered);
  EXPECT_DOUBLE_EQ(job.stats.travel_after_mm, job.stats.travel_before_mm);
}

TEST(Plan, CountsEveryStrokeAndItsLengthInTheStatistics) {
  const Job job = plan_job(test::two_piece_sheet(), builtin_profiles().device("test"),
                           builtin_profiles().medium("copy-80"));
  std::size_t strokes = 0;
  double length = 0;
  for (const Pass& p : job.passes) {
    strokes += p.strokes.size();
    for (const Stroke& s : p.strokes)
      length += stroke_length_mm(s, job.units_per_mm);
  }
  EXPECT_EQ(job.stats.strokes, strokes);
  EXPECT_NEAR(job.stats.cut_length_mm, length, 1e-9);
  // Outlines 2 x 140 + hole 20 + folds 30 + 40 (no overcut by default).
  EXPECT_NEAR(length, 370, 1e-9);
}

}  // namespace
TEST(Plan, ThePenDrawsPartLettersBesideTheSeamNumbers) {
  Sheet sheet = test::two_piece_sheet();
  const Vec2 at = sheet.texts.front().at_mm + Vec2{0, -6};
  sheet.texts.push_back({"B", at, 6, 0, PathRole::Piece, 0});
  PlanOptions o;
  o.draw_labels = true;
  o.font = &pen_font();
  const Job job =
      plan_job(sheet, builtin_profiles().device("cameo4"), builtin_profiles().medium("copy-80"), o);
  const Pass* draw = find_pass(job, PassKind::Draw);
  ASSERT_NE(draw, nullptr);
  int letter_strokes = 0;
  for (const Stroke& s : draw->strokes)
    letter_strokes += s.role == PathRole::Piece;
  EXPECT_GE(letter_strokes, 2) << "a B takes its upright and its bowls";
}

}  // namespace foldkit::devices
