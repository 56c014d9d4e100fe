// Device and media profiles: every built-in one loads, bad files name the file, the key and the problem,
// user profiles replace built-in ones, and the page <-> device transform round-trips.
#include <fstream>
#include <regex>

#include <gtest/gtest.h>

#include "foldkit/devices/profile.hpp"
#include "foldkit/error.hpp"
#include "test_paths.hpp"

namespace foldkit::devices {
namespace {

namespace fs = std::filesystem;

const fs::path kDevices = test::source_dir() / "profiles" / "devices";

// The test device's file with `from` replaced by `to` (the text must occur), written to a temp file.
fs::path edited(const std::string& name, const std::string& from, const std::string& to) {
  std::ifstream in(kDevices / "test.toml");
  std::string text((std::istreambuf_iterator<char>(in)), {});
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  const fs::path out = test::temp_dir("profile") / name;
  std::ofstream(out) << text;
  return out;
}

std::string load_error(const fs::path& file) {
  try {
    (void)load_device_profile(file);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Profile, EveryBuiltInProfileLoads) {
  const ProfileSet set = load_profiles(foldkit::test::profiles_dir());
  EXPECT_EQ(set.devices.size(), 10u);
  EXPECT_EQ(set.media.size(), 4u);
  for (const DeviceProfile& d : set.devices) {
    EXPECT_FALSE(d.name.empty()) << d.id;
    EXPECT_GT(d.units_per_mm, 0) << d.id;
    EXPECT_NE(d.tool(ToolKind::Blade), nullptr) << d.id;
    EXPECT_LE(d.speed_steps.min, d.speed_steps.max) << d.id;
  }
}

TEST(Profile, ReadsTheCameo4AsTheProtocolDocumentDescribesIt) {
  const DeviceProfile d = load_device_profile(kDevices / "cameo4.toml");
  EXPECT_EQ(d.id, "cameo4");
  EXPECT_EQ(d.protocol, Protocol::Gpgl);
  EXPECT_EQ(d.usb_vendor, 0x0b4d);
  EXPECT_EQ(d.usb_product, 0x1137);
  EXPECT_EQ(d.units_per_mm, 20);
  EXPECT_TRUE(d.axes.feed_first);
  EXPECT_DOUBLE_EQ(d.area_width_mm, 304.8);
  ASSERT_NE(d.mat("12x12"), nullptr);
  EXPECT_EQ(d.mat("12x12")->code, 1);
  EXPECT_EQ(d.holders, 2);
  ASSERT_NE(d.tool(ToolKind::Scorer), nullptr);
  EXPECT_EQ(d.tool(ToolKind::Scorer)->holder, 2);
  EXPECT_TRUE(d.regmarks.supported);
  EXPECT_EQ(d.regmarks.search, "TB123");
}

TEST(Profile, EachFoldMethodIsNamedOnceAndItsNameReadsBackAsIt) {
  const auto& choices = foldkit::devices::fold_method_choices();
  ASSERT_EQ(choices.size(), 4u);
  for (std::size_t i = 0; i < choices.size(); ++i) {
    EXPECT_EQ(foldkit::devices::fold_method_name(choices[i].second), choices[i].first);
    for (std::size_t k = 0; k < i; ++k) {
      EXPECT_NE(choices[k].first, choices[i].first);
      EXPECT_NE(choices[k].second, choices[i].second);
    }
  }
}

TEST(Profile, ReadsMediaSettings) {
  const MediaProfile m = load_media_profile(test::source_dir() / "profiles" / "media" / "cardstock-300.toml");
  EXPECT_EQ(m.id, "cardstock-300");
  EXPECT_EQ(m.cut.passes, 2);
  EXPECT_GT(m.cut.force_gf, m.score.force_gf);
  ASSERT_TRUE(m.fold_method.has_value());
  EXPECT_EQ(*m.fold_method, FoldMethod::Perforate);
}

TEST(Profile, AnUnknownKeyNamesTheFileAndTheKey) {
  const auto f = edited("typo.toml", "units_per_mm = 20", "units_per_mm = 20\nunits_pr_mm = 20");
  EXPECT_EQ(load_error(f), f.string() + ": units_pr_mm: unknown key");
}

TEST(Profile, AnUnknownKeyInATableNamesItsPath) {
  const auto f = edited("table.toml", "[speed]\n", "[speed]\nmaxx = 3\n");
  EXPECT_EQ(load_error(f), f.string() + ": speed.maxx: unknown key");
}

TEST(Profile, AWrongTypeSaysWhatWasExpected) {
  const auto f = edited("type.toml", "units_per_mm = 20", "units_per_mm = \"20\"");
  EXPECT_EQ(load_error(f), f.string() + ": units_per_mm: expected a number");
}

TEST(Profile, AMissingKeyIsAnError) {
  const auto f = edited("missing.toml", "protocol = \"gpgl\"\n", "");
  EXPECT_EQ(load_error(f), f.string() + ": protocol: missing");
}

TEST(Profile, AnOutOfRangeValueSaysTheRange) {
  const auto f = edited("range.toml", "holder = 2\n", "holder = 3\n");
  EXPECT_NE(load_error(f).find("tools[2].holder: must be between 1 and 2, got 3"), std::string::npos)
      << load_error(f);
}

TEST(Profile, AnUnknownChoiceListsTheValidOnes) {
  const auto f = edited("choice.toml", "protocol = \"gpgl\"", "protocol = \"dmpl\"");
  EXPECT_NE(load_error(f).find("protocol: unknown value \"dmpl\" (expected one of gpgl, hpgl)"),
            std::string::npos);
}

TEST(Profile, ATomlSyntaxErrorGivesTheLine) {
  const auto f = edited("syntax.toml", "[holders]", "[holders");
  EXPECT_NE(load_error(f).find(f.string() + ": line "), std::string::npos) << load_error(f);
}

TEST(Profile, AMediaFileIsNotADevice) {
  const std::string e = load_error(test::source_dir() / "profiles" / "media" / "copy-80.toml");
  EXPECT_NE(e.find("kind: this is a media profile, not a device profile"), std::string::npos) << e;
}

TEST(Profile, AScorerPreferenceNeedsAScoringTool) {
  const auto f = edited("noscorer.toml", "kind = \"scorer\"", "kind = \"pen\"");
  EXPECT_NE(load_error(f).find("fold_method: \"scorer\" but no tool of kind \"scorer\""), std::string::npos);
}

TEST(Profile, AUserProfileReplacesTheBuiltInOneWithTheSameId) {
  const auto dir = test::temp_dir("user-profile");
  {
    std::ifstream in(kDevices / "cameo4.toml");
    std::string text((std::istreambuf_iterator<char>(in)), {});
    text.replace(text.find("product = 0x1137"), 16, "product = 0x1139");
    std::ofstream(dir / "cameo4.toml") << text;
  }
  const ProfileSet set = load_profiles(foldkit::test::profiles_dir(), {dir / "cameo4.toml"});
  EXPECT_EQ(set.device("cameo4").usb_product, 0x1139);
  EXPECT_EQ(set.devices.size(), 10u);
}

TEST(Profile, UnknownIdsListTheKnownOnes) {
  const ProfileSet set = load_profiles(foldkit::test::profiles_dir());
  try {
    (void)set.device("cameo9");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("known: cameo3, cameo4"), std::string::npos) << e.what();
  }
  EXPECT_THROW((void)set.medium("vellum"), InputError);
}

TEST(Profile, PageToDeviceRoundTripsForEveryAxisSetup) {
  DeviceProfile d;
  d.units_per_mm = 40;
  const Vec2 area{300, 400}, p{12.5, 77.25};
  for (int bits = 0; bits < 8; ++bits) {
    d.axes = {(bits & 1) != 0, (bits & 2) != 0, (bits & 4) != 0};
    const Vec2 q = device_to_page(d, page_to_device(d, p, area), area);
    EXPECT_NEAR(q.x, p.x, 1e-9);
    EXPECT_NEAR(q.y, p.y, 1e-9);
  }
}

TEST(Profile, GpglPutsTheFeedAxisFirstAndHpglYUpFlipsIt) {
  DeviceProfile gpgl;
  gpgl.units_per_mm = 20;
  gpgl.axes = {true, false, false};
  EXPECT_EQ(page_to_device(gpgl, {10, 30}, {300, 300}), (Vec2{600, 200}));
  DeviceProfile hpgl;
  hpgl.units_per_mm = 40;
  hpgl.axes = {false, false, true};
  EXPECT_EQ(page_to_device(hpgl, {10, 30}, {300, 300}), (Vec2{400, 10800}));
}

TEST(Profile, MediaSettingsBecomeClampedDeviceSteps) {
  DeviceProfile d;
  d.speed_steps = {1, 10};
  d.mm_s_per_speed_step = 10;
  d.force_steps = {1, 33};
  d.gf_per_force_step = 7;
  EXPECT_EQ(speed_step(d, 50), 5);
  EXPECT_EQ(speed_step(d, 500), 10);
  EXPECT_EQ(speed_step(d, 1), 1);
  EXPECT_EQ(force_step(d, 70), 10);
  EXPECT_EQ(force_step(d, 1000), 33);
}

TEST(Profile, RegistrationMarkLengthsAreBoundedLikeTheirOptions) {
  // 1e300 used to reach the device as TB51,-9223372036854775808, and --dry-run passed it (issue 10).
  const fs::path hostile = test::source_dir() / "tests" / "data" / "hostile";
  const fs::path arm = hostile / "device_regmark_arm_1e300.toml";
  const fs::path stroke = hostile / "device_regmark_stroke_1e300.toml";
  ASSERT_TRUE(fs::is_regular_file(arm) && fs::is_regular_file(stroke));
  EXPECT_EQ(load_error(arm),
            arm.string() + ": regmarks.arm_length_mm: must be between 1 and 100, got 1e+300");
  EXPECT_EQ(load_error(stroke),
            stroke.string() + ": regmarks.stroke_mm: must be between 0.05 and 5, got 1e+300");
  const auto square = edited("square.toml", "search = \"TB123\"\n", "search = \"TB123\"\nsquare_mm = 0.2\n");
  EXPECT_NE(load_error(square).find("regmarks.square_mm: must be between 1 and 50, got 0.2"),
            std::string::npos)
      << load_error(square);
  const auto inset = edited("inset.toml", "search = \"TB123\"\n", "search = \"TB123\"\ninset_mm = 500\n");
  EXPECT_NE(load_error(inset).find("regmarks.inset_mm: must be between 0 and 100, got 500"),
            std::string::npos)
      << load_error(inset);
}

}  // namespace
}  // namespace foldkit::devices
