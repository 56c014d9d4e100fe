// Pure parts of the USB layer: id table, GP-GL status replies, slicing at command boundaries.
#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "device_fixtures.hpp"
#include "foldkit/devices/usb_ids.hpp"

using namespace foldkit::devices;

namespace {
using foldkit::test::bytes_of;
}  // namespace

TEST(UsbIds, BuiltinTableHasNoDuplicateIdsAndNamesTheCameo3) {
  std::set<std::pair<int, int>> seen;
  bool cameo3 = false;
  for (const auto& id : builtin_usb_ids()) {
    EXPECT_TRUE(seen.insert({id.vendor, id.product}).second) << id.model;
    EXPECT_TRUE(is_cutter_vendor(id.vendor)) << id.model;
    if (id.vendor == 0x0b4d && id.product == 0x112f) cameo3 = id.model == "Silhouette Cameo 3";
  }
  EXPECT_TRUE(cameo3);
  EXPECT_FALSE(is_cutter_vendor(0x046d));
}

TEST(UsbIds, EveryBuiltinIdIsCoveredByTheShippedUdevRules) {
  std::ifstream in(std::string(FOLDKIT_SOURCE_DIR) + "/profiles/udev/60-foldkit-cutters.rules");
  ASSERT_TRUE(in) << "rules file missing";
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string rules = ss.str();
  for (const auto& id : builtin_usb_ids()) {
    char line[96];
    std::snprintf(line, sizeof line, "ATTR{idVendor}==\"%04x\", ATTR{idProduct}==\"%04x\"", id.vendor,
                  id.product);
    EXPECT_NE(rules.find(line), std::string::npos) << id.model;
  }
}

TEST(GpglStatus, DigitsFollowedByEtxMapToDeviceStates) {
  EXPECT_EQ(parse_gpgl_status(bytes_of("0\x03")), DeviceState::Ready);
  EXPECT_EQ(parse_gpgl_status(bytes_of("1\x03")), DeviceState::Busy);
  EXPECT_EQ(parse_gpgl_status(bytes_of("2\x03")), DeviceState::NoMedia);
  EXPECT_EQ(parse_gpgl_status(bytes_of("3\x03")), DeviceState::Paused);
  EXPECT_EQ(parse_gpgl_status(bytes_of("    0\x03")), DeviceState::Ready);
}

TEST(GpglStatus, TruncatedOrUnknownRepliesAreUnknown) {
  EXPECT_EQ(parse_gpgl_status(bytes_of("")), DeviceState::Unknown);
  EXPECT_EQ(parse_gpgl_status(bytes_of("0")), DeviceState::Unknown);
  EXPECT_EQ(parse_gpgl_status(bytes_of("9\x03")), DeviceState::Unknown);
  EXPECT_EQ(parse_gpgl_status(bytes_of("01\x03")), DeviceState::Unknown);
}

TEST(SliceAtEtx, SlicesEndOnEtxAndConcatenateToTheInput) {
  const auto stream = bytes_of(
      "M10,20\x03"
      "D30,40\x03"
      "D50,60\x03"
      "M0,0\x03");
  const auto slices = slice_at_etx(stream, 16);
  std::vector<std::byte> joined;
  for (const auto& s : slices) {
    EXPECT_LE(s.size(), 16u);
    EXPECT_EQ(s.back(), std::byte{0x03});
    joined.insert(joined.end(), s.begin(), s.end());
  }
  EXPECT_EQ(joined, stream);
  EXPECT_EQ(slices.size(),
            2u);  // 14 bytes then 12: the second pair of commands does not fit the first window
}

TEST(SliceAtEtx, ACommandLongerThanTheWindowIsSplitAtTheWindow) {
  const auto stream = bytes_of("D1,2,3,4,5,6,7,8\x03");
  const auto slices = slice_at_etx(stream, 8);
  ASSERT_EQ(slices.size(), 3u);
  EXPECT_EQ(slices[0].size(), 8u);
  EXPECT_EQ(slices[2].back(), std::byte{0x03});
}
