// The machines' own models: where a job lands on each, and a simulated device that disagrees with a
// wrong profile instead of trusting it (TG codes, origin, commands, marks).
#include <gtest/gtest.h>

#include "device_fixtures.hpp"
#include "foldkit/devices/device_model.hpp"
#include "foldkit/devices/gpgl.hpp"
#include "foldkit/devices/hpgl.hpp"
#include "foldkit/devices/plan.hpp"
#include "foldkit/devices/send.hpp"
#include "foldkit/devices/simulated_device.hpp"
#include "foldkit/devices/stroke_font.hpp"
#include "foldkit/error.hpp"
#include "sample_sheets.hpp"
#include "test_paths.hpp"

namespace foldkit::devices {
namespace {

using foldkit::test::builtin_profiles;

const MediaProfile& paper() {
  return builtin_profiles().medium("copy-80");
}

constexpr Vec2 kA4{210, 297};

// A4 with a 1 mm square whose corner is the sheet's top-left mark position, 10 mm in from both edges.
Sheet a4_mark_corner() {
  Sheet s;
  s.size_mm = kA4;
  s.paths.push_back(test::rect_path(PathRole::Cut, {10, 10}, {11, 11}, 0));
  return s;
}

std::string encode(const Job& job) {
  return job.protocol == Protocol::Gpgl ? encode_gpgl(job) : encode_hpgl(job);
}

// Sends the job to the simulated machine with an A4 sheet loaded; "" when it passes, else the error.
std::string dry_run(const DeviceProfile& planner, const Sheet& sheet, const PlanOptions& o,
                    SimOptions so = {}) {
  try {
    const Job job = plan_job(sheet, planner, paper(), o);
    so.sheet_mm = sheet.size_mm;
    SimulatedDevice dev(planner, so);
    SendOptions send;
    send.protocol = job.protocol;
    send.poll_interval = std::chrono::milliseconds(1);
    send_job(stream_bytes(encode(job)), dev, send);
    dev.close();
    if (!dev.marks_problem().empty()) return dev.marks_problem();
    return "";
  } catch (const Error& e) {
    return e.what();
  }
}

struct Landing {
  const char* device;
  DevicePoint at;  // where page (10, 10) mm lands, device units in the device's order
};

class TopLeftMark : public ::testing::TestWithParam<Landing> {};

TEST_P(TopLeftMark, LandsWhereThatMachinePutsTheSheetsTopLeftCorner) {
  const Landing l = GetParam();
  PlanOptions o;
  o.fold_method = FoldMethod::None;
  o.order = false;
  const Job job = plan_job(a4_mark_corner(), builtin_profiles().device(l.device), paper(), o);
  ASSERT_EQ(job.passes.size(), 1u);
  EXPECT_EQ(job.passes[0].strokes[0].points[0], l.at) << l.device;
}

// Silhouettes: a = feed from the mat's top edge, b = carriage from its left, 20 SU/mm [IS]. Roll cutters
// (CE6000 at 10 units/mm [CE], GX-24 at 40 PLU/mm [FM]): the sheet's corner sits at the origin.
// Generic HP-GL: x right, y up from the bottom of the A4 mat (297 mm).
INSTANTIATE_TEST_SUITE_P(Profiles, TopLeftMark,
                         ::testing::Values(Landing{"cameo3", {200, 200}}, Landing{"cameo4", {200, 200}},
                                           Landing{"cameo5", {200, 200}}, Landing{"portrait3", {200, 200}},
                                           Landing{"curio", {200, 200}}, Landing{"ce6000", {100, 100}},
                                           Landing{"roland-gx24", {400, 400}},
                                           Landing{"generic-hpgl", {400, 11480}}),
                         [](const auto& info) {
                           std::string n = info.param.device;
                           for (char& c : n)
                             if (c == '-') c = '_';
                           return n;
                         });

TEST(MachineModel, IsBuiltInForEveryRealProfileAndTakenFromTheProfileOtherwise) {
  for (const char* id : {"cameo3", "cameo4", "cameo5", "portrait3", "curio", "ce6000", "roland-gx24"})
    EXPECT_FALSE(machine_model(builtin_profiles().device(id)).from_profile) << id;
  EXPECT_TRUE(machine_model(builtin_profiles().device("generic-hpgl")).from_profile);
  EXPECT_TRUE(machine_model(builtin_profiles().device("test")).from_profile);
}

TEST(MachineModel, PassesEveryJobFoldkitWritesForEveryProfile) {
  PlanOptions o;
  o.fold_method = FoldMethod::None;
  for (const DeviceProfile& d : builtin_profiles().devices) {
    Sheet s = d.area_width_mm >= kA4.x ? a4_mark_corner() : test::two_piece_sheet();
    EXPECT_EQ(dry_run(d, s, o), "") << d.id;
  }
}

using foldkit::test::pen_font;

TEST(MachineModel, PassesEveryProfilesFullJobWithLabelsFoldsAndMarks) {
  // Everything a cut writes: labels with the pen where there is one, folds by the profile's own method,
  // and on a machine with a mark sensor the printed marks searched; the sheet fits every bed.
  for (const DeviceProfile& d : builtin_profiles().devices) {
    Sheet s = test::two_piece_sheet({15, 15});  // 120 x 60 mm: the test device's bed is 120 mm wide
    PlanOptions o;
    o.draw_labels = d.tool(ToolKind::Pen) != nullptr;
    o.font = &pen_font();
    SimOptions so;
    if (d.regmarks.supported && d.protocol == Protocol::Gpgl) {
      test::add_regmarks(s, {4, 4}, {s.size_mm.x - 4, s.size_mm.y - 4}, 10);
      o.regmarks = true;
      so.printed_marks = printed_marks(s);
    }
    EXPECT_EQ(dry_run(d, s, o, so), "") << d.id;
  }
}

TEST(MachineModel, RefusesAPortrait3ProfileThatSendsTheCameosMat) {
  DeviceProfile wrong = builtin_profiles().device("portrait3");
  wrong.mats.front().code = 1;  // the old profile: TG1 is the Cameo's 12x12 mat
  const std::string e = dry_run(wrong, a4_mark_corner(), {});
  EXPECT_NE(e.find("job expects mat TG1 but mat 8x12 (TG3) is loaded"), std::string::npos) << e;
}

TEST(MachineModel, RefusesARolandProfileThatMeasuresTheCarriageFromTheFarEnd) {
  DeviceProfile wrong = builtin_profiles().device("roland-gx24");
  wrong.axes.carriage_reversed = true;  // the old profile: 584 - x
  wrong.axes.origin_at_media = false;
  const std::string e = dry_run(wrong, a4_mark_corner(), {});
  EXPECT_NE(e.find("leaves the loaded sheet"), std::string::npos) << e;
}

TEST(MachineModel, RefusesSilhouetteCommandsOnTheCe6000) {
  DeviceProfile wrong = builtin_profiles().device("ce6000");
  wrong.gpgl_family = GpglFamily::Cameo3;  // the old stream: ESC 05, FG, TB71, FA, TG, FN, FX...
  const std::string e = dry_run(wrong, a4_mark_corner(), {});
  EXPECT_NE(e.find("is not one the Graphtec CE6000-60 takes"), std::string::npos) << e;
}

TEST(MachineModel, RefusesHpglFsOnTheRoland) {
  DeviceProfile wrong = builtin_profiles().device("roland-gx24");
  wrong.hpgl_force_command = "FS";
  const std::string e = dry_run(wrong, a4_mark_corner(), {});
  EXPECT_NE(e.find("command FS is not one the Roland GX-24 takes"), std::string::npos) << e;
}

// Marks `inset` mm in from the edges, the whole set moved by `shift` (a printer's offset).
Sheet a4_with_marks(double inset, double arm, Vec2 shift = {0, 0}) {
  Sheet s;
  s.size_mm = kA4;
  s.paths.push_back(test::rect_path(PathRole::Cut, {40, 40}, {80, 80}, 0));
  test::add_regmarks(s, Vec2{inset, inset} + shift, Vec2{kA4.x - inset, kA4.y - inset} + shift, arm);
  return s;
}

TEST(MachineModel, FindsPrintedMarksAndCutsRelativeToWhereTheyReallyAre) {
  PlanOptions o;
  o.regmarks = true;
  o.fold_method = FoldMethod::None;
  SimOptions so;
  // Printed 2 mm up and left of where the layout put them (a printer's margin): the search starting
  // 10 mm before the expected mark still finds them.
  Sheet printed = a4_with_marks(15, 20, {-2, -2});
  so.printed_marks = printed_marks(printed);
  EXPECT_EQ(dry_run(builtin_profiles().device("cameo4"), a4_with_marks(15, 20), o, so), "");
}

TEST(MachineModel, MissesMarksWhenTheSearchStartsOnTheMarkAndThePrintIsShifted) {
  PlanOptions o;
  o.regmarks = true;
  o.fold_method = FoldMethod::None;
  const DeviceProfile& d = builtin_profiles().device("cameo4");
  const Sheet layout = a4_with_marks(15, 20);
  Job job = plan_job(layout, d, paper(), o);
  job.regmarks->start_a = job.regmarks->origin_a;  // the old search start: exactly on the mark
  job.regmarks->start_b = job.regmarks->origin_b;
  SimOptions so;
  so.sheet_mm = kA4;
  so.printed_marks = printed_marks(a4_with_marks(15, 20, {-2, -2}));
  SimulatedDevice dev(d, so);
  SendOptions send;
  send.poll_interval = std::chrono::milliseconds(1);
  EXPECT_THROW(send_job(stream_bytes(encode_gpgl(job)), dev, send), DeviceError);
  EXPECT_NE(dev.marks_problem().find("the search starts at"), std::string::npos) << dev.marks_problem();
  EXPECT_TRUE(dev.strokes().empty());
}

TEST(MachineModel, RefusesToCutWhenTheSearchCommandDoesNotDescribeThePrintedMarks) {
  PlanOptions o;
  o.regmarks = true;
  o.fold_method = FoldMethod::None;
  const DeviceProfile& d = builtin_profiles().device("cameo3");
  Job job = plan_job(a4_with_marks(15, 15), d, paper(), o);
  job.regmarks->arm_length = 400;  // the old stream: TB51,400 whatever was printed
  SimOptions so;
  so.sheet_mm = kA4;
  so.printed_marks = printed_marks(a4_with_marks(15, 15));
  SimulatedDevice dev(d, so);
  SendOptions send;
  send.poll_interval = std::chrono::milliseconds(1);
  EXPECT_THROW(send_job(stream_bytes(encode_gpgl(job)), dev, send), DeviceError);
  EXPECT_NE(dev.marks_problem().find("TB51 says 20 mm arms, the printed ones are 15 mm"), std::string::npos)
      << dev.marks_problem();
}

}  // namespace
}  // namespace foldkit::devices
