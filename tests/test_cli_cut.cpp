// `foldkit cut` and `foldkit profiles` end to end: dry runs on the simulated device, streams to files,
// bad profiles, out-of-area sheets, injected faults (clear message, non-zero exit, bounded time) and Ctrl-C.
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <fstream>
#include <thread>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cmd_cut.hpp"
#include "cmd_profiles.hpp"
#include "in_process.hpp"
#include "scoped_env.hpp"
#include "test_images.hpp"
#include "test_paths.hpp"

namespace {

namespace fs = std::filesystem;

struct CliRun {
  int exit_code = -1;
  std::string out, err;
};

using foldkit::test::slurp;

// Runs foldkit in `dir` with arguments (each single-quoted), capturing stdout and stderr.
CliRun run_foldkit(const fs::path& dir, const std::vector<std::string>& args) {
  std::string cmd = "cd '" + dir.string() + "' && '" + foldkit::test::foldkit_binary().string() + "'";
  for (const auto& a : args)
    cmd += " '" + a + "'";
  cmd += " >'" + (dir / "out.txt").string() + "' 2>'" + (dir / "err.txt").string() + "'";
  const int status = std::system(cmd.c_str());
  CliRun r;
  if (WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
  r.out = slurp(dir / "out.txt");
  r.err = slurp(dir / "err.txt");
  return r;
}

std::string mesh() {
  return foldkit::test::example_mesh("spot_128.obj").string();
}

TEST(CliProfiles, ListsEveryDeviceAndMedium) {
  foldkit::cli::ProfilesArgs args;
  args.json = true;
  const auto j = nlohmann::json::parse(foldkit::test::stdout_of([&] { foldkit::cli::run_profiles(args); }));
  std::set<std::string> devices, media;
  for (const auto& d : j["devices"])
    devices.insert(d["id"]);
  for (const auto& m : j["media"])
    media.insert(m["id"]);
  for (const char* id :
       {"cameo3", "cameo4", "cameo5", "portrait3", "curio", "ce6000", "roland-gx24", "generic-hpgl"})
    EXPECT_TRUE(devices.count(id)) << id;
  for (const char* id : {"copy-80", "cardstock-160", "cardstock-220", "cardstock-300"})
    EXPECT_TRUE(media.count(id)) << id;
}

TEST(CliProfiles, NamesTheFileAndKeyOfABadUserProfile) {
  const auto dir = foldkit::test::temp_dir("cli-badprofile");
  std::ofstream(dir / "mine.toml")
      << "kind = \"media\"\nname = \"x\"\nthickness_mm = 0.2\nwieght = 3\n"
      << "[cut]\nforce_gf = 1\nspeed_mm_s = 1\n[score]\nforce_gf = 1\nspeed_mm_s = 1\n"
      << "[draw]\nforce_gf = 1\nspeed_mm_s = 1\n";
  const CliRun r = run_foldkit(dir, {"profiles", "--profile", (dir / "mine.toml").string()});
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.err.find("mine.toml: wieght: unknown key"), std::string::npos) << r.err;
}

TEST(CliCut, DryRunReportsCutLengthTravelAndTimeAndWritesTheRendering) {
  const auto dir = foldkit::test::temp_dir("cli-dry");
  foldkit::cli::CutArgs args;
  args.mesh = mesh();
  args.device = "cameo4";
  args.media = "cardstock-220";
  args.dry_run = true;
  args.json = true;
  args.preview = (dir / "cut.svg").string();
  const auto j = nlohmann::json::parse(foldkit::test::stdout_of([&] { foldkit::cli::run_cut(args); }));
  EXPECT_TRUE(j["simulated"].get<bool>());
  ASSERT_GE(j["sheets"].size(), 1u);
  const auto& s = j["sheets"][0];
  EXPECT_GT(s["cut_length_mm"].get<double>(), 100);
  EXPECT_LT(s["travel_after_mm"].get<double>(), s["travel_before_mm"].get<double>());
  EXPECT_GT(s["estimated_s"].get<double>(), 0);
  EXPECT_NEAR(s["simulated_tool_down_mm"].get<double>(), s["cut_length_mm"].get<double>(), 1);
  EXPECT_TRUE(fs::exists(dir / "cut.svg"));
}

TEST(CliCut, UsesTheSimulatedDeviceAndSaysSoWhenNoDeviceIsNamed) {
  const auto dir = foldkit::test::temp_dir("cli-nodevice");
  const CliRun r = run_foldkit(dir, {"cut", mesh()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("no --device given: sending to a simulated"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(dir / "spot_128-cut.png"));
}

TEST(CliCut, WritesTheStreamToAFileInTheDevicesLanguage) {
  const auto dir = foldkit::test::temp_dir("cli-out");
  CliRun r = run_foldkit(dir, {"cut", mesh(), "--device", "cameo4", "-o", "job.gpgl", "-q"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(slurp(dir / "job.gpgl").substr(0, 5), std::string("\x1b\x05"
                                                              "FG\x03",
                                                              5));
  r = run_foldkit(dir, {"cut", mesh(), "--device", "roland-gx24", "-o", "job.plt", "-q"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string plt = slurp(dir / "job.plt");
  EXPECT_EQ(plt.substr(0, 6), "IN;PA;");
  EXPECT_EQ(plt.substr(plt.size() - 3), "IN;");
  r = run_foldkit(dir, {"cut", mesh(), "--device", "cameo4", "-o", "wrong.plt"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("speaks GP-GL"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "wrong.plt"));
  // -o used to be ignored silently beside --dry-run.
  r = run_foldkit(dir, {"cut", mesh(), "--device", "cameo4", "--dry-run", "-o", "job.png"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("choose one"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "job.png"));
}

TEST(CliCut, RefusesASheetThatDoesNotFitTheCuttingAreaBeforeSendingAnything) {
  const auto dir = foldkit::test::temp_dir("cli-area");
  // Fitted to A3 the pieces spread over 277 mm; the Portrait 3's mat is 203 mm wide.
  const CliRun r = run_foldkit(dir, {"cut", mesh(), "--device", "portrait3", "--mat", "8x12", "--paper", "A3",
                                     "--fit", "-o", "job.gpgl"});
  EXPECT_EQ(r.exit_code, 6);
  EXPECT_NE(r.err.find("leaves the cutting area of Silhouette Portrait 3 with mat 8x12"), std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(dir / "job.gpgl"));
}

TEST(CliCut, NamesUnknownDevicesAndMedia) {
  const auto dir = foldkit::test::temp_dir("cli-unknown");
  CliRun r = run_foldkit(dir, {"cut", mesh(), "--device", "cameo9", "--dry-run"});
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.err.find("no such device profile (known: cameo3, cameo4"), std::string::npos) << r.err;
  r = run_foldkit(dir, {"cut", mesh(), "--media", "vellum", "--dry-run"});
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.err.find("--media vellum"), std::string::npos) << r.err;
}

struct FaultCase {
  std::vector<std::string> extra;
  std::string message;
};

class CliFault : public ::testing::TestWithParam<FaultCase> {};

TEST_P(CliFault, EndsWithAClearMessageAndExit6InBoundedTime) {
  const auto dir = foldkit::test::temp_dir("cli-fault");
  std::vector<std::string> args{"cut", mesh(), "--device", "cameo4", "--dry-run", "--ready-timeout",
                                "0.5", "-q"};
  args.insert(args.end(), GetParam().extra.begin(), GetParam().extra.end());
  const auto start = std::chrono::steady_clock::now();
  const CliRun r = run_foldkit(dir, args);
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(30));
  EXPECT_EQ(r.exit_code, 6) << r.err;
  EXPECT_NE(r.err.find(GetParam().message), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err;
}

INSTANTIATE_TEST_SUITE_P(
    Faults, CliFault,
    ::testing::Values(FaultCase{{"--sim-fault", "not-ready"}, "paused (not ready) for more than 0.500 s"},
                      FaultCase{{"--sim-fault", "no-media"}, "no media loaded"},
                      FaultCase{{"--sim-fault", "disconnect=400"}, "disconnected after 400 bytes"},
                      FaultCase{{"--sim-fault", "stall=400"}, "accepted no data after 400 bytes"},
                      FaultCase{{"--sim-fault", "marks-not-found", "--regmarks"},
                                "registration marks not found"}));

TEST(CliCut, StopsCleanlyOnCtrlC) {
  const auto dir = foldkit::test::temp_dir("cli-sigint");
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    // The simulated device stays paused, so the send waits until the signal comes.
    const std::string err = (dir / "err.txt").string(), bin = foldkit::test::foldkit_binary().string(),
                      m = mesh();
    freopen(err.c_str(), "w", stderr);
    execl(bin.c_str(), bin.c_str(), "cut", m.c_str(), "--device", "cameo4", "--dry-run", "--sim-fault",
          "not-ready", "--ready-timeout", "60", static_cast<char*>(nullptr));
    _exit(127);
  }
  // Wait (bounded) until the send is waiting on the device, then press Ctrl-C.
  bool waiting = false;
  for (int i = 0; i < 600 && !waiting; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    waiting = slurp(dir / "err.txt").find("waiting:") != std::string::npos;
  }
  ASSERT_TRUE(waiting) << slurp(dir / "err.txt");
  kill(pid, SIGINT);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status)) << "killed by the signal instead of stopping cleanly";
  EXPECT_EQ(WEXITSTATUS(status), 130);
  const std::string err = slurp(dir / "err.txt");
  EXPECT_NE(err.find("stopped by Ctrl-C after 0 of"), std::string::npos) << err;
  EXPECT_NE(err.find("the tool was raised and the job ended"), std::string::npos) << err;
}

TEST(CliCut, ADeviceNodeThatStopsTakingDataIsGivenUpAfterTheReadyTimeoutAsOverUsb) {
  // Before, a node had its own fixed 10 s: --ready-timeout did not reach it. A FIFO whose reader never
  // reads, its buffer shrunk to one page, is a cutter that has stopped taking data; the labelled GX-24
  // job (~48 kB of HP-GL) cannot fit in it.
  const fs::path dir = foldkit::test::temp_dir("cli-node-timeout");
  const fs::path node = dir / "lp0";
  ASSERT_EQ(::mkfifo(node.c_str(), 0600), 0);
  const int reader = ::open(node.c_str(), O_RDONLY | O_NONBLOCK);
  ASSERT_GE(reader, 0);
  ::fcntl(reader, F_SETPIPE_SZ, 4096);
  const CliRun r = run_foldkit(dir, {"cut", mesh(), "--device", "roland-gx24", "--draw-labels", "-o",
                                     node.string(), "--ready-timeout", "0.3", "-q"});
  ::close(reader);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("took no data for 300 ms"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err;
}

// `foldkit sim`: a stream written by cut (or by another program) replayed on the machine's model.
TEST(CliSim, ReplaysAWrittenJobAndReportsWhatItWouldCut) {
  const fs::path dir = foldkit::test::temp_dir("cli-sim");
  ASSERT_EQ(run_foldkit(dir, {"cut", mesh(), "--device", "portrait3", "-o", "job.gpgl", "-q"}).exit_code, 0);
  const CliRun r = run_foldkit(dir, {"sim", "job.gpgl", "--device", "portrait3", "--preview", "sim.png"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("checked against its built-in machine model"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(" strokes, tool down "), std::string::npos) << r.out;
  EXPECT_TRUE(fs::exists(dir / "sim.png"));
}

TEST(CliSim, RefusesAStreamWithTheWrongMatAndDrawsThePartialPicture) {
  const fs::path dir = foldkit::test::temp_dir("cli-sim-wrong");
  ASSERT_EQ(run_foldkit(dir, {"cut", mesh(), "--device", "portrait3", "-o", "job.gpgl", "-q"}).exit_code, 0);
  // The stream a Cameo profile writes: TG1 on a machine whose 8x12 mat is TG3.
  std::string job = slurp(dir / "job.gpgl");
  const auto tg = job.find("TG3\x03");
  ASSERT_NE(tg, std::string::npos);
  job[tg + 2] = '1';
  std::ofstream(dir / "wrong.gpgl", std::ios::binary) << job;
  const CliRun r = run_foldkit(dir, {"sim", "wrong.gpgl", "--device", "portrait3", "--preview", "part.png"});
  EXPECT_EQ(r.exit_code, 6) << r.err;
  EXPECT_NE(r.err.find("job expects mat TG1 but mat 8x12 (TG3) is loaded"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("0 strokes were done, partial picture in part.png"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(dir / "part.png"));
}

TEST(CliSim, ReportsHowFarAFaultyRunGot) {
  const fs::path dir = foldkit::test::temp_dir("cli-sim-fault");
  ASSERT_EQ(run_foldkit(dir, {"cut", mesh(), "--device", "cameo4", "-o", "job.gpgl", "-q"}).exit_code, 0);
  const CliRun r = run_foldkit(
      dir, {"sim", "job.gpgl", "--device", "cameo4", "--sim-fault", "disconnect=3000", "--preview", "p.svg"});
  EXPECT_EQ(r.exit_code, 6) << r.err;
  EXPECT_NE(r.err.find("strokes were done, partial picture in p.svg"), std::string::npos) << r.err;
}

TEST(CliCut, TellsTheDeviceTheMarksThatWerePrintedAndRefusesSquaresItCannotFind) {
  const fs::path dir = foldkit::test::temp_dir("cli-regmark-geometry");
  ASSERT_EQ(run_foldkit(dir, {"cut", mesh(), "--device", "cameo4", "--regmarks", "--regmark-arm", "15mm",
                              "-o", "job.gpgl", "-q"})
                .exit_code,
            0);
  EXPECT_NE(slurp(dir / "job.gpgl").find("TB51,300\x03"), std::string::npos);
  const CliRun r = run_foldkit(dir, {"cut", mesh(), "--device", "cameo4", "--regmarks", "--regmark-square",
                                     "7mm", "-o", "bad.gpgl", "-q"});
  EXPECT_EQ(r.exit_code, 6) << r.err;
  EXPECT_NE(r.err.find("finds only 5.00 mm registration squares; the sheet's is 7.00 mm"), std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(dir / "bad.gpgl"));
}

}  // namespace

TEST(CliCut, TheRegistrationMarksPrintedAreTheOnesTheDeviceIsToldToFind) {
  // The profile's mark geometry lays out the marks; a --regmark-arm given on the command line is told to
  // the device too (TB51 in device units, 20 per mm on a Cameo), so the two never disagree.
  const auto dir = foldkit::test::temp_dir("cli-regmarks");
  CliRun r = run_foldkit(dir, {"cut", mesh(), "--device", "cameo4", "--regmarks", "-o", "job.gpgl", "-q"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(slurp(dir / "job.gpgl").find("TB51,400"), std::string::npos);
  r = run_foldkit(dir, {"cut", mesh(), "--device", "cameo4", "--regmarks", "--regmark-arm", "30", "-o",
                        "job.gpgl", "-q"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(slurp(dir / "job.gpgl").find("TB51,600"), std::string::npos);
}

namespace {

using Rgb = foldkit::test::RgbImage;
using foldkit::test::read_image;

bool red(const unsigned char* p) {
  return p[0] > 160 && p[1] < 90 && p[2] < 90;
}

bool dark(const unsigned char* p) {
  return p[0] + p[1] + p[2] < 3 * 110;
}

// The share of `over`'s red (cut) pixels that lie within 2 px of a dark (printed line) pixel of
// `print` moved by (dx, dy) pixels; counts the red pixels. Red that the print has itself (mountain folds)
// is not the cut: left out.
double share_on_print(const Rgb& over, const Rgb& print, int dx, int dy, int& reds) {
  constexpr int kReach = 2;
  int near = 0;
  reds = 0;
  for (int y = kReach; y + kReach < over.h; ++y)
    for (int x = kReach; x + kReach < over.w; ++x) {
      if (!red(over.px(x, y)) || (x < print.w && y < print.h && red(print.px(x, y)))) continue;
      ++reds;
      bool found = false;
      for (int v = -kReach; v <= kReach && !found; ++v)
        for (int u = -kReach; u <= kReach && !found; ++u) {
          const int px = x + u - dx, py = y + v - dy;
          found = px >= 0 && py >= 0 && px < print.w && py < print.h && dark(print.px(px, py));
        }
      near += found;
    }
  return reds ? static_cast<double>(near) / reds : 0;
}

}  // namespace

// `make --regmarks` writing print.png (150 dpi) and `cut --regmarks --dry-run` laying the simulated
// Cameo 4's cut over it as over.png, with the same layout options. Folds print dashed: only the blade's
// strokes, which follow solid lines, are compared.
struct PrintAndCut {
  std::vector<std::string> make, cut;
};
PrintAndCut print_and_cut_commands() {
  const std::vector<std::string> same{"--size", "80mm", "--regmarks", "-q"};
  PrintAndCut c{
      {"make", mesh(), "--no-guide", "--dpi", "150", "-o", "print.png"},
      {"cut", mesh(), "--device", "cameo4", "--dry-run", "--overlay", "over.png", "--fold-method", "none"}};
  c.make.insert(c.make.end(), same.begin(), same.end());
  c.cut.insert(c.cut.end(), same.begin(), same.end());
  return c;
}

// Print-and-cut: `make --regmarks` prints the sheet, `cut --regmarks` with the same options cuts it; the
// simulated device's cut, found through the printed marks and laid over the print, runs on the printed
// cut lines (and would not, were the print 1 mm off).
TEST(CliCut, TheOverlayShowsTheSimulatedCutOnTheLinesMakePrints) {
  const auto dir = foldkit::test::temp_dir("cli-overlay");
  const auto [make, cut] = print_and_cut_commands();
  CliRun r = run_foldkit(dir, make);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_foldkit(dir, cut);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("the simulated cut over the print: over.png"), std::string::npos) << r.out;
  const Rgb print = read_image(dir / "print.png"), over = read_image(dir / "over.png");
  ASSERT_GT(print.w, 0);
  ASSERT_EQ(over.w, print.w);
  ASSERT_EQ(over.h, print.h);
  int reds = 0;
  EXPECT_GE(share_on_print(over, print, 0, 0, reds), 0.98);
  EXPECT_GT(reds, 2000) << "the cut is drawn";
  const int mm = static_cast<int>(150 / 25.4);
  EXPECT_LT(share_on_print(over, print, mm, mm, reds), 0.8) << "the check sees a cut 1 mm off its print";

  // Without the simulated device there is nothing to lay over the print.
  r = run_foldkit(dir, {"cut", mesh(), "--device", "cameo4", "-o", "job.gpgl", "--overlay", "o.png"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("add --dry-run"), std::string::npos) << r.err;
  r = run_foldkit(dir, {"cut", mesh(), "--dry-run", "--overlay", "o.svg"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_FALSE(fs::exists(dir / "o.svg"));
}

// Print-and-cut calibration end to end: an offset stored once by `calibrate --offset` is applied by a
// later `cut --regmarks` (a new process), and the simulated device's cut, laid over the print, lies off
// the printed lines by exactly that offset. 0.1 in is 15 px at the overlay's 150 dpi.
TEST(CliCut, TheOverlayShowsTheCutMovedByTheStoredCalibrationOffset) {
  const auto dir = foldkit::test::temp_dir("cli-overlay-offset");
  const foldkit::test::ScopedEnv xdg("XDG_CONFIG_HOME", (dir / "config").string());
  const auto [make, cut] = print_and_cut_commands();
  CliRun r = run_foldkit(dir, make);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_foldkit(dir, {"calibrate", "--device", "cameo4", "--offset", "0.1,-0.1in"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_foldkit(dir, cut);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE((r.out + r.err).find("cuts moved by +2.54, -2.54 mm"), std::string::npos) << r.out << r.err;
  const Rgb print = read_image(dir / "print.png"), over = read_image(dir / "over.png");
  ASSERT_EQ(over.w, print.w);
  int reds = 0;
  EXPECT_GE(share_on_print(over, print, 15, -15, reds), 0.98) << "the cut is the print moved by the offset";
  EXPECT_GT(reds, 2000);
  EXPECT_LT(share_on_print(over, print, 0, 0, reds), 0.8) << "the offset is visible beside the print";
}
