// The --json scheme of every command (docs/json.md): one version key, counts end in _count, lists are
// plural nouns, every other number carries its unit (_mm, _s, _gf, ...) or says it is a fraction, and
// no number is written as prose. Each command's report is parsed and every key walked.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scoped_env.hpp"
#include "test_paths.hpp"

namespace fs = std::filesystem;
using foldkit::test::run_foldkit;
using foldkit::test::run_foldkit_in;
using nlohmann::json;

namespace {

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

bool has_unit(const std::string& key) {
  for (const char* unit :
       {"_mm", "_mm2", "_s", "_rad", "_px", "_mb", "_gf", "_mm_per_s", "_mm_per_unit", "_units", "_units2"})
    if (ends_with(key, unit)) return true;
  return false;
}

bool is_fraction(const std::string& key) {
  return key == "coverage" || ends_with(key, "_coverage") || ends_with(key, "_fraction") ||
         ends_with(key, "_ratio");
}

// Integers that are names rather than amounts: an ordinal, a printed number, a USB address, a seed.
bool is_identifier(const std::string& key) {
  for (const char* id : {"schema_version", "sheet", "step", "seam", "holder", "bus", "address", "seed",
                         "genus", "euler_characteristic"})
    if (key == id) return true;
  return false;
}

// Objects keyed by the data's own names (a table): by size band under a unit, by profile key.
bool is_table(const std::string& key) {
  return has_unit(key) || key == "sources";
}

// Lists are plural nouns ("media" is the plural of medium).
bool is_plural(const std::string& key) {
  return ends_with(key, "s") || key == "media";
}

// Keys whose strings are sentences by design.
bool is_prose(const std::string& key) {
  return key == "notes" || key == "error" || key == "problem" || key == "usb_error";
}

// Every breach of the scheme under `value` (reached through `key`), one line each.
void walk(const json& value, const std::string& key, const std::string& where, bool free_keys,
          std::vector<std::string>& bad) {
  static const std::regex snake("[a-z][a-z0-9_]*");
  static const std::regex number_prose("\\s*[-+]?[0-9][0-9.]*\\s+\\S.*");
  const std::string at = where + "/" + key;
  if (!free_keys && !key.empty() && !std::regex_match(key, snake)) bad.push_back(at + ": not snake_case");
  if (key.find("seconds") != std::string::npos) bad.push_back(at + ": seconds are _s");
  if (value.is_object()) {
    for (const auto& [k, v] : value.items())
      walk(v, k, at, is_table(key), bad);
  } else if (value.is_array()) {
    if (!free_keys && !is_plural(key) && !has_unit(key)) bad.push_back(at + ": a list is a plural noun");
    for (const json& v : value)
      if (v.is_object() || v.is_array()) walk(v, "", at, true, bad);
  } else if (value.is_number_integer() || value.is_number_unsigned()) {
    if (!free_keys && !ends_with(key, "_count") && !is_identifier(key) && !has_unit(key))
      bad.push_back(at + ": an integer is a _count, an identifier or has a unit");
  } else if (value.is_number_float()) {
    if (!free_keys && !has_unit(key) && !is_fraction(key))
      bad.push_back(at + ": a number has a unit or is a fraction");
  } else if (value.is_string()) {
    if (!is_prose(key) && std::regex_match(value.get<std::string>(), number_prose))
      bad.push_back(at + ": a number written as prose: " + value.get<std::string>());
  }
}

// Parses a command's standard output and checks the whole report.
json expect_scheme(const foldkit::test::CliRun& run, const std::string& command) {
  EXPECT_EQ(run.exit_code, 0) << command << ": " << run.err;
  json j;
  try {
    j = json::parse(run.out);
  } catch (const json::exception& e) {
    ADD_FAILURE() << command << ": not JSON (" << e.what() << "): " << run.out.substr(0, 200);
    return j;
  }
  EXPECT_EQ(j.value("schema_version", 0), 1) << command;
  std::vector<std::string> bad;
  for (const auto& [k, v] : j.items())
    walk(v, k, command, false, bad);
  EXPECT_TRUE(bad.empty()) << ::testing::PrintToString(bad);
  return j;
}

}  // namespace

TEST(CliJson, TheWalkCatchesEveryKindOfBreach) {
  std::vector<std::string> bad;
  const json old = json::parse(R"({"faces": 12, "seconds": 1.5, "usb": [], "cut": "130 gf 80 mm/s x1",
                                   "Size": 3, "scale": 0.5})");
  for (const auto& [k, v] : old.items())
    walk(v, k, "", false, bad);
  EXPECT_EQ(bad.size(), 8u) << ::testing::PrintToString(bad);
  bad.clear();
  const json good = json::parse(R"({"face_count": 12, "unfold_s": 1.5, "usb_devices": [], "sheet": 2,
                                    "cut": {"force_gf": 130, "speed_mm_per_s": 80, "pass_count": 1},
                                    "median_unfold_s": {"<300": 0.2}, "notes": ["3 seams cut"]})");
  for (const auto& [k, v] : good.items())
    walk(v, k, "", false, bad);
  EXPECT_TRUE(bad.empty()) << ::testing::PrintToString(bad);
}

TEST(CliJson, MakeUnfoldInspectAndCutFollowTheScheme) {
  const fs::path dir = foldkit::test::temp_dir("json-scheme");
  const std::string mesh = foldkit::test::example_mesh("spot_128.obj").string();
  const json make = expect_scheme(
      run_foldkit({"make", mesh, "--size", "120mm", "--hints", "-o", (dir / "s.pdf").string(), "--json"}),
      "make");
  EXPECT_GT(make.value("face_count", 0), 0);
  EXPECT_GE(make.value("layout_s", -1.0), 0.0);
  const json unfold =
      expect_scheme(run_foldkit({"unfold", mesh, "-o", (dir / "net.obj").string(), "--json"}), "unfold");
  EXPECT_GE(unfold.value("unfold_s", -1.0), 0.0);
  EXPECT_FALSE(unfold.contains("part_room_mm")) << "no size, no room";
  const json parts = expect_scheme(
      run_foldkit({"unfold", mesh, "--size", "250mm", "-o", (dir / "parts.obj").string(), "--json"}),
      "unfold");
  EXPECT_GT(parts.value("scale_mm_per_unit", 0.0), 0.0);
  ASSERT_EQ(parts["part_room_mm"].size(), 2u);
  EXPECT_NEAR(parts["part_room_mm"][0].get<double>(), 210 - 2 * 10 - 2 * 8, 2.5) << "A4, margins and borders";
  expect_scheme(run_foldkit({"inspect", mesh, "--json"}), "inspect");
  expect_scheme(run_foldkit({"cut", mesh, "--size", "120mm", "--device", "cameo4", "--dry-run", "--preview",
                             (dir / "c.png").string(), "--json"}),
                "cut");
  ASSERT_EQ(run_foldkit({"cut", mesh, "--size", "120mm", "--device", "cameo4", "-o",
                         (dir / "job.gpgl").string(), "-q"})
                .exit_code,
            0);
  expect_scheme(run_foldkit({"sim", (dir / "job.gpgl").string(), "--device", "cameo4", "--json"}), "sim");
}

TEST(CliJson, ProfilesGiveMediaSettingsAsNumbersAndDevicesFollowTheScheme) {
  const json profiles = expect_scheme(run_foldkit({"profiles", "--json"}), "profiles");
  ASSERT_TRUE(profiles.contains("media"));
  ASSERT_FALSE(profiles["media"].empty());
  for (const json& m : profiles["media"]) {
    EXPECT_TRUE(m["cut"]["force_gf"].is_number()) << m.dump();
    EXPECT_TRUE(m["cut"]["speed_mm_per_s"].is_number()) << m.dump();
    EXPECT_GE(m["cut"]["pass_count"].get<int>(), 1) << m.dump();
  }
  expect_scheme(run_foldkit({"devices", "--json"}), "devices");
}

TEST(CliJson, CalibrateFollowsTheScheme) {
  const fs::path dir = foldkit::test::temp_dir("json-calibrate");
  const foldkit::test::ScopedEnv xdg("XDG_CONFIG_HOME", (dir / "config").string());
  expect_scheme(run_foldkit({"calibrate", "--device", "cameo4", "--offset", "0.5,0.5mm", "--json"}),
                "calibrate --offset");
  expect_scheme(run_foldkit({"calibrate", "--device", "cameo4", "--show", "--json"}), "calibrate --show");
  expect_scheme(run_foldkit({"calibrate", "--device", "cameo4", "-o", (dir / "page.pdf").string(), "--job",
                             (dir / "job.gpgl").string(), "--json"}),
                "calibrate");
}

TEST(CliJson, BenchAndTheLayoutBenchFollowTheScheme) {
  const fs::path corpus = foldkit::test::temp_dir("json-bench");
  fs::copy_file(foldkit::test::example_mesh("spot_128.obj"), corpus / "spot_128.obj");
  const json bench = expect_scheme(
      run_foldkit({"bench", corpus.string(), "--methods", "mst", "--json", "--time-limit", "20"}), "bench");
  ASSERT_EQ(bench["rows"].size(), 1u);
  EXPECT_EQ(bench["rows"][0]["face_count"].get<int>(), 128);
  const json layout = expect_scheme(
      run_foldkit({"bench", corpus.string(), "--layout", "--sizes", "150", "--json"}), "bench --layout");
  ASSERT_EQ(layout["rows"].size(), 1u);
  // Every run's parts are checked as every unfolding is: congruent, overlap-free, partners matched.
  EXPECT_TRUE(layout["rows"][0]["part_problems"].is_array());
  EXPECT_TRUE(layout["rows"][0]["part_problems"].empty()) << layout["rows"][0].dump();
  EXPECT_EQ(layout["totals"]["runs_with_invalid_parts_count"], 0);
}
