// The stored print-and-cut calibration: a TOML file per device that round-trips and refuses nonsense,
// a plan option that moves every stroke of a job with registration marks by exactly the stored offset
// (and nothing else), the simulated device cutting off the print by that offset, and the CLI storing it
// once (`calibrate --offset`) so that a new run of `cut --regmarks` applies it.
#include "device_fixtures.hpp"
#include "foldkit/devices/calibration.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "foldkit/devices/command_parser.hpp"
#include "foldkit/devices/gpgl.hpp"
#include "foldkit/devices/plan.hpp"
#include "foldkit/devices/print_cut_preview.hpp"
#include "foldkit/devices/send.hpp"
#include "foldkit/devices/simulated_device.hpp"
#include "foldkit/error.hpp"
#include "foldkit/layout/calibration_page.hpp"
#include "scoped_env.hpp"
#include "test_paths.hpp"

namespace fs = std::filesystem;
using namespace foldkit;
using namespace foldkit::devices;

namespace {

using foldkit::test::builtin_profiles;

using foldkit::test::slurp;

// Every M and D point of a GP-GL stream after the registration-mark search, in device units.
std::vector<DevicePoint> geometry(const std::string& stream) {
  GpglParser parser;
  std::vector<DevicePoint> out;
  bool after_search = false;
  for (const ParsedCommand& c : parser.feed(stream_bytes(stream))) {
    if (c.name == "TB" && !c.params.empty() && (c.params[0] == 123 || c.params[0] == 124))
      after_search = true;
    if (!after_search || (c.name != "M" && c.name != "D")) continue;
    for (std::size_t i = 0; i + 1 < c.params.size(); i += 2)
      out.push_back({std::llround(c.params[i]), std::llround(c.params[i + 1])});
  }
  return out;
}

// The offset in device units and order, as the planner converts page millimetres.
DevicePoint device_delta(const DeviceProfile& d, Vec2 offset_mm) {
  const Vec2 area = cutting_area_mm(d, "");
  const Vec2 a = page_to_device(d, {50, 50}, area), b = page_to_device(d, Vec2{50, 50} + offset_mm, area);
  return {std::llround(b.x - a.x), std::llround(b.y - a.y)};
}

// Strokes (runs of runs_of) each as the sorted set of the corners it cuts through: the planner may order the
// moved strokes differently (its start point, the top-left mark, does not move), and then run an open stroke
// the other way or start a closed outline at another corner, past which it overcuts. The final return home is
// not geometry and is left out.
std::vector<std::vector<DevicePoint>> strokes_of(const std::vector<std::vector<DevicePoint>>& runs) {
  auto less = [](DevicePoint x, DevicePoint y) { return std::pair{x.a, x.b} < std::pair{y.a, y.b}; };
  std::vector<std::vector<DevicePoint>> out;
  for (std::vector<DevicePoint> run : runs) {
    // A closed outline comes back to its first corner; what follows is the overcut.
    const auto back = std::find(run.begin() + 1, run.end(), run.front());
    if (back != run.end()) run.erase(back, run.end());
    std::sort(run.begin(), run.end(), less);
    run.erase(std::unique(run.begin(), run.end()), run.end());
    out.push_back(std::move(run));
  }
  std::sort(out.begin(), out.end(), [&](const auto& x, const auto& y) {
    return std::lexicographical_compare(x.begin(), x.end(), y.begin(), y.end(), less);
  });
  return out;
}

// The runs of a GP-GL stream after the registration-mark search: each move (M) and the cuts (D) that
// follow it, in device units.
std::vector<std::vector<DevicePoint>> runs_of(const std::string& stream) {
  GpglParser parser;
  std::vector<std::vector<DevicePoint>> out;
  bool after_search = false;
  for (const ParsedCommand& c : parser.feed(stream_bytes(stream))) {
    if (c.name == "TB" && !c.params.empty() && (c.params[0] == 123 || c.params[0] == 124))
      after_search = true;
    if (!after_search || (c.name != "M" && c.name != "D")) continue;
    for (std::size_t i = 0; i + 1 < c.params.size(); i += 2) {
      if (c.name == "M" || out.empty()) out.emplace_back();
      out.back().push_back({std::llround(c.params[i]), std::llround(c.params[i + 1])});
    }
  }
  return out;
}

// `before` moved by `d` equals `after`, stroke by stroke (see strokes_of); a lone move (the return
// home) is not geometry.
void expect_shifted(std::vector<std::vector<DevicePoint>> before, std::vector<std::vector<DevicePoint>> after,
                    DevicePoint d) {
  auto drop_moves = [](std::vector<std::vector<DevicePoint>>& runs) {
    runs.erase(std::remove_if(runs.begin(), runs.end(), [](const auto& r) { return r.size() < 2; }),
               runs.end());
  };
  drop_moves(before);
  drop_moves(after);
  ASSERT_GT(before.size(), 3u);
  for (auto& run : before)
    for (DevicePoint& p : run)
      p = {p.a + d.a, p.b + d.b};
  EXPECT_EQ(strokes_of(before), strokes_of(after));
}

using foldkit::test::ScopedEnv;

}  // namespace

TEST(Calibration, AStoredOffsetReadsBackTheSame) {
  const fs::path file = calibration_file(test::temp_dir("calib-rt"), "cameo4");
  EXPECT_FALSE(load_calibration(file, "cameo4").has_value());
  save_calibration(file, {"cameo4", {0.8, -1.2}});
  const auto c = load_calibration(file, "cameo4");
  ASSERT_TRUE(c.has_value());
  EXPECT_EQ(c->offset_mm, (Vec2{0.8, -1.2}));
}

TEST(Calibration, MalformedForeignOrAbsurdFilesAreInputErrorsNamingTheKey) {
  const fs::path dir = test::temp_dir("calib-bad");
  auto expect_error = [&](const std::string& text, const std::string& needle) {
    const fs::path f = dir / "cameo4.toml";
    std::ofstream(f) << text;
    try {
      (void)load_calibration(f, "cameo4");
      ADD_FAILURE() << "no error for: " << text;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
  };
  expect_error("kind = \"calibration\"\ndevice = \"cameo4\"\noffset_x_mm = 1\n", "offset_y_mm");
  expect_error("kind = \"calibration\"\ndevice = \"cameo3\"\noffset_x_mm = 1\noffset_y_mm = 0\n", "cameo3");
  expect_error("kind = \"calibration\"\ndevice = \"cameo4\"\noffset_x_mm = 90\noffset_y_mm = 0\n",
               "offset_x_mm");
  expect_error("kind = \"calibration\"\ndevice = \"cameo4\"\noffset_x_mm = \"a\"\noffset_y_mm = 0\n",
               "offset_x_mm");
  expect_error("kind = \"calibration\"\ndevice = \"cameo4\"\noffset_x_mm = 1\noffset_y_mm = 0\nx = 1\n",
               "x: unknown");
  expect_error("offset_x_mm = = 1\n", "line 1");
  EXPECT_THROW(save_calibration(dir / "x.toml", {"cameo4", {0, std::nan("")}}), InputError);
}

TEST(Calibration, TheOffsetShiftsEveryStrokeOfAPrintAndCutJobByExactlyThatMuch) {
  const DeviceProfile& cameo = builtin_profiles().device("cameo4");
  const MediaProfile& paper = builtin_profiles().medium("copy-80");
  const auto page = layout::calibration_page();
  PlanOptions plain;
  plain.regmarks = true;
  PlanOptions shifted = plain;
  shifted.print_cut_offset_mm = {0.8, -1.2};
  const std::string a = encode_gpgl(plan_job(page.sheet, cameo, paper, plain));
  const std::string b = encode_gpgl(plan_job(page.sheet, cameo, paper, shifted));
  const DevicePoint d = device_delta(cameo, {0.8, -1.2});
  EXPECT_EQ(std::abs(d.a) + std::abs(d.b), 16 + 24) << "0.8 and 1.2 mm at 20 units/mm";
  expect_shifted(runs_of(a), runs_of(b), d);
  // The mark search itself is where the marks are printed: unchanged.
  EXPECT_EQ(a.substr(0, a.find("TB123")), b.substr(0, b.find("TB123")));
}

TEST(Calibration, WithoutRegistrationMarksTheOffsetDoesNothing) {
  const DeviceProfile& cameo = builtin_profiles().device("cameo4");
  const auto page = layout::calibration_page();
  PlanOptions shifted;
  shifted.print_cut_offset_mm = {0.8, -1.2};
  EXPECT_EQ(encode_gpgl(plan_job(page.sheet, cameo, builtin_profiles().medium("copy-80"), {})),
            encode_gpgl(plan_job(page.sheet, cameo, builtin_profiles().medium("copy-80"), shifted)));
}

TEST(Calibration, TheSimulatedDeviceCutsTheCrossesOffTheirPrintByTheOffset) {
  const DeviceProfile& cameo = builtin_profiles().device("cameo4");
  const auto page = layout::calibration_page();
  PlanOptions plan;
  plan.regmarks = true;
  plan.print_cut_offset_mm = {0.8, -1.2};
  const std::string stream =
      encode_gpgl(plan_job(page.sheet, cameo, builtin_profiles().medium("copy-80"), plan));
  SimulatedDevice sim(cameo);
  SendOptions send;
  send.protocol = Protocol::Gpgl;
  send_job(stream_bytes(stream), sim, send);
  sim.close();
  const auto cuts = simulated_cuts_mm(sim, cameo, "");
  ASSERT_EQ(cuts.size(), 2 * page.crosses_mm.size());
  for (Vec2 c : page.crosses_mm) {
    int near = 0;
    for (const auto& line : cuts) {
      const Vec2 mid = (line.front() + line.back()) * 0.5;
      // 1/20 mm: the device's step.
      if (std::abs(mid.x - (c.x + 0.8)) <= 0.05 && std::abs(mid.y - (c.y - 1.2)) <= 0.05) ++near;
    }
    EXPECT_EQ(near, 2) << "cross at " << c.x << ", " << c.y;
  }
  const fs::path png = test::temp_dir("calib-sim") / "preview.png";
  render_print_and_cut(page.sheet, cuts, png);
  EXPECT_GT(fs::file_size(png), 1000u);
}

TEST(Calibration, AnOffsetEnteredOnceShiftsEveryLaterCutJobOnThatDevice) {
  const fs::path dir = test::temp_dir("calib-cli");
  const ScopedEnv xdg("XDG_CONFIG_HOME", (dir / "config").string());
  const std::string mesh = test::example_mesh("spot_128.obj").string();
  const std::vector<std::string> cut = {"cut",        mesh,     "--device", "cameo4",
                                        "--regmarks", "--size", "80mm",     "-q"};
  auto cut_to = [&](const std::string& name) {
    auto args = cut;
    args.insert(args.end(), {"-o", (dir / name).string()});
    const auto run = test::run_foldkit(args);
    EXPECT_EQ(run.exit_code, 0) << run.err;
    return slurp(dir / name);
  };
  const std::string before = cut_to("before.gpgl");

  const auto store = test::run_foldkit({"calibrate", "--device", "cameo4", "--offset", "0.8,-1.2mm"});
  ASSERT_EQ(store.exit_code, 0) << store.err;
  EXPECT_TRUE(fs::exists(dir / "config/foldkit/calibration/cameo4.toml"));
  const auto shown = test::run_foldkit({"calibrate", "--device", "cameo4", "--show"});
  EXPECT_NE(shown.out.find("+0.80, -1.20 mm"), std::string::npos) << shown.out;

  // A new process, which knows the offset only from the file.
  const std::string after = cut_to("after.gpgl");
  expect_shifted(runs_of(before), runs_of(after),
                 device_delta(builtin_profiles().device("cameo4"), {0.8, -1.2}));

  // --reset takes the correction back.
  ASSERT_EQ(test::run_foldkit({"calibrate", "--device", "cameo4", "--reset"}).exit_code, 0);
  EXPECT_EQ(cut_to("reset.gpgl"), before);
}

TEST(Calibration, CalibrateWritesThePageTheJobAndThePreview) {
  const fs::path dir = test::temp_dir("calib-page");
  const ScopedEnv xdg("XDG_CONFIG_HOME", (dir / "config").string());
  const auto run =
      test::run_foldkit({"calibrate", "--device", "cameo4", "-o", (dir / "page.pdf").string(), "--job",
                         (dir / "job.gpgl").string(), "--preview", (dir / "cut.png").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(slurp(dir / "page.pdf").rfind("%PDF", 0), 0u);
  const std::string job = slurp(dir / "job.gpgl");
  EXPECT_NE(job.find("TB123"), std::string::npos) << "cut relative to the registration marks";
  EXPECT_EQ(geometry(job).size() > 10, true);
  EXPECT_GT(fs::file_size(dir / "cut.png"), 1000u);
}

TEST(Calibration, BadOffsetsAreUsageErrorsAndStoreNothing) {
  const fs::path dir = test::temp_dir("calib-badcli");
  const ScopedEnv xdg("XDG_CONFIG_HOME", (dir / "config").string());
  for (const char* bad : {"0.8", "a,b", "0.8,-1.2km", "30,0", "0.8,nan"}) {
    const auto run = test::run_foldkit({"calibrate", "--device", "cameo4", "--offset", bad});
    EXPECT_EQ(run.exit_code, 2) << bad << ": " << run.err;
    EXPECT_NE(run.err.find("--offset"), std::string::npos) << run.err;
  }
  EXPECT_FALSE(fs::exists(dir / "config"));
  EXPECT_EQ(
      test::run_foldkit({"calibrate", "--device", "cameo4", "--job", (dir / "x.plt").string()}).exit_code, 2);
  EXPECT_EQ(
      test::run_foldkit({"calibrate", "--device", "cameo4", "--preview", (dir / "x.svg").string()}).exit_code,
      2);
  EXPECT_FALSE(fs::exists(dir / "x.plt"));
  const auto hpgl = test::run_foldkit({"calibrate", "--device", "generic-hpgl"});
  EXPECT_NE(hpgl.exit_code, 0);
  EXPECT_NE(hpgl.err.find("registration marks"), std::string::npos) << hpgl.err;
}

// The stored offset moves the blade: a job it pushes off the cutting area is refused before a byte is
// written, and the error says that the offset, not the layout, is the cause.
TEST(Calibration, AnOffsetThatPushesTheCutOffTheMatIsRefusedAndNamed) {
  const fs::path dir = test::temp_dir("calib-bounds");
  const ScopedEnv xdg("XDG_CONFIG_HOME", (dir / "config").string());
  ASSERT_EQ(test::run_foldkit({"calibrate", "--device", "cameo4", "--offset", "-25,-25mm"}).exit_code, 0);
  const auto run =
      test::run_foldkit({"cut", test::example_mesh("spot_128.obj").string(), "--device", "cameo4",
                         "--regmarks", "--size", "180mm", "-q", "-o", (dir / "job.gpgl").string()});
  EXPECT_NE(run.exit_code, 0);
  EXPECT_NE(run.err.find("leaves the cutting area"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("only with the print-and-cut offset -25.00, -25.00 mm"), std::string::npos)
      << run.err;
  EXPECT_FALSE(fs::exists(dir / "job.gpgl"));
}
