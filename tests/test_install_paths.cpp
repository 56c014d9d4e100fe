// Where foldkit finds its profiles and the Hershey font: relative to the executable, then the user's
// folder, never through a path of the source tree; and what the CLI says when they are not there.
#include <sys/wait.h>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "foldkit/devices/install_paths.hpp"
#include "foldkit/devices/profile.hpp"
#include "foldkit/error.hpp"
#include "scoped_env.hpp"
#include "test_paths.hpp"

namespace foldkit::devices {
namespace {

namespace fs = std::filesystem;

void touch(const fs::path& file, const std::string& text = "") {
  fs::create_directories(file.parent_path());
  std::ofstream(file) << text;
}

std::string slurp(const fs::path& file) {
  std::ifstream in(file);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The built-in copy-80 profile under another name.
std::string renamed_copy80(const std::string& name) {
  const std::string from = "name = \"Copy paper 80 gsm\"";
  std::string text = slurp(test::profiles_dir() / "media" / "copy-80.toml");
  const std::size_t at = text.find(from);
  if (at != std::string::npos) text.replace(at, from.size(), "name = \"" + name + "\"");
  return text;
}

// A prefix laid out as `cmake --install` lays it out: bin/foldkit and share/foldkit/profiles.
struct FakeInstall {
  fs::path root = test::temp_dir("install-paths");
  fs::path prefix = root / "prefix";
  fs::path config = root / "config" / "foldkit";
  InstallPaths paths{prefix / "bin" / "foldkit", config, {root / "data"}};

  FakeInstall() { touch(paths.executable); }
  ~FakeInstall() { fs::remove_all(root); }
  fs::path builtin() const { return prefix / "share" / "foldkit" / "profiles"; }
};

using foldkit::test::ScopedEnv;

TEST(ProfileDirs, AreTheInstalledProfilesBesideTheProgramThenTheUsersOwn) {
  const FakeInstall f;
  fs::create_directories(f.builtin() / "devices");
  fs::create_directories(f.config / "profiles" / "media");
  EXPECT_EQ(profile_dirs(f.paths), (std::vector<fs::path>{f.builtin(), f.config / "profiles"}));
}

TEST(ProfileDirs, SkipAFolderWithNeitherDevicesNorMedia) {
  const FakeInstall f;
  fs::create_directories(f.builtin());
  fs::create_directories(f.config / "profiles" / "devices");
  EXPECT_EQ(profile_dirs(f.paths), (std::vector<fs::path>{f.config / "profiles"}));
  EXPECT_EQ(profile_search_dirs(f.paths), (std::vector<fs::path>{f.builtin(), f.config / "profiles"}));
}

TEST(ProfileDirs, AreEmptyWhenNothingIsInstalledAndNoFolderIsKnown) {
  const FakeInstall f;
  EXPECT_TRUE(profile_dirs(f.paths).empty());
  EXPECT_TRUE(profile_search_dirs(InstallPaths{}).empty());
}

TEST(ProfileDirs, FromTheBuildTreeReachTheSourceProfilesThroughTheBuildsShareFolder) {
  // build/cli/foldkit -> build/share/foldkit/profiles, a link CMake makes to the source's profiles/.
  InstallPaths paths;
  paths.executable = test::foldkit_binary();
  const std::vector<fs::path> dirs = profile_dirs(paths);
  ASSERT_EQ(dirs.size(), 1u);
  EXPECT_TRUE(fs::equivalent(dirs[0], test::profiles_dir())) << dirs[0];
}

TEST(LoadProfiles, AUserProfileWithABuiltinIdReplacesItAndANewIdIsAdded) {
  const FakeInstall f;
  fs::create_directories(f.builtin());
  fs::copy(test::profiles_dir() / "media", f.builtin() / "media");
  const std::string mine = renamed_copy80("My copy paper");
  touch(f.config / "profiles" / "media" / "copy-80.toml", mine);
  touch(f.config / "profiles" / "media" / "my-paper.toml", mine);
  const ProfileSet set = load_profiles(profile_dirs(f.paths));
  EXPECT_EQ(set.medium("copy-80").name, "My copy paper");
  EXPECT_EQ(set.medium("my-paper").name, "My copy paper");
  EXPECT_EQ(set.medium("cardstock-220").name, "Cardstock 220 gsm");
}

TEST(XdgDataDirs, KeepAbsoluteEntriesInOrderAndDefaultToUsrLocalShareAndUsrShare) {
  EXPECT_EQ(xdg_data_dirs("/opt/share:relative::/usr/share"),
            (std::vector<fs::path>{"/opt/share", "/usr/share"}));
  const std::vector<fs::path> defaults{"/usr/local/share", "/usr/share"};
  EXPECT_EQ(xdg_data_dirs(nullptr), defaults);
  EXPECT_EQ(xdg_data_dirs(""), defaults);
  EXPECT_EQ(xdg_data_dirs("only/relative"), defaults);
}

TEST(FindStrokeFont, TakesFoldkitsOwnShareFolderBeforeTheDataDirs) {
  const FakeInstall f;
  touch(f.root / "data" / "hershey-fonts" / "futural.jhf");
  EXPECT_EQ(find_stroke_font(f.paths), f.root / "data" / "hershey-fonts" / "futural.jhf");
  touch(f.prefix / "share" / "hershey-fonts" / "futural.jhf");
  EXPECT_EQ(find_stroke_font(f.paths), f.prefix / "share" / "hershey-fonts" / "futural.jhf");
  touch(f.prefix / "share" / "foldkit" / "fonts" / "futural.jhf");
  EXPECT_EQ(find_stroke_font(f.paths), f.prefix / "share" / "foldkit" / "fonts" / "futural.jhf");
}

TEST(FindStrokeFont, RefusesWithEveryPathLookedAtAndThePackageThatShipsIt) {
  const FakeInstall f;
  try {
    find_stroke_font(f.paths, "rowmans");
    FAIL() << "no font was installed";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find((f.prefix / "share" / "hershey-fonts" / "rowmans.jhf").string()), std::string::npos)
        << what;
    EXPECT_NE(what.find((f.root / "data" / "hershey-fonts" / "rowmans.jhf").string()), std::string::npos)
        << what;
    EXPECT_NE(what.find("hershey-fonts-data"), std::string::npos) << what;
  }
}

TEST(FindStrokeFont, FindsDebiansHersheyFontsThroughTheDefaultDataDirs) {
  if (!fs::exists("/usr/share/hershey-fonts/futural.jhf")) GTEST_SKIP() << "hershey-fonts-data not installed";
  InstallPaths paths;
  paths.data_dirs = xdg_data_dirs(nullptr);
  EXPECT_EQ(find_stroke_font(paths), "/usr/share/hershey-fonts/futural.jhf");
}

TEST(CliProfileDirs, ListTheBuiltinFolderThenTheUsersWhoseProfilesAreAdded) {
  const FakeInstall f;
  touch(f.config / "profiles" / "media" / "my-paper.toml", renamed_copy80("My paper"));
  const ScopedEnv env("XDG_CONFIG_HOME", (f.root / "config").string());
  const test::CliRun r = test::run_foldkit({"profiles", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["profile_dirs"].size(), 2u) << j["profile_dirs"];
  EXPECT_TRUE(fs::equivalent(j["profile_dirs"][0].get<std::string>(), test::profiles_dir()));
  EXPECT_EQ(j["profile_dirs"][1], (f.config / "profiles").string());
  bool mine = false;
  for (const auto& m : j["media"])
    mine = mine || m["id"] == "my-paper";
  EXPECT_TRUE(mine) << r.out;
}

TEST(CliProfileDirs, WithoutAnyProfileTheProgramSaysWhereItLookedAndFails) {
  // A copy of the program outside any prefix or build tree has no built-in profiles.
  const FakeInstall f;
  fs::copy_file(test::foldkit_binary(), f.root / "foldkit");
  const std::string cmd = "cd '" + f.root.string() + "' && env -i XDG_CONFIG_HOME='" +
                          (f.root / "config").string() + "' ./foldkit profiles >out 2>err";
  const int status = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 1);
  const std::string message = slurp(f.root / "err");
  EXPECT_NE(message.find("no device or media profiles found (looked in " +
                         (f.root.parent_path() / "share").string() + "/foldkit/profiles, " +
                         (f.config / "profiles").string() + ")"),
            std::string::npos)
      << message;
  EXPECT_EQ(slurp(f.root / "out"), "") << "no empty tables";
}

}  // namespace
}  // namespace foldkit::devices
