// `foldkit bench` end to end on a two-mesh corpus: one row per mesh, every run checked, JSON summary.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "test_paths.hpp"

namespace fs = std::filesystem;
using foldkit::test::run_foldkit;

TEST(CliBench, JsonRowsGivePiecesSecondsMemoryAndAValidCheckForEveryMethod) {
  fs::path dir = foldkit::test::temp_dir("bench");
  fs::copy_file(foldkit::test::example_mesh("spot_128.obj"), dir / "spot_128.obj");
  fs::copy_file(foldkit::test::example_mesh("bob_128.obj"), dir / "bob_128.obj");
  auto run = run_foldkit(
      {"bench", "--corpus", dir.string(), "--methods", "mst,search", "--json", "--time-limit", "20"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  ASSERT_FALSE(run.signalled);
  const auto j = nlohmann::json::parse(run.out);
  ASSERT_EQ(j["rows"].size(), 2u);
  for (const auto& row : j["rows"]) {
    EXPECT_EQ(row["face_count"].get<int>(), 128);
    EXPECT_TRUE(row["valid"].get<bool>()) << row.dump();
    const auto& search = row["results"]["search"];
    EXPECT_EQ(search["piece_count"].get<int>(), 1) << row.dump();
    EXPECT_GT(search["peak_mb"].get<double>(), 0.0);
    EXPECT_GE(search["unfold_s"].get<double>(), 0.0);
    EXPECT_GT(row["results"]["mst"]["piece_count"].get<int>(), 1);
  }
  EXPECT_EQ(j["summary"]["search"]["one_piece_count"].get<int>(), 2);
  EXPECT_EQ(j["summary"]["mst"]["valid_count"].get<int>(), 2);
}

TEST(CliBench, AMissingCorpusIsAnInputError) {
  auto run = run_foldkit({"bench", "--corpus", "/nonexistent/meshes"});
  EXPECT_EQ(run.exit_code, 3) << run.err;
  EXPECT_NE(run.err.find("/nonexistent/meshes"), std::string::npos) << run.err;
}

TEST(CliBench, AnUnknownMethodIsAUsageError) {
  fs::path dir = foldkit::test::temp_dir("bench-bad");
  auto run = run_foldkit({"bench", "--corpus", dir.string(), "--methods", "mst,magic"});
  EXPECT_EQ(run.exit_code, 2) << run.err;
}

TEST(CliBench, TakesTheFolderAsAnArgumentFromAnyDirectory) {
  const fs::path corpus = foldkit::test::temp_dir("bench-arg");
  fs::copy_file(foldkit::test::example_mesh("spot_128.obj"), corpus / "spot_128.obj");
  // Run from a folder with no ../shared beside it: nothing may come from the source tree.
  const fs::path elsewhere = foldkit::test::temp_dir("bench-cwd");
  const auto run =
      foldkit::test::run_foldkit_in(elsewhere, {"bench", corpus.string(), "--methods", "mst", "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto j = nlohmann::json::parse(run.out);
  ASSERT_EQ(j["rows"].size(), 1u);
  EXPECT_TRUE(j["rows"][0]["valid"].get<bool>()) << j.dump();
}

TEST(CliBench, WithoutAFolderOrASharedCorpusItSaysWhatToPass) {
  const fs::path elsewhere = foldkit::test::temp_dir("bench-none") / "a" / "b";
  fs::create_directories(elsewhere);
  const auto run = foldkit::test::run_foldkit_in(elsewhere, {"bench"});
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_NE(run.err.find("foldkit bench /path/to/meshes"), std::string::npos) << run.err;
  const auto layout = foldkit::test::run_foldkit_in(elsewhere, {"bench", "--layout"});
  EXPECT_EQ(layout.exit_code, 2) << layout.err;
}

namespace {

// A `bench --layout --json` report of one run of lowpoly/cube.obj at 100 mm and one of a mesh the
// corpus does not hold, with figures no layout of the cube gives.
nlohmann::json report_before() {
  auto row = [](const std::string& mesh, long sheets, long parts) {
    return nlohmann::json{
        {"mesh", mesh},        {"size_mm", 100.0}, {"sheet_count", sheets}, {"area_bound_sheet_count", 1},
        {"part_count", parts}, {"coverage", 0.25}, {"seam_count", 12},      {"seams_without_tab_count", 2},
        {"wall_s", 9.5}};
  };
  return {
      {"schema_version", 1},
      {"rows", {row("lowpoly/cube.obj", 7, 6), row("absent.obj", 40, 99), {{"mesh", "x"}, {"error", "e"}}}}};
}

fs::path cube_corpus(const std::string& tag) {
  const fs::path corpus = foldkit::test::temp_dir(tag);
  fs::create_directories(corpus / "lowpoly");
  fs::copy_file(foldkit::test::source_dir() / "tests" / "data" / "lowpoly" / "cube.obj",
                corpus / "lowpoly" / "cube.obj");
  return corpus;
}

fs::path written(const fs::path& dir, const std::string& name, const std::string& text) {
  std::ofstream(dir / name, std::ios::binary) << text;
  return dir / name;
}

}  // namespace

TEST(CliBench, TheLayoutRunsMeasuredBeforeAreShownBesideTheRunsNowAndTotalledOverTheRunsBothShare) {
  const fs::path corpus = cube_corpus("bench-before");
  const fs::path before = written(corpus, "before.json", report_before().dump());
  const std::vector<std::string> args{"bench", "--layout", corpus.string(), "--sizes",
                                      "100",   "--before", before.string()};
  std::vector<std::string> json_args = args;
  json_args.push_back("--json");
  const auto run = run_foldkit(json_args);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto j = nlohmann::json::parse(run.out);
  ASSERT_EQ(j["rows"].size(), 1u);
  const auto& row = j["rows"][0];
  EXPECT_EQ(row["before"]["sheet_count"], 7) << row.dump();
  EXPECT_EQ(row["before"]["part_count"], 6);
  EXPECT_EQ(row["before"]["seams_without_tab_count"], 2);
  const auto& totals = j["before"]["totals"];
  EXPECT_EQ(j["before"]["file"], before.string());
  EXPECT_EQ(totals["run_count"], 1) << "the mesh absent from the corpus is not compared";
  EXPECT_EQ(totals["sheet_count"], 7);
  EXPECT_EQ(totals["part_count"], 6);
  EXPECT_DOUBLE_EQ(totals["median_coverage"].get<double>(), 0.25);
  const auto& now = j["before"]["now_totals"];
  EXPECT_EQ(now["run_count"], 1);
  EXPECT_EQ(now["sheet_count"], row["sheet_count"]);
  EXPECT_EQ(now["part_count"], row["part_count"]);

  const auto text = run_foldkit(args);
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("| before  area parts coverage"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("on the 1 runs measured both times"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("before: 7 sheets, area bound 1 (x7.00)"), std::string::npos) << text.out;
}

TEST(CliBench, AReportBeforeThatIsNotOneIsRefusedWithItsProblemBeforeAnyRun) {
  const fs::path corpus = cube_corpus("bench-before-bad");
  nlohmann::json negative = report_before();
  negative["rows"][0]["sheet_count"] = -1;
  nlohmann::json missing = report_before();
  missing["rows"][0].erase("coverage");
  nlohmann::json other_scheme = report_before();
  other_scheme["schema_version"] = 2;
  nlohmann::json fraction = report_before();
  fraction["rows"][0]["part_count"] = 2.5;
  const std::vector<std::pair<fs::path, std::string>> cases{
      {corpus / "absent.json", "no such benchmark report"},
      {corpus / "lowpoly", "not a file"},
      {written(corpus, "text.json", "sheets: 3"), "not a JSON report"},
      {written(corpus, "array.json", "[1, 2]"), "not a JSON report"},
      {written(corpus, "v2.json", other_scheme.dump()), "schema_version 1 expected"},
      {written(corpus, "negative.json", negative.dump()),
       "row 1: 'sheet_count' is not a number of at least 0"},
      {written(corpus, "missing.json", missing.dump()), "row 1 has no figure 'coverage'"},
      {written(corpus, "fraction.json", fraction.dump()), "row 1: 'part_count' is not a count"},
      {written(corpus, "large.json", std::string(5u << 20, ' ')), "too large for a benchmark report"},
  };
  for (const auto& [file, problem] : cases) {
    const auto run = run_foldkit({"bench", "--layout", corpus.string(), "--before", file.string()});
    EXPECT_EQ(run.exit_code, 3) << file << ": " << run.err;
    EXPECT_FALSE(run.signalled) << file;
    EXPECT_EQ(run.err.rfind("foldkit: " + file.string() + ": ", 0), 0u) << run.err;
    EXPECT_NE(run.err.find(problem), std::string::npos) << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << "one line: " << run.err;
    EXPECT_EQ(run.out, "") << "no run before the report is read: " << file;
  }
}
