// HP-GL encoder: golden streams for the HP-GL test device, framing, and Debian's hp2xx as an independent
// reader of what we send.
#include <array>
#include <cstdio>
#include <fstream>
#include <regex>

#include <algorithm>

#include <gtest/gtest.h>

#include "device_fixtures.hpp"
#include "foldkit/devices/command_parser.hpp"
#include "foldkit/devices/hpgl.hpp"
#include "foldkit/devices/plan.hpp"
#include "golden.hpp"
#include "sample_sheets.hpp"
#include "test_paths.hpp"

namespace foldkit::devices {
namespace {

using foldkit::test::builtin_profiles;

using foldkit::test::pen_font;

Sheet square() {
  Sheet s;
  s.size_mm = {100, 100};
  s.paths.push_back(test::rect_path(PathRole::Cut, {10, 20}, {30, 40}, 0));
  return s;
}

struct Case {
  std::string name;
  Sheet sheet;
  PlanOptions options;
};

std::vector<Case> cases() {
  PlanOptions labels;
  labels.draw_labels = true;
  labels.font = &pen_font();
  return {{"square", square(), {}}, {"two_pieces_with_labels", test::two_piece_sheet(), labels}};
}

class HpglGolden : public ::testing::TestWithParam<std::size_t> {};

TEST_P(HpglGolden, MatchesTheReviewedStream) {
  const Case c = cases()[GetParam()];
  const Job job = plan_job(c.sheet, builtin_profiles().device("test-hpgl"),
                           builtin_profiles().medium("cardstock-220"), c.options);
  test::expect_golden(c.name + ".plt", encode_hpgl(job));
}

INSTANTIATE_TEST_SUITE_P(TestDevice, HpglGolden, ::testing::Range<std::size_t>(0, 2),
                         [](const auto& info) { return cases()[info.param].name; });

TEST(Hpgl, InitialisesSelectsTheToolAndEndsWithIn) {
  const std::string s = encode_hpgl(
      plan_job(square(), builtin_profiles().device("test-hpgl"), builtin_profiles().medium("copy-80")));
  EXPECT_EQ(s.substr(0, 6), "IN;PA;");
  EXPECT_NE(s.find("SP1;VS10;FS8;"), std::string::npos);  // 100 mm/s, 80 gf at 10 gf per step
  EXPECT_EQ(s.substr(s.size() - 3), "IN;");
  HpglParser parser;
  EXPECT_GT(parser.feed(stream_bytes(s)).size(), 6u);
  EXPECT_NO_THROW(parser.finish());
}

TEST(Hpgl, FlipsYForABottomLeftOrigin) {
  // The test device's origin is bottom left with y up: page y 20 and 40 on a 150 mm area are device y
  // 130 and 110 mm; the cut starts at the corner nearest the origin, page (10, 40).
  const std::string s = encode_hpgl(
      plan_job(square(), builtin_profiles().device("test-hpgl"), builtin_profiles().medium("copy-80")));
  EXPECT_NE(s.find("PU400,4400;PD400,5200;"), std::string::npos) << s;
}

TEST(Hpgl, LeavesOutTheForceCommandForDevicesThatTakeItFromThePanel) {
  DeviceProfile d = builtin_profiles().device("test-hpgl");
  d.hpgl_force_command.clear();
  const std::string s = encode_hpgl(plan_job(square(), d, builtin_profiles().medium("copy-80")));
  EXPECT_EQ(s.find("FS"), std::string::npos);
}

// Runs hp2xx on `stream` and returns its stderr, or nullopt when hp2xx is not installed.
std::optional<std::string> run_hp2xx(const std::string& stream, const std::filesystem::path& dir) {
  if (std::system("command -v hp2xx >/dev/null 2>&1") != 0) return std::nullopt;
  const auto in = dir / "job.plt", out = dir / "job.svg", err = dir / "stderr.txt";
  std::ofstream(in, std::ios::binary) << stream;
  const std::string cmd =
      "hp2xx -t -m svg -f '" + out.string() + "' '" + in.string() + "' 2>'" + err.string() + "'";
  if (std::system(cmd.c_str()) != 0) return std::string("hp2xx failed");
  return test::slurp(err);
}

TEST(Hpgl, RendersWithHp2xxWithNoIgnoredCommands) {
  const auto dir = test::temp_dir("hpgl");
  for (const char* id : {"generic-hpgl", "roland-gx24", "test-hpgl"}) {
    PlanOptions o;
    DeviceProfile d = builtin_profiles().device(id);
    o.draw_labels = d.tool(ToolKind::Pen) != nullptr;
    o.font = &pen_font();
    // hp2xx renders for pen plotters and counts the cutter-only FS (force) as ignored; everything else
    // we send must be understood.
    d.hpgl_force_command.clear();
    const Job job = plan_job(test::two_piece_sheet(), d, builtin_profiles().medium("cardstock-220"), o);
    const auto err = run_hp2xx(encode_hpgl(job), dir);
    if (!err) GTEST_SKIP() << "hp2xx is not installed";
    std::smatch m;
    const std::regex ignored("HPGL command\\(s\\) ignored: ([0-9]+)");
    ASSERT_TRUE(std::regex_search(*err, m, ignored)) << *err;
    EXPECT_EQ(m[1], "0") << id << ": " << *err;
    EXPECT_TRUE(std::regex_search(*err, std::regex("Unexpected event\\(s\\): +0"))) << id << ": " << *err;
    EXPECT_EQ(err->find("hp2xx failed"), std::string::npos) << *err;
    EXPECT_TRUE(std::filesystem::file_size(dir / "job.svg") > 200) << id;
  }
}

TEST(Hpgl, Hp2xxCountsOnlyTheForceCommandsAsIgnored) {
  const auto dir = test::temp_dir("hpgl-fs");
  const Job job = plan_job(test::two_piece_sheet(), builtin_profiles().device("test-hpgl"),
                           builtin_profiles().medium("cardstock-220"));
  const std::string s = encode_hpgl(job);
  const auto err = run_hp2xx(s, dir);
  if (!err) GTEST_SKIP() << "hp2xx is not installed";
  std::size_t fs = 0;
  for (std::size_t at = s.find(";FS"); at != std::string::npos; at = s.find(";FS", at + 1))
    ++fs;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(*err, m, std::regex("HPGL command\\(s\\) ignored: ([0-9]+)"))) << *err;
  EXPECT_EQ(std::stoul(m[1]), fs);
}

// --- The Roland GX-24 against the Roland writer ([FM] mod_Roland_vinyl.js, docs/plotter-protocols.md 3) --

Sheet a4_corner_square() {
  Sheet s;
  s.size_mm = {210, 297};
  s.paths.push_back(test::rect_path(PathRole::Cut, {10, 10}, {30, 30}, 0));
  return s;
}

TEST(HpglRoland, SetsForceWithRolandsBangFsAndSpeedWithVs) {
  // [FM]: PA;PA;!ST1;!FS<force>;VS<v>; the GX-24 reads !FS, not HP-GL's FS.
  PlanOptions o;
  o.fold_method = FoldMethod::None;
  const std::string s = encode_hpgl(plan_job(a4_corner_square(), builtin_profiles().device("roland-gx24"),
                                             builtin_profiles().medium("copy-80"), o));
  EXPECT_EQ(s.substr(0, s.find("PU")), "IN;PA;SP1;VS10;!FS80;");
  EXPECT_EQ(s.find(";FS"), std::string::npos);
  EXPECT_EQ(s.substr(s.size() - 10), "PU;SP0;IN;");
}

TEST(HpglRoland, PutsTheCutOnTheSheetAtTheFrontRightOrigin) {
  // The origin is the loaded sheet's corner: a 20 mm square 10 mm from the sheet's top-left corner lies
  // 10..30 mm from the origin on both axes (40 PLU/mm), not 554..574 mm across the 584 mm carriage.
  PlanOptions o;
  o.fold_method = FoldMethod::None;
  o.order = false;
  const Job job = plan_job(a4_corner_square(), builtin_profiles().device("roland-gx24"),
                           builtin_profiles().medium("copy-80"), o);
  ASSERT_EQ(job.passes.size(), 1u);
  for (const DevicePoint& p : job.passes[0].strokes[0].points) {
    EXPECT_GE(p.a, 400);
    EXPECT_LE(p.a, 1200);
    EXPECT_GE(p.b, 400);
    EXPECT_LE(p.b, 1200);
  }
}

TEST(Hpgl, SendsOnePointPerPenDown) {
  const std::string s = encode_hpgl(plan_job(test::two_piece_sheet(), builtin_profiles().device("test-hpgl"),
                                             builtin_profiles().medium("copy-80")));
  for (std::size_t at = s.find("PD"); at != std::string::npos; at = s.find("PD", at + 1)) {
    const std::string cmd = s.substr(at, s.find(';', at) - at);
    EXPECT_EQ(std::count(cmd.begin(), cmd.end(), ','), 1) << cmd;
  }
}

}  // namespace
}  // namespace foldkit::devices
