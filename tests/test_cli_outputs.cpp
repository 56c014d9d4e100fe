// Every command's outputs: never over an input, into device nodes and FIFOs directly, through symbolic
// links, to standard output with -o -, all sheets or none, no stale sheets of an earlier run, and no
// temporary file left by Ctrl-C or SIGTERM (exit 130 / 143).
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "scoped_env.hpp"
#include "test_paths.hpp"

namespace fs = std::filesystem;
using foldkit::test::run_foldkit;

namespace {

using foldkit::test::slurp;

std::vector<std::string> entries(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir))
    names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

bool has_hidden_temporary(const fs::path& dir) {
  for (const std::string& name : entries(dir)) {
    if (name.find(".tmp-") != std::string::npos || name.find(".old-") != std::string::npos) return true;
  }
  return false;
}

// A private copy of an example mesh, so a test that went wrong could only damage the copy.
fs::path copy_mesh(const fs::path& dir, const std::string& name) {
  fs::copy_file(foldkit::test::example_mesh(name), dir / name);
  return dir / name;
}

TEST(CliOutputs, AnOutputThatIsTheInputIsRefusedAndNothingIsWritten) {
  const fs::path dir = foldkit::test::temp_dir("outputs-same");
  const fs::path mesh = copy_mesh(dir, "fish_350.obj");
  const std::string before = slurp(mesh);
  fs::create_symlink("fish_350.obj", dir / "soft.obj");
  fs::create_hard_link(mesh, dir / "hard.obj");
  const std::vector<std::vector<std::string>> commands = {
      {"unfold", mesh.string(), "-o", mesh.string()},
      {"unfold", mesh.string(), "-o", (dir / "soft.obj").string()},
      {"unfold", (dir / "soft.obj").string(), "-o", (dir / "hard.obj").string()},
      {"unfold", mesh.string(), "-o", (dir / "." / "fish_350.obj").string()},
      {"make", mesh.string(), "--format", "svg", "-o", (dir / "hard.obj").string()},
      {"cut", mesh.string(), "--device", "cameo4", "-o", mesh.string()},
      {"cut", mesh.string(), "--dry-run", "--preview", (dir / "soft.obj").string()},
  };
  for (const auto& args : commands) {
    const auto r = run_foldkit(args);
    EXPECT_EQ(r.exit_code, 2) << args[0] << " -o " << args.back() << ": " << r.err;
    EXPECT_NE(r.err.find("is the input file"), std::string::npos) << r.err;
    EXPECT_EQ(slurp(mesh), before) << "the mesh is untouched";
  }
  EXPECT_TRUE(fs::is_symlink(dir / "soft.obj"));
  EXPECT_EQ(entries(dir), (std::vector<std::string>{"fish_350.obj", "hard.obj", "soft.obj"}));
}

TEST(CliOutputs, CutWritesOnlyJobStreamsNotAnyExtension) {
  const fs::path dir = foldkit::test::temp_dir("outputs-cut-ext");
  const auto r = run_foldkit({"cut", foldkit::test::example_mesh("fish_350.obj").string(), "--device",
                              "cameo4", "-o", (dir / "job.obj").string()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find(".gpgl (GP-GL)"), std::string::npos) << r.err;
  EXPECT_TRUE(entries(dir).empty());
}

TEST(CliOutputs, AFifoIsWrittenIntoAndStaysAFifo) {
  const fs::path dir = foldkit::test::temp_dir("outputs-fifo");
  const fs::path fifo = dir / "net.obj";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string received;
  std::thread reader([&] { received = slurp(fifo); });
  const auto r =
      run_foldkit({"unfold", foldkit::test::example_mesh("fish_350.obj").string(), "-o", fifo.string()});
  reader.join();
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::is_fifo(fifo)) << "not replaced by a regular file";
  EXPECT_NE(received.find("\nf "), std::string::npos) << "the net went through the FIFO";
  EXPECT_EQ(entries(dir), std::vector<std::string>{"net.obj"});
}

TEST(CliOutputs, ASymbolicLinkIsWrittenThroughAndStaysALink) {
  const fs::path dir = foldkit::test::temp_dir("outputs-link");
  fs::create_directory(dir / "sheets");
  fs::create_symlink("sheets/spot.pdf", dir / "latest.pdf");
  const auto r = run_foldkit({"make", foldkit::test::example_mesh("spot_128.obj").string(), "--size", "120mm",
                              "-o", (dir / "latest.pdf").string(), "-q"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::is_symlink(dir / "latest.pdf"));
  EXPECT_EQ(slurp(dir / "sheets" / "spot.pdf").substr(0, 5), "%PDF-");
  EXPECT_EQ(entries(dir / "sheets"), std::vector<std::string>{"spot.pdf"});
}

TEST(CliOutputs, AMissingLabelFontIsOneLineBeforeThePipelineAndNothingIsWritten) {
  const fs::path dir = foldkit::test::temp_dir("outputs-no-font");
  fs::create_directory(dir / "empty-share");
  fs::create_directory(dir / "out");
  const foldkit::test::ScopedEnv env("XDG_DATA_DIRS", (dir / "empty-share").string());
  // A mesh the loader refuses (exit 3): the font error (exit 1) comes first only if it is checked
  // before the pipeline loads anything.
  std::ofstream(dir / "broken.obj") << "v 0 0 0\nf 1 2 3\n";
  const std::string out = (dir / "out").string();
  const std::vector<std::vector<std::string>> commands = {
      {"make", (dir / "broken.obj").string(), "-o", out + "/m.dxf"},
      {"make", (dir / "broken.obj").string(), "--bundle", out + "/bundle"},
      {"make", (dir / "broken.obj").string(), "-o", out + "/m.pdf", "--bundle", out + "/bundle"},
      {"cut", (dir / "broken.obj").string(), "--device", "cameo4", "--dry-run", "--draw-labels", "--preview",
       out + "/c.png"},
  };
  for (const auto& args : commands) {
    const auto r = run_foldkit(args);
    EXPECT_EQ(r.exit_code, 1) << args[0] << " " << args.back() << ": " << r.err;
    EXPECT_NE(r.err.find("no Hershey font futural.jhf"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_TRUE(entries(dir / "out").empty()) << ::testing::PrintToString(entries(dir / "out"));
  }
  // Outputs without pen labels do not need the font.
  const auto pdf = run_foldkit({"make", foldkit::test::example_mesh("spot_128.obj").string(), "--size",
                                "120mm", "-o", out + "/m.pdf", "-q"});
  EXPECT_EQ(pdf.exit_code, 0) << pdf.err;
}

TEST(CliOutputs, DashWritesTheNetTheSheetsOrTheJobToStandardOutput) {
  const std::string fish = foldkit::test::example_mesh("fish_350.obj").string();
  const std::string spot = foldkit::test::example_mesh("spot_128.obj").string();
  auto r = run_foldkit({"unfold", fish, "-o", "-"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("# foldkit flat net", 0), 0u) << r.out.substr(0, 80);
  EXPECT_NE(r.err.find("piece"), std::string::npos) << "the summary goes to stderr: " << r.err;

  r = run_foldkit({"make", spot, "--size", "120mm", "-o", "-", "-q"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.substr(0, 5), "%PDF-");
  EXPECT_EQ(r.out.find(" sheet"), std::string::npos) << "no summary inside the PDF";

  // One sheet at this size (SVG to standard output is one sheet's file).
  r = run_foldkit({"make", spot, "--size", "100mm", "--format", "svg", "-o", "-", "-q"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("<svg"), std::string::npos);

  r = run_foldkit({"cut", fish, "--device", "cameo4", "--size", "100mm", "-o", "-", "-q"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_GT(r.out.size(), 100u);
  EXPECT_EQ(r.out.find("strokes"), std::string::npos) << "no summary inside the job";
  EXPECT_NE(r.err.find("strokes"), std::string::npos) << r.err;

  r = run_foldkit({"make", spot, "-o", "-", "--json"});
  EXPECT_EQ(r.exit_code, 2) << "--json and -o - cannot share stdout: " << r.err;
}

TEST(CliOutputs, StaleSheetsOfAnEarlierRunAreRemovedAndSaidSo) {
  const fs::path dir = foldkit::test::temp_dir("outputs-stale");
  for (int k = 2; k <= 14; ++k)
    std::ofstream(dir / ("m-" + std::to_string(k) + ".svg")) << "<svg/> stale";
  std::ofstream(dir / "m-20.svg") << "not part of a run: a gap before it";
  std::ofstream(dir / "m-notes.svg") << "unrelated";
  const auto r = run_foldkit({"make", foldkit::test::example_mesh("spot_128.obj").string(), "--size", "120mm",
                              "-o", (dir / "m.svg").string(), "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const int sheets = j["sheet_count"];
  ASSERT_LT(sheets, 14);
  for (int k = 2; k <= 14; ++k) {
    const fs::path f = dir / ("m-" + std::to_string(k) + ".svg");
    if (k <= sheets)
      EXPECT_EQ(slurp(f).find("stale"), std::string::npos) << f << " is a sheet of this run";
    else
      EXPECT_FALSE(fs::exists(f)) << f << " of the earlier run is removed";
  }
  EXPECT_TRUE(fs::exists(dir / "m-20.svg"));
  EXPECT_TRUE(fs::exists(dir / "m-notes.svg"));
  EXPECT_NE(
      j["notes"].dump().find("removed " + std::to_string(14 - sheets) + " sheet file(s) of an earlier run"),
      std::string::npos)
      << j["notes"].dump();
}

TEST(CliOutputs, ASheetThatCannotBeWrittenLeavesEveryOldSheetInPlace) {
  const fs::path dir = foldkit::test::temp_dir("outputs-none");
  std::ofstream(dir / "m.svg") << "old sheet 1";
  std::ofstream(dir / "m-2.svg") << "old sheet 2";
  fs::create_directory(dir / "m-3.svg");  // sheet 3 has no place to go
  // spot_350 at 160 mm on A5 needs more than two sheets.
  const auto r = run_foldkit({"make", foldkit::test::example_mesh("spot_350.obj").string(), "--size", "160mm",
                              "--paper", "A5", "-o", (dir / "m.svg").string(), "-q"});
  ASSERT_EQ(r.exit_code, 4) << r.err;
  EXPECT_NE(r.err.find("m-3.svg"), std::string::npos) << r.err;
  EXPECT_EQ(slurp(dir / "m.svg"), "old sheet 1");
  EXPECT_EQ(slurp(dir / "m-2.svg"), "old sheet 2");
  EXPECT_FALSE(has_hidden_temporary(dir)) << ::testing::PrintToString(entries(dir));
  EXPECT_EQ(entries(dir), (std::vector<std::string>{"m-2.svg", "m-3.svg", "m.svg"}));
}

// Starts foldkit with `args` in `dir` (stdout and stderr to files there).
pid_t spawn_foldkit(const fs::path& dir, const std::vector<std::string>& args) {
  const std::string bin = foldkit::test::foldkit_binary().string();
  const std::string out = (dir / "stdout.txt").string(), err = (dir / "stderr.txt").string();
  std::vector<std::string> argv_strings{bin};
  argv_strings.insert(argv_strings.end(), args.begin(), args.end());
  const pid_t pid = ::fork();
  if (pid == 0) {
    if (!std::freopen(out.c_str(), "w", stdout) || !std::freopen(err.c_str(), "w", stderr)) ::_exit(126);
    std::vector<char*> argv;
    for (std::string& s : argv_strings)
      argv.push_back(s.data());
    argv.push_back(nullptr);
    ::execv(bin.c_str(), argv.data());
    ::_exit(127);
  }
  return pid;
}

// Waits (bounded) until `dir` holds a hidden temporary file: the command is writing its output. Up to
// 2 minutes: on a loaded 2-core CI machine the pipeline before the first write took over 30 s once.
bool wait_for_temporary(const fs::path& dir, pid_t pid) {
  for (int i = 0; i < 4800; ++i) {
    if (has_hidden_temporary(dir)) return true;
    int status = 0;
    if (::waitpid(pid, &status, WNOHANG) == pid) return false;  // ended before writing anything
    std::this_thread::sleep_for(std::chrono::milliseconds(25));
  }
  return false;
}

struct SignalCase {
  int signal;
  int exit_code;
};

class CliSignal : public ::testing::TestWithParam<SignalCase> {};

TEST_P(CliSignal, MakeRemovesItsTemporaryFilesAndExitsWithTheSignalsCode) {
  const fs::path dir = foldkit::test::temp_dir("outputs-signal");
  fs::create_directory(dir / "out");
  // PNG at 600 dpi of several sheets: the temporaries exist for seconds while the sheets render. On A5
  // there are more of them than on A4 (2), so a test process descheduled on a loaded machine between
  // seeing the first temporary and sending the signal still finds the command writing.
  const pid_t pid =
      spawn_foldkit(dir, {"make", foldkit::test::example_mesh("spot_350.obj").string(), "--size", "160mm",
                          "--paper", "A5", "--dpi", "600", "-o", (dir / "out" / "m.png").string(), "-q"});
  ASSERT_GT(pid, 0);
  ASSERT_TRUE(wait_for_temporary(dir / "out", pid)) << slurp(dir / "stderr.txt");
  ::kill(pid, GetParam().signal);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status)) << "ended by the signal itself, without clean-up";
  EXPECT_EQ(WEXITSTATUS(status), GetParam().exit_code);
  EXPECT_TRUE(entries(dir / "out").empty()) << ::testing::PrintToString(entries(dir / "out"));
  EXPECT_NE(slurp(dir / "stderr.txt").find("foldkit: "), std::string::npos);
}

TEST_P(CliSignal, UnfoldStopsWithTheSignalsCodeWhileItsOutputWaits) {
  const fs::path dir = foldkit::test::temp_dir("outputs-signal-unfold");
  // A FIFO nobody reads: unfold waits at the output, a state the test can see in /proc.
  const fs::path fifo = dir / "net.obj";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const pid_t pid = spawn_foldkit(
      dir, {"unfold", foldkit::test::example_mesh("fish_350.obj").string(), "-o", fifo.string()});
  ASSERT_GT(pid, 0);
  bool waiting = false;
  for (int i = 0; i < 1200 && !waiting; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(25));
    waiting = slurp("/proc/" + std::to_string(pid) + "/wchan").find("wait_for_partner") != std::string::npos;
  }
  EXPECT_TRUE(waiting) << "unfold never reached its output";
  ::kill(pid, GetParam().signal);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), GetParam().exit_code);
  EXPECT_TRUE(fs::is_fifo(fifo));
  EXPECT_FALSE(has_hidden_temporary(dir));
}

INSTANTIATE_TEST_SUITE_P(IntAndTerm, CliSignal,
                         ::testing::Values(SignalCase{SIGINT, 130}, SignalCase{SIGTERM, 143}),
                         [](const auto& info) { return info.param.signal == SIGINT ? "Sigint" : "Sigterm"; });

}  // namespace
