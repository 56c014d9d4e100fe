// What a mistyped command line prints (cli/usage_errors): CLI11's own message naming the word it did not
// understand, the subcommand or option the user most likely meant, one line, exit code 2.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "test_paths.hpp"

using foldkit::test::run_foldkit;

namespace {

std::size_t lines(const std::string& s) {
  return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n'));
}

}  // namespace

TEST(CliUsage, AMistypedSubcommandNamesTheWordAndTheNearestSubcommand) {
  for (const std::string typo : {"mak", "mkae", "maek"}) {
    const auto run = run_foldkit({typo});
    EXPECT_EQ(run.exit_code, 2) << typo;
    EXPECT_NE(run.err.find("not expected: " + typo), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("did you mean make?"), std::string::npos) << run.err;
    EXPECT_EQ(run.err.find("A subcommand is required"), std::string::npos) << run.err;
    EXPECT_EQ(lines(run.err), 1u) << run.err;
  }
  const auto unfold = run_foldkit({"unfodl", "mesh.obj"});
  EXPECT_EQ(unfold.exit_code, 2);
  EXPECT_NE(unfold.err.find("did you mean unfold?"), std::string::npos) << unfold.err;
}

TEST(CliUsage, AnUnknownTopLevelOptionIsShownWithTheListOfSubcommands) {
  const auto run = run_foldkit({"--foo"});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("not expected: --foo"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("make, unfold, inspect"), std::string::npos) << run.err;
  EXPECT_EQ(run.err.find("A subcommand is required"), std::string::npos) << run.err;
}

TEST(CliUsage, AMistypedOptionOfASubcommandNamesTheNearestOptionAndTheSubcommandsHelp) {
  const std::string mesh = foldkit::test::example_mesh("spot_128.obj").string();
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"make", "--sizee", "10", mesh, "-o", "x.pdf"},
        std::vector<std::string>{"make", mesh, "--sizee=10mm", "-o", "x.pdf"}}) {
    const auto run = run_foldkit(args);
    EXPECT_EQ(run.exit_code, 2) << run.err;
    EXPECT_NE(run.err.find("--sizee"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("did you mean --size?"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("foldkit make --help"), std::string::npos) << run.err;
  }
  const auto cut = run_foldkit({"cut", mesh, "--dryrun"});
  EXPECT_EQ(cut.exit_code, 2);
  EXPECT_NE(cut.err.find("did you mean --dry-run?"), std::string::npos) << cut.err;
}

TEST(CliUsage, AWordFarFromEveryNameGetsNoGuess) {
  const auto run = run_foldkit({"make", foldkit::test::example_mesh("spot_128.obj").string(), "-o", "x.pdf",
                                "--completely-unrelated"});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("--completely-unrelated"), std::string::npos) << run.err;
  EXPECT_EQ(run.err.find("did you mean"), std::string::npos) << run.err;
}

TEST(CliUsage, NoSubcommandAtAllListsThemAndHelpAndVersionStillExitZero) {
  const auto none = run_foldkit({});
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_NE(none.err.find("make, unfold"), std::string::npos) << none.err;
  EXPECT_EQ(run_foldkit({"--help"}).exit_code, 0);
  EXPECT_EQ(run_foldkit({"make", "--help"}).exit_code, 0);
  const auto version = run_foldkit({"--version"});
  EXPECT_EQ(version.exit_code, 0);
  EXPECT_FALSE(version.out.empty());
}
