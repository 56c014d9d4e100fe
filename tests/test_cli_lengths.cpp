// Bounded values on the command line (cli/length_option): every length option takes units through the
// one length parser, and a value out of range is refused at once with readable bounds, never a
// 309-digit number.
#include <gtest/gtest.h>

#include <regex>
#include <string>

#include <nlohmann/json.hpp>

#include "test_paths.hpp"

namespace fs = std::filesystem;
using foldkit::test::run_foldkit;

namespace {

std::string mesh() {
  return foldkit::test::example_mesh("spot_128.obj").string();
}

// No run of 20 digits: the mark of a double printed with %f.
bool has_long_number(const std::string& s) {
  return std::regex_search(s, std::regex("[0-9]{20}"));
}

}  // namespace

TEST(CliLengths, EveryLayoutLengthTakesUnits) {
  const fs::path dir = foldkit::test::temp_dir("lengths");
  const auto run = run_foldkit({"make",        mesh(),          "-o",         (dir / "m.pdf").string(),
                                "--size",      "6in",           "--margin",   "1cm",
                                "--tab-width", "0.2in",         "--spacing",  "2mm",
                                "--label-min", "0.25cm",        "--regmarks", "--regmark-inset",
                                "1cm",         "--regmark-arm", "0.8in",      "--regmark-square",
                                "0.5cm",       "--bleed",       "0.05cm",     "--paper",
                                "21x29.7cm",   "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto j = nlohmann::json::parse(run.out);
  EXPECT_NEAR(j["size_mm"].get<double>(), 152.4, 1e-9);
  EXPECT_NEAR(j["paper_mm"][0].get<double>(), 210, 1e-9);
  EXPECT_NEAR(j["paper_mm"][1].get<double>(), 297, 1e-9);
}

TEST(CliLengths, ALengthOutOfRangeNamesTheBoundsInMillimetres) {
  struct Case {
    std::string option, value, bounds;
  };
  for (const Case& c : {Case{"--margin", "1e300mm", "between 0 mm and 200 mm"},
                        Case{"--margin", "-5", "between 0 mm and 200 mm"},
                        Case{"--tab-width", "1e308in", "between 0.5 mm and 50 mm"},
                        Case{"--spacing", "6cm", "between 0 mm and 50 mm"},
                        Case{"--label-min", "1in", "between 0.5 mm and 3.5 mm"},
                        Case{"--bleed", "2cm", "between 0 mm and 10 mm"},
                        Case{"--size", "1e300", "between 1 mm and 10000 mm"},
                        Case{"--regmark-arm", "1e300", "between 1 mm and 100 mm"},
                        Case{"--paper", "1e9x1e9mm", "between 10 mm and 3000 mm"}}) {
    const auto run = run_foldkit({"make", mesh(), "-o", "never-written.pdf", c.option, c.value});
    EXPECT_EQ(run.exit_code, 2) << c.option << " " << c.value << ": " << run.err;
    EXPECT_NE(run.err.find(c.option), std::string::npos) << run.err;
    EXPECT_NE(run.err.find(c.bounds), std::string::npos) << run.err;
    EXPECT_FALSE(has_long_number(run.err)) << run.err;
    EXPECT_FALSE(fs::exists("never-written.pdf"));
  }
}

TEST(CliLengths, ALengthThatIsNoLengthSaysWhatALengthLooksLike) {
  const auto run = run_foldkit({"make", mesh(), "-o", "x.pdf", "--margin", "ten"});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("expected a length such as 5mm"), std::string::npos) << run.err;
}

TEST(CliLengths, PlainNumbersOutOfRangeNameTheirBoundsToo) {
  struct Case {
    std::vector<std::string> args;
    std::string bounds;
  };
  const std::string m = mesh();
  for (const Case& c :
       {Case{{"make", m, "-o", "x.png", "--dpi", "1e300"}, "between 10 and 2400 dpi"},
        Case{{"make", m, "-o", "x.png", "--dpi", "1e400"}, "between 10 and 2400 dpi"},
        Case{{"make", m, "-o", "x.pdf", "--time-limit", "1e300"}, "between 0.01 and 1000000 s"},
        Case{{"make", m, "-o", "x.pdf", "--max-faces", "2"}, "between 4 and 100000000 faces"},
        Case{{"make", m, "-o", "x.pdf", "--flat-angle", "nan"}, "between 0 and 30 degrees"},
        Case{{"cut", m, "--dry-run", "--ready-timeout", "1e300"}, "between 0.1 and 3600 s"},
        Case{{"cut", m, "--dry-run", "--overcut", "1e300"}, "between 0 mm and 10 mm"},
        Case{{"inspect", m, "--max-faces", "-1"}, "between 4 and 100000000 faces"},
        Case{{"sim", "job.gpgl", "--device", "cameo4", "--paper", "1e9x1e9mm"},
             "between 10 mm and 3000 mm"}}) {
    const auto run = run_foldkit(c.args);
    EXPECT_EQ(run.exit_code, 2) << run.err;
    EXPECT_NE(run.err.find(c.bounds), std::string::npos) << run.err;
    EXPECT_FALSE(has_long_number(run.err)) << run.err;
  }
}

TEST(CliLengths, ACalibrationOffsetTakesUnitsThroughTheSameParser) {
  const fs::path config = foldkit::test::temp_dir("lengths-config");
  // The offset is stored under XDG_CONFIG_HOME: a test must not touch the user's own.
  setenv("XDG_CONFIG_HOME", config.c_str(), 1);
  const auto cm = run_foldkit({"calibrate", "--device", "cameo4", "--offset=0.08,-0.12cm", "--json"});
  ASSERT_EQ(cm.exit_code, 0) << cm.err;
  const auto j = nlohmann::json::parse(cm.out);
  EXPECT_NEAR(j["offset_mm"][0].get<double>(), 0.8, 1e-9);
  EXPECT_NEAR(j["offset_mm"][1].get<double>(), -1.2, 1e-9);
  const auto in = run_foldkit({"calibrate", "--device", "cameo4", "--offset=-0.1in,0.5mm", "--json"});
  ASSERT_EQ(in.exit_code, 0) << in.err;
  EXPECT_NEAR(nlohmann::json::parse(in.out)["offset_mm"][0].get<double>(), -2.54, 1e-9);
  EXPECT_EQ(run_foldkit({"calibrate", "--device", "cameo4", "--offset=1,x"}).exit_code, 2);
  unsetenv("XDG_CONFIG_HOME");
}
