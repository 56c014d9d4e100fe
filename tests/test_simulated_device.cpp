// The simulated device: strict parsing, state, faults, rendering, and the round trip every device
// profile must pass: sheet -> job -> bytes -> simulated device gives back the same strokes.
#include <algorithm>
#include <array>
#include <chrono>
#include <fstream>

#include <gtest/gtest.h>

#include "device_fixtures.hpp"
#include "foldkit/devices/gpgl.hpp"
#include "foldkit/devices/hpgl.hpp"
#include "foldkit/devices/plan.hpp"
#include "foldkit/devices/send.hpp"
#include "foldkit/devices/simulated_device.hpp"
#include "foldkit/error.hpp"
#include "sample_sheets.hpp"
#include "test_paths.hpp"

namespace foldkit::devices {
namespace {

using foldkit::test::builtin_profiles;

using foldkit::test::pen_font;

std::string encode(const Job& job) {
  return job.protocol == Protocol::Gpgl ? encode_gpgl(job) : encode_hpgl(job);
}

void send_all(SimulatedDevice& dev, const std::string& stream, std::size_t chunk = 37) {
  // Odd chunk sizes make commands straddle writes, as USB transfers do.
  for (std::size_t i = 0; i < stream.size(); i += chunk)
    dev.write(stream_bytes(stream).subspan(i, std::min(chunk, stream.size() - i)));
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const DeviceError& e) {
    return e.what();
  }
  return "";
}

class EveryDevice : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryDevice, GivesBackTheJobsStrokesWithinOneUnitInsideTheCuttingArea) {
  const DeviceProfile& device = builtin_profiles().device(GetParam());
  PlanOptions options;
  options.draw_labels = device.tool(ToolKind::Pen) != nullptr;
  options.font = &pen_font();
  options.overcut_mm = 1;
  const Job job =
      plan_job(test::two_piece_sheet(), device, builtin_profiles().medium("cardstock-220"), options);
  SimulatedDevice dev(device);
  send_all(dev, encode(job));
  dev.close();

  std::vector<const Stroke*> expected;
  for (const Pass& pass : job.passes)
    for (const Stroke& s : pass.strokes)
      expected.push_back(&s);
  ASSERT_GE(expected.size(), 5u);
  ASSERT_EQ(dev.strokes().size(), expected.size());
  const Vec2 area = cutting_area_mm(device, "");
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const auto& got = dev.strokes()[i].points;
    ASSERT_EQ(got.size(), expected[i]->points.size()) << "stroke " << i;
    for (std::size_t k = 0; k < got.size(); ++k) {
      EXPECT_LE(std::abs(got[k].x - static_cast<double>(expected[i]->points[k].a)), 1.0);
      EXPECT_LE(std::abs(got[k].y - static_cast<double>(expected[i]->points[k].b)), 1.0);
      const Vec2 page = device_to_page(device, got[k], area);
      EXPECT_GE(page.x, -1e-9);
      EXPECT_GE(page.y, -1e-9);
      EXPECT_LE(page.x, area.x + 1e-9);
      EXPECT_LE(page.y, area.y + 1e-9);
    }
  }
  EXPECT_NEAR(dev.down_length_mm(), job.stats.cut_length_mm, 0.01);
}

INSTANTIATE_TEST_SUITE_P(Profiles, EveryDevice,
                         ::testing::Values("cameo3", "cameo4", "cameo5", "portrait3", "curio", "ce6000",
                                           "roland-gx24", "generic-hpgl", "test", "test-hpgl"));

TEST(SimulatedDevice, CoversEveryBuiltInProfileInTheRoundTripTable) {
  EXPECT_EQ(builtin_profiles().devices.size(), 10u) << "add new profiles to the EveryDevice table";
}

TEST(SimulatedDevice, AnswersTheCameo3HandshakeLikeTheRecording) {
  SimulatedDevice dev(builtin_profiles().device("cameo3"));
  const std::string esc05 = "\x1b\x05", fg = "FG\x03";
  auto reply = [&](const std::string& c) {
    auto r = dev.request(stream_bytes(c), std::chrono::milliseconds(100));
    return std::string(reinterpret_cast<const char*>(r->data()), r->size());
  };
  EXPECT_EQ(reply(esc05), std::string("0\x03"));
  EXPECT_EQ(reply(fg), std::string("CAMEO 3 V1.60    \x03"));  // 17 characters, as the Cameo 3 sent
  dev.write(stream_bytes("\x1b\x04"));
  EXPECT_EQ(reply("TB71\x03"), std::string("    0,    0\x03"));
}

TEST(SimulatedDevice, FindsTheMarksAndCutsRelativeToThem) {
  const DeviceProfile& device = builtin_profiles().device("cameo4");
  Sheet marked = test::two_piece_sheet({25, 30});
  test::add_regmarks(marked, {10, 12}, {150, 90});
  PlanOptions o;
  o.regmarks = true;
  const Job job = plan_job(marked, device, builtin_profiles().medium("copy-80"), o);
  SimulatedDevice dev(device);
  send_all(dev, encode_gpgl(job));
  dev.close();
  ASSERT_TRUE(dev.mark_origin().has_value());
  EXPECT_EQ(*dev.mark_origin(), (Vec2{240, 200}));  // 12 mm down, 10 mm across, 20 units per mm
  ASSERT_EQ(dev.strokes().size(), job.stats.strokes);
  // Back on the page, the first outline starts where the sheet has it.
  const Vec2 first = device_to_page(device, dev.strokes().back().points.front() + *dev.mark_origin(),
                                    cutting_area_mm(device, ""));
  bool on_a_corner = false;
  for (const Path& p : marked.paths)
    if (p.role == PathRole::Cut)
      for (Vec2 q : p.points_mm)
        on_a_corner |= norm(q - first) < 0.05;
  EXPECT_TRUE(on_a_corner) << first.x << ", " << first.y;
}

TEST(SimulatedDevice, FollowsHpglRelativeMoves) {
  SimulatedDevice dev(builtin_profiles().device("test-hpgl"));
  dev.write(stream_bytes("IN;SP1;VS5;FS5;PU400,400;PR;PD100,0,0,100;PA;PU0,0;SP0;IN;"));
  dev.close();
  ASSERT_EQ(dev.strokes().size(), 1u);
  EXPECT_EQ(dev.strokes()[0].points, (std::vector<Vec2>{{400, 400}, {500, 400}, {500, 500}}));
  EXPECT_NEAR(dev.down_length_mm(), 5, 1e-9);
}

TEST(SimulatedDevice, RejectsAnUnknownCommandWithItsByteOffset) {
  SimulatedDevice dev(builtin_profiles().device("test"));
  const std::string msg = error_of([&] { dev.write(stream_bytes("\x1b\x04TG1\x03QQ5\x03")); });
  EXPECT_NE(msg.find("byte 6"), std::string::npos) << msg;
}

TEST(SimulatedDevice, RejectsADrawOutsideTheCutWindowWithItsOffset) {
  SimulatedDevice dev(builtin_profiles().device("test"));
  const std::string setup =
      "\x1b\x04J1\x03!5,1\x03"
      "FX10,1\x03M0,0\x03";
  dev.write(stream_bytes(setup));
  const std::string msg = error_of([&] { dev.write(stream_bytes("D3001,10\x03")); });
  EXPECT_NE(msg.find("byte " + std::to_string(setup.size())), std::string::npos) << msg;
  EXPECT_NE(msg.find("cut window"), std::string::npos) << msg;
  EXPECT_NE(error_of([&] { (void)dev.status(); }).find("stopped earlier"), std::string::npos);
}

TEST(SimulatedDevice, RejectsOutOfRangeSettingsAndDrawsBeforeToolSetUp) {
  auto first_error = [](const std::string& stream) {
    SimulatedDevice dev(builtin_profiles().device("test"));
    return error_of([&] { dev.write(stream_bytes(stream)); });
  };
  EXPECT_NE(first_error("\x1b\x04!11,1\x03").find("speed 11 out of range 1..10"), std::string::npos);
  EXPECT_NE(first_error("\x1b\x04"
                        "FX34,1\x03")
                .find("force 34 out of range"),
            std::string::npos);
  EXPECT_NE(first_error("\x1b\x04J3\x03").find("holder does not exist"), std::string::npos);
  EXPECT_NE(first_error("\x1b\x04J1\x03M0,0\x03"
                        "D10,10\x03")
                .find("before speed and force"),
            std::string::npos);
  EXPECT_NE(first_error("J1\x03").find("before ESC 04"), std::string::npos);
  EXPECT_NE(first_error("\x1b\x04TG2\x03").find("expects mat TG2"), std::string::npos);
  EXPECT_NE(first_error("\x1b\x04M1,2,3\x03").find("M takes 2"), std::string::npos);
  EXPECT_NE(first_error("\x1b\x04M1,x\x03").find("not a number"), std::string::npos);
  EXPECT_NE(first_error("\x1b\x07").find("unknown escape"), std::string::npos);
}

TEST(SimulatedDevice, RejectsAStreamThatEndsInsideACommandOrWithTheToolDown) {
  SimulatedDevice cut_short(builtin_profiles().device("test"));
  cut_short.write(stream_bytes("\x1b\x04J1\x03M0,0"));
  EXPECT_NE(error_of([&] { cut_short.close(); }).find("ends inside a command"), std::string::npos);
  SimulatedDevice left_down(builtin_profiles().device("test"));
  left_down.write(
      stream_bytes("\x1b\x04J1\x03!5,1\x03"
                   "FX5,1\x03M0,0\x03"
                   "D10,10\x03"));
  EXPECT_NE(error_of([&] { left_down.close(); }).find("tool down"), std::string::npos);
  SimulatedDevice hpgl(builtin_profiles().device("test-hpgl"));
  hpgl.write(stream_bytes("IN;SP1;PU0,0;PD10,10;"));
  EXPECT_NE(error_of([&] { hpgl.close(); }).find("pen down"), std::string::npos);
}

TEST(SimulatedDevice, ParsesHpglStrictly) {
  SimulatedDevice dev(builtin_profiles().device("test-hpgl"));
  EXPECT_NE(error_of([&] { dev.write(stream_bytes("IN;PA;XX1;")); }).find("HP-GL byte 6: unknown command"),
            std::string::npos);
  SimulatedDevice odd(builtin_profiles().device("test-hpgl"));
  EXPECT_NE(error_of([&] { odd.write(stream_bytes("IN;SP1;PD1,2,3;")); }).find("x,y pairs"),
            std::string::npos);
  SimulatedDevice range(builtin_profiles().device("test-hpgl"));
  EXPECT_NE(error_of([&] { range.write(stream_bytes("IN;SP1;VS99;")); }).find("velocity 99 out of range"),
            std::string::npos);
}

// --- Faults: each ends with a clear DeviceError within a bounded time, never a hang. ---

struct Fault {
  std::string name;
  SimFaults faults;
  std::string message;
};

SimFaults faults(const std::function<void(SimFaults&)>& set) {
  SimFaults f;
  set(f);
  return f;
}

class InjectedFault : public ::testing::TestWithParam<Fault> {};

TEST_P(InjectedFault, EndsWithAClearMessageWithinABoundedTime) {
  const DeviceProfile& device = builtin_profiles().device("cameo4");
  Sheet marked = test::two_piece_sheet({15, 15});
  test::add_regmarks(marked, {2, 2}, {110, 60});
  PlanOptions po;
  po.regmarks = true;
  const std::string stream = encode_gpgl(plan_job(marked, device, builtin_profiles().medium("copy-80"), po));
  SimOptions so;
  so.faults = GetParam().faults;
  SimulatedDevice dev(device, so);
  SendOptions o;
  o.chunk_bytes = 64;
  o.ready_timeout = std::chrono::milliseconds(200);
  o.poll_interval = std::chrono::milliseconds(10);
  const auto start = std::chrono::steady_clock::now();
  const std::string msg = error_of([&] { send_job(stream_bytes(stream), dev, o); });
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
  EXPECT_NE(msg.find(GetParam().message), std::string::npos) << msg;
}

INSTANTIATE_TEST_SUITE_P(
    Faults, InjectedFault,
    ::testing::Values(Fault{"NotReady", faults([](SimFaults& f) { f.not_ready = true; }),
                            "paused (not ready) for more than 0.200 s"},
                      Fault{"NoMedia", faults([](SimFaults& f) { f.no_media = true; }), "no media loaded"},
                      Fault{"Disconnect", faults([](SimFaults& f) { f.disconnect_after = 300; }),
                            "disconnected after 300 bytes"},
                      Fault{"Stall", faults([](SimFaults& f) { f.stall_after = 300; }),
                            "accepted no data after 300 bytes"},
                      Fault{"MarksNotFound", faults([](SimFaults& f) { f.marks_not_found = true; }),
                            "registration marks not found"}),
    [](const auto& info) { return info.param.name; });

TEST(SendJob, SendsAWholeJobInSlicesWithProgress) {
  const DeviceProfile& device = builtin_profiles().device("cameo4");
  const Job job = plan_job(test::two_piece_sheet(), device, builtin_profiles().medium("copy-80"));
  const std::string stream = encode_gpgl(job);
  SimulatedDevice dev(device);
  std::vector<SendProgress> seen;
  SendOptions o;
  o.chunk_bytes = 64;
  o.estimated_s = job.stats.estimated_s;
  o.progress = [&](const SendProgress& p) { seen.push_back(p); };
  const SendResult r = send_job(stream_bytes(stream), dev, o);
  dev.close();
  EXPECT_FALSE(r.cancelled);
  EXPECT_EQ(r.bytes_sent, stream.size());
  EXPECT_EQ(r.strokes_total, job.stats.strokes);
  EXPECT_EQ(r.strokes_done, r.strokes_total);
  EXPECT_EQ(dev.strokes().size(), job.stats.strokes);
  ASSERT_GT(seen.size(), 3u);
  for (std::size_t i = 1; i < seen.size(); ++i)
    EXPECT_GE(seen[i].bytes_sent, seen[i - 1].bytes_sent);
  EXPECT_EQ(seen.back().bytes_sent, stream.size());
  EXPECT_DOUBLE_EQ(seen.back().seconds_left, 0.0);
}

TEST(SendJob, StopsCleanlyOnCancelWithTheToolUpAndTheJobEnded) {
  const DeviceProfile& device = builtin_profiles().device("test");
  const Job job = plan_job(test::two_piece_sheet(), device, builtin_profiles().medium("copy-80"));
  SimulatedDevice dev(device);
  std::atomic<bool> cancel{false};
  SendOptions o;
  o.chunk_bytes = 32;
  o.cancel = &cancel;
  o.progress = [&](const SendProgress& p) {
    if (p.strokes_done >= 2) cancel = true;
  };
  const SendResult r = send_job(stream_bytes(encode_gpgl(job)), dev, o);
  EXPECT_TRUE(r.cancelled);
  EXPECT_GE(r.strokes_done, 2u);
  EXPECT_LT(r.strokes_done, r.strokes_total);
  EXPECT_NO_THROW(dev.close());  // the abort tail left the tool up and the stream complete
  EXPECT_LT(dev.strokes().size(), job.stats.strokes);
}

// The two-piece sheet planned for the "test" profile with pen labels, run on `dev` to the end.
void cut_and_draw_two_pieces(SimulatedDevice& dev) {
  PlanOptions o;
  o.draw_labels = true;
  o.font = &pen_font();
  dev.write(stream_bytes(encode_gpgl(plan_job(test::two_piece_sheet(), builtin_profiles().device("test"),
                                              builtin_profiles().medium("copy-80"), o))));
  dev.close();
}

TEST(SimulatedDevice, RendersWhatItCutScoredAndDrewToPngAndSvg) {
  SimulatedDevice dev(builtin_profiles().device("test"));
  cut_and_draw_two_pieces(dev);
  const auto dir = test::temp_dir("sim-render");
  dev.render(dir / "cut.png");
  dev.render(dir / "cut.svg");
  std::ifstream png(dir / "cut.png", std::ios::binary);
  char magic[4] = {};
  png.read(magic, 4);
  EXPECT_EQ(std::string(magic + 1, 3), "PNG");
  const std::string text = test::slurp(dir / "cut.svg");
  EXPECT_NE(text.find("<svg"), std::string::npos);
  EXPECT_NE(text.find("rgb(80%,10%,10%)"), std::string::npos) << "pen strokes drawn red";
  EXPECT_THROW(dev.render(dir / "cut.pdf"), OutputError);
}

TEST(SimulatedDevice, TheSceneDrawsEveryStrokeInItsToolsColourInsideItsBox) {
  SimulatedDevice dev(builtin_profiles().device("test"));
  cut_and_draw_two_pieces(dev);
  const SimScene scene = dev.scene();
  ASSERT_EQ(scene.lines.size(), dev.strokes().size());
  const std::array<double, 3> pen{0.8, 0.1, 0.1}, cut{0, 0, 0}, score{0.1, 0.3, 0.8}, scorer{0.1, 0.55, 0.2};
  int pens = 0, cuts = 0;
  for (const SimScene::Line& line : scene.lines) {
    EXPECT_TRUE(line.rgb == pen || line.rgb == cut || line.rgb == score || line.rgb == scorer);
    pens += line.rgb == pen ? 1 : 0;
    cuts += line.rgb == cut ? 1 : 0;
    EXPECT_EQ(line.width_mm, line.rgb == cut ? 0.25 : 0.2);
    for (Vec2 p : line.points) {
      EXPECT_GE(p.x, scene.box.min.x - 1e-9);
      EXPECT_LE(p.x, scene.box.max.x + 1e-9);
      EXPECT_GE(p.y, scene.box.min.y - 1e-9);
      EXPECT_LE(p.y, scene.box.max.y + 1e-9);
    }
  }
  EXPECT_GT(pens, 0) << "the labels are drawn with the pen";
  EXPECT_GT(cuts, 0) << "the outlines are cut";
  EXPECT_FALSE(scene.sheet) << "no sheet was loaded";
  EXPECT_FALSE(scene.search_origin) << "no registration marks were searched";
}

// Records how long each query may take: the reference allows 10 s for FG and TB71 (the head moves),
// 5 s for a status reply.
class TimeoutRecorder final : public Transport {
 public:
  void write(std::span<const std::byte>) override {}
  DeviceState status() override { return DeviceState::Ready; }
  void close() override {}
  bool reads_replies() const override { return true; }
  std::string describe() const override { return "recorder"; }
  std::optional<std::vector<std::byte>> request(std::span<const std::byte> command,
                                                std::chrono::milliseconds timeout) override {
    std::string c(reinterpret_cast<const char*>(command.data()), command.size());
    timeouts.emplace_back(c, timeout.count());
    const std::string r = c == "\x1b\x05" ? "0\x03" : "    0,    0\x03";
    std::vector<std::byte> out(r.size());
    std::transform(r.begin(), r.end(), out.begin(), [](char ch) { return static_cast<std::byte>(ch); });
    return out;
  }
  std::vector<std::pair<std::string, long>> timeouts;
};

TEST(SendJob, WaitsTenSecondsForFgAndTb71AndFiveForStatus) {
  TimeoutRecorder t;
  send_job(stream_bytes("\x1b\x05"
                        "FG\x03\x1b\x04TB71\x03"
                        "FA\x03"),
           t, {});
  ASSERT_EQ(t.timeouts.size(), 4u);
  EXPECT_EQ(t.timeouts[0].second, 5000);   // ESC 05
  EXPECT_EQ(t.timeouts[1].second, 10000);  // FG
  EXPECT_EQ(t.timeouts[2].second, 10000);  // TB71
  EXPECT_EQ(t.timeouts[3].second, 10000);  // FA
}

}  // namespace
}  // namespace foldkit::devices
