// The simulated device: strict parsing, state, faults, rendering, and the round trip every device
// profile must pass: sheet -> job -> bytes -> simulated device gives back the same strokes.
#include <chrono>
#include <fstream>

#include <gtest/gtest.h>

#include "foldkit/devices/gpgl.hpp"
#include "foldkit/devices/hpgl.hpp"
#include "foldkit/devices/plan.hpp"
#include "foldkit/devices/simulated_device.hpp"
#include "foldkit/error.hpp"
#include "sample_sheets.hpp"
#include "test_paths.hpp"

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
  const DeviceProfile& device = profiles().device(GetParam());
  PlanOptions options;
  options.draw_labels = device.tool(ToolKind::Pen) != nullptr;
  options.font = &font();
  options.overcut_mm = 1;
  const Job job = plan_job(test::two_piece_sheet(), device, profiles().medium("cardstock-220"), options);
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
  EXPECT_EQ(profiles().devices.size(), 10u) << "add new profiles to the EveryDevice table";
}

TEST(SimulatedDevice, AnswersTheCameo3HandshakeLikeTheRecording) {
  SimulatedDevice dev(profiles().device("cameo3"));
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

TEST(SimulatedDevice, RejectsAnUnknownCommandWithItsByteOffset) {
  SimulatedDevice dev(profiles().device("test"));
  const std::string msg = error_of([&] { dev.write(stream_bytes("\x1b\x04TG1\x03QQ5\x03")); });
  EXPECT_NE(msg.find("byte 6"), std::string::npos) << msg;
}

}  // namespace
}  // namespace foldkit::devices
