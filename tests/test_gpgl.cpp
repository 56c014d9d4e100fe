// GP-GL encoder: golden streams for the test device, and the framing rules of the Silhouette dialect.
#include <gtest/gtest.h>

#include "foldkit/devices/command_parser.hpp"
#include "foldkit/devices/gpgl.hpp"
#include "foldkit/devices/plan.hpp"
#include "golden.hpp"
#include "sample_sheets.hpp"

namespace foldkit::devices {
namespace {

const ProfileSet& profiles() {
  static const ProfileSet set = load_profiles(builtin_profiles_dir());
  return set;
}

const StrokeFont& font() {
  static const StrokeFont f = load_stroke_font(default_stroke_font_path());
  return f;
}

struct Case {
  std::string name;
  Sheet sheet;
  PlanOptions options;
};

Sheet square() {
  Sheet s;
  s.size_mm = {100, 100};
  s.paths.push_back(test::rect_path(PathRole::Cut, {10, 20}, {30, 40}, 0));
  return s;
}

std::vector<Case> cases() {
  PlanOptions labels;
  labels.draw_labels = true;
  labels.font = &font();
  PlanOptions overcut;
  overcut.overcut_mm = 1;
  Sheet marked = test::two_piece_sheet({15, 15});
  test::add_regmarks(marked, {2, 2}, {110, 60});
  PlanOptions regmarks;
  regmarks.regmarks = true;
  return {{"square", square(), {}},
          {"square_overcut", square(), overcut},
          {"two_pieces_with_labels", test::two_piece_sheet(), labels},
          {"regmarks", marked, regmarks}};
}

class GpglGolden : public ::testing::TestWithParam<std::size_t> {};

TEST_P(GpglGolden, MatchesTheReviewedStream) {
  const Case c = cases()[GetParam()];
  const Job job = plan_job(c.sheet, profiles().device("test"), profiles().medium("cardstock-220"), c.options);
  test::expect_golden(c.name + ".gpgl", encode_gpgl(job));
}

INSTANTIATE_TEST_SUITE_P(TestDevice, GpglGolden, ::testing::Range<std::size_t>(0, 4),
                         [](const auto& info) { return cases()[info.param].name; });

TEST(Gpgl, EndsEveryCommandWithEtxAndParsesStrictly) {
  const Job job =
      plan_job(test::two_piece_sheet(), profiles().device("cameo4"), profiles().medium("copy-80"));
  const std::string s = encode_gpgl(job);
  GpglParser parser;
  const auto commands = parser.feed(stream_bytes(s));
  EXPECT_NO_THROW(parser.finish());
  EXPECT_GT(commands.size(), 20u);
  EXPECT_EQ(s.back(), kEtx);
}

TEST(Gpgl, OpensWithTheHandshakeOfTheCameo3Recording) {
  const Job job = plan_job(square(), profiles().device("cameo3"), profiles().medium("copy-80"));
  const std::string s = encode_gpgl(job);
  // ESC 05, FG, ESC 04, TB71, FA as in the recorded session; then mat, portrait and the 12x12 window.
  EXPECT_EQ(s.substr(0, 15), std::string("\x1b\x05"
                                         "FG\x03\x1b\x04TB71\x03"
                                         "FA\x03",
                                         15));
  EXPECT_NE(s.find(std::string("TG1\x03"
                               "FN0\x03TB50,0\x03\\0,0\x03Z6096,6096\x03")),
            std::string::npos);
  EXPECT_NE(s.find(std::string("FC0,1,1\x03"
                               "FC18,1,1\x03")),
            std::string::npos);
}

TEST(Gpgl, SetsUpEachPassesHolderSpeedAndForceBeforeItsStrokes) {
  PlanOptions o;
  o.draw_labels = true;
  o.font = &font();
  const Job job =
      plan_job(test::two_piece_sheet(), profiles().device("test"), profiles().medium("cardstock-220"), o);
  ASSERT_GE(job.passes.size(), 3u);
  const std::string s = encode_gpgl(job);
  std::size_t from = 0;
  for (const Pass& p : job.passes) {
    const std::string setup = "J" + std::to_string(p.holder) + "\x03!" + std::to_string(p.speed_step) + "," +
                              std::to_string(p.holder) +
                              "\x03"
                              "FX" +
                              std::to_string(p.force_step) + "," + std::to_string(p.holder) + "\x03";
    const std::size_t at = s.find(setup, from);
    ASSERT_NE(at, std::string::npos) << pass_kind_name(p.kind);
    const std::size_t first_move = s.find("\x03M", at);
    EXPECT_LT(at, first_move);
    from = at + 1;
  }
}

TEST(Gpgl, SplitsLongStrokesOverSeveralDrawCommands) {
  Sheet s;
  s.size_mm = {100, 100};
  Path circle{PathRole::Cut, {}, true, 0, false};
  for (int i = 0; i < 200; ++i)
    circle.points_mm.push_back({50 + 30 * std::cos(i * 0.0314159), 50 + 30 * std::sin(i * 0.0314159)});
  s.paths.push_back(circle);
  const std::string out = encode_gpgl(plan_job(s, profiles().device("test"), profiles().medium("copy-80")));
  std::size_t draws = 0;
  for (std::size_t at = out.find("\x03"
                                 "D");
       at != std::string::npos; at = out.find("\x03"
                                              "D",
                                              at + 1))
    ++draws;
  EXPECT_EQ(draws, 4u);  // 200 points + return to start = 200 segments, 64 per command
}

TEST(Gpgl, SearchesTheRegistrationMarksBeforeAnyStroke) {
  Sheet marked = test::two_piece_sheet({15, 15});
  test::add_regmarks(marked, {2, 2}, {110, 60});
  PlanOptions o;
  o.regmarks = true;
  const std::string s =
      encode_gpgl(plan_job(marked, profiles().device("cameo4"), profiles().medium("copy-80"), o));
  const std::size_t search = s.find("TB123,");
  ASSERT_NE(search, std::string::npos);
  EXPECT_LT(search, s.find("\x03M"));
  // Extent 58 x 108 mm and origin 2,2 mm, feed axis first, 20 units/mm.
  EXPECT_NE(s.find("TB123,1160,2160,40,40\x03"), std::string::npos);
}

TEST(Gpgl, AbortTailLiftsTheToolAndEndsTheJob) {
  const std::string tail = gpgl_abort_tail();
  EXPECT_NE(tail.find("M0,0\x03"), std::string::npos);
  EXPECT_NE(tail.find("J0\x03"), std::string::npos);
  EXPECT_EQ(tail.back(), kEtx);
}

}  // namespace
}  // namespace foldkit::devices
