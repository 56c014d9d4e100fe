// `foldkit bench` end to end on a two-mesh corpus: one row per mesh, every run checked, JSON summary.
#include <gtest/gtest.h>

#include <filesystem>

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
