// The CLI on awkward and broken inputs, end to end: `foldkit inspect` on the shared bad/ and tricky/ sets
// and on small files written here, checking exit codes and the one-line `foldkit: <file>: <problem>` message.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "cmd_inspect.hpp"
#include "in_process.hpp"
#include "test_paths.hpp"

namespace fs = std::filesystem;

namespace {

struct CliRun {
  int exit_code = -1;
  bool signalled = false;
  std::string out, err;
};

using foldkit::test::slurp;

// Runs foldkit with arguments (each single-quoted), capturing stdout and stderr into temp files.
CliRun run_foldkit(const std::vector<std::string>& args) {
  const fs::path dir = foldkit::test::temp_dir("cli_inputs");
  std::string cmd;
  const auto quoted = [&cmd](const std::string& s) {
    cmd.append(" '");
    cmd.append(s);
    cmd.append("'");
  };
  quoted(foldkit::test::foldkit_binary().string());
  for (const auto& a : args)
    quoted(a);
  cmd.append(" >");
  quoted((dir / "out").string());
  cmd.append(" 2>");
  quoted((dir / "err").string());
  const int status = std::system(cmd.c_str());
  CliRun r;
  if (WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
  r.signalled = WIFSIGNALED(status) || (WIFEXITED(status) && WEXITSTATUS(status) > 128);
  r.out = slurp(dir / "out");
  r.err = slurp(dir / "err");
  fs::remove_all(dir);
  return r;
}

int count_lines(const std::string& s) {
  return static_cast<int>(std::count(s.begin(), s.end(), '\n'));
}

}  // namespace

TEST(CliInputs, EveryBadCorpusFileGivesOneLineAndExitCodeThree) {
  auto shared = foldkit::test::shared_meshes();
  if (!shared) GTEST_SKIP() << "../shared/meshes not present";
  int files = 0;
  for (const auto& entry : fs::directory_iterator(*shared / "bad")) {
    const std::string file = entry.path().string();
    const CliRun r = run_foldkit({"inspect", file});
    EXPECT_FALSE(r.signalled) << file;
    EXPECT_EQ(r.exit_code, 3) << file << ": " << r.err;
    EXPECT_EQ(count_lines(r.err), 1) << file << ": " << r.err;
    EXPECT_EQ(r.err.rfind("foldkit: " + file + ": ", 0), 0u) << r.err;
    EXPECT_TRUE(r.out.empty()) << file;
    ++files;
  }
  EXPECT_GE(files, 8);
}

TEST(CliInputs, EveryTrickyCorpusFileIsInspectedSuccessfully) {
  auto shared = foldkit::test::shared_meshes();
  if (!shared) GTEST_SKIP() << "../shared/meshes not present";
  for (const auto& entry : fs::directory_iterator(*shared / "tricky")) {
    foldkit::cli::InspectArgs args;
    args.mesh = entry.path().string();
    args.json = true;
    const auto j = nlohmann::json::parse(foldkit::test::stdout_of([&] { foldkit::cli::run_inspect(args); }));
    EXPECT_GT(j["face_count"].get<int>(), 0);
    EXPECT_TRUE(j["orientable"].get<bool>());
  }
}

TEST(CliInputs, TrickyFilesReportWhatTheLoaderRepaired) {
  auto shared = foldkit::test::shared_meshes();
  if (!shared) GTEST_SKIP() << "../shared/meshes not present";
  const auto inspect = [&](const std::string& name) {
    foldkit::cli::InspectArgs args;
    args.mesh = (*shared / "tricky" / name).string();
    args.json = true;
    return nlohmann::json::parse(foldkit::test::stdout_of([&] { foldkit::cli::run_inspect(args); }));
  };
  const auto two = inspect("two_components.obj");
  EXPECT_EQ(two["component_count"], 2);
  EXPECT_EQ(two["genus"], 1);
  EXPECT_NE(two["notes"].dump().find("2 connected components: unfolded separately"), std::string::npos);
  const auto quads = inspect("quads_ngons.obj");
  EXPECT_EQ(quads["face_count"], 466);
  EXPECT_EQ(quads["genus"], 2);
  const auto hole = inspect("open_hole.obj");
  EXPECT_EQ(hole["boundary_loop_count"], 1);
  EXPECT_FALSE(hole["closed"].get<bool>());
  EXPECT_NE(inspect("flipped_faces.obj")["notes"].dump().find("re-oriented 5 faces"), std::string::npos);
  EXPECT_NE(inspect("nonmanifold_vertex.obj")["notes"].dump().find("split 1 non-manifold vertex"),
            std::string::npos);
  EXPECT_NE(inspect("degenerate.obj")["notes"].dump().find("zero-area"), std::string::npos);
}

TEST(CliInputs, InspectJsonDescribesTheBundledBob) {
  const CliRun r = run_foldkit({"inspect", "--json", foldkit::test::example_mesh("bob_128.obj").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["face_count"], 128);
  EXPECT_EQ(j["genus"], 1);
  EXPECT_EQ(j["component_count"], 1);
  EXPECT_TRUE(j["closed"].get<bool>());
  const int classes = j["vertex_classes"]["elliptic_count"].get<int>() +
                      j["vertex_classes"]["hyperbolic_count"].get<int>() +
                      j["vertex_classes"]["flat_count"].get<int>();
  EXPECT_EQ(classes, j["vertex_count"].get<int>());
  EXPECT_LT(j["bounding_box"]["min_units"][0].get<double>(), j["bounding_box"]["max_units"][0].get<double>());
}

TEST(CliInputs, InspectTableNamesEveryQuantity) {
  const CliRun r = run_foldkit({"inspect", foldkit::test::example_mesh("spot_128.obj").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* key : {"faces", "vertices", "edges", "boundary loops", "components", "genus", "closed",
                          "orientable", "elliptic", "hyperbolic", "flat", "bounding box"})
    EXPECT_NE(r.out.find(key), std::string::npos) << key;
}

TEST(CliInputs, MaxFacesDecimatesBeforeInspecting) {
  const CliRun r = run_foldkit(
      {"inspect", "--json", "--max-faces", "120", foldkit::test::example_mesh("spot_350.obj").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_LE(j["face_count"].get<int>(), 120);
  EXPECT_EQ(j["original_face_count"], 350);
  EXPECT_EQ(j["genus"], 0);
}

TEST(CliInputs, MissingFileExitsWithInputCode) {
  const CliRun r = run_foldkit({"inspect", "/nonexistent/mesh.obj"});
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_EQ(r.err, "foldkit: /nonexistent/mesh.obj: no such file\n");
}

TEST(CliInputs, UnknownExtensionExitsWithInputCode) {
  const fs::path dir = foldkit::test::temp_dir("cli_ext");
  std::ofstream(dir / "m.dae") << "<COLLADA/>";
  const CliRun r = run_foldkit({"inspect", (dir / "m.dae").string()});
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.err.find("unsupported file type '.dae'"), std::string::npos) << r.err;
  fs::remove_all(dir);
}

TEST(CliInputs, NonPositiveMaxFacesIsAUsageError) {
  const CliRun r =
      run_foldkit({"inspect", "--max-faces", "0", foldkit::test::example_mesh("spot_128.obj").string()});
  EXPECT_EQ(r.exit_code, 2);
}
