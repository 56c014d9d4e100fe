// The USB fault table: libusb codes to faults, and the one-line messages users act on.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "foldkit/devices/usb_errors.hpp"
#include "foldkit/devices/usb_ids.hpp"

using namespace foldkit::devices;

namespace {
// libusb's error codes are part of its stable ABI (libusb.h, enum libusb_error).
constexpr int kSuccess = 0, kIo = -1, kAccess = -3, kNoDevice = -4, kNotFound = -5, kBusy = -6, kTimeout = -7,
              kOverflow = -8, kPipe = -9, kInterrupted = -10, kNotSupported = -12, kOther = -99;

UsbFaultContext cameo3() {
  UsbFaultContext c;
  c.device = "Silhouette Cameo 3 (usb 003:017, 0b4d:112f)";
  c.vendor = 0x0b4d;
  c.product = 0x112f;
  return c;
}
}  // namespace

TEST(UsbFaults, LibusbCodesMapToTheFaultsUsersAreToldAbout) {
  EXPECT_EQ(usb_fault_from_libusb(kSuccess), UsbFault::None);
  EXPECT_EQ(usb_fault_from_libusb(42), UsbFault::None);  // byte counts are successes
  EXPECT_EQ(usb_fault_from_libusb(kAccess), UsbFault::PermissionDenied);
  EXPECT_EQ(usb_fault_from_libusb(kBusy), UsbFault::Busy);
  EXPECT_EQ(usb_fault_from_libusb(kNoDevice), UsbFault::Unplugged);
  EXPECT_EQ(usb_fault_from_libusb(kNotFound), UsbFault::NotFound);
  EXPECT_EQ(usb_fault_from_libusb(kTimeout), UsbFault::Timeout);
  EXPECT_EQ(usb_fault_from_libusb(kPipe), UsbFault::Stall);
  EXPECT_EQ(usb_fault_from_libusb(kOverflow), UsbFault::Overflow);
  EXPECT_EQ(usb_fault_from_libusb(kInterrupted), UsbFault::Interrupted);
  EXPECT_EQ(usb_fault_from_libusb(kNotSupported), UsbFault::Unsupported);
  EXPECT_EQ(usb_fault_from_libusb(kIo), UsbFault::Io);
  EXPECT_EQ(usb_fault_from_libusb(kOther), UsbFault::Io);
  EXPECT_EQ(usb_fault_from_libusb(-1234), UsbFault::Io);
}

TEST(UsbFaults, PermissionDeniedNamesTheShippedRulesFileAndGivesTheRuleLine) {
  auto c = cameo3();
  c.operation = "opening";
  const std::string m = usb_fault_message(UsbFault::PermissionDenied, c);
  EXPECT_NE(m.find("permission denied"), std::string::npos) << m;
  EXPECT_NE(m.find("profiles/udev/60-foldkit-cutters.rules"), std::string::npos) << m;
  EXPECT_NE(m.find(udev_rule_line(0x0b4d, 0x112f)), std::string::npos) << m;
  EXPECT_NE(m.find("udevadm"), std::string::npos) << m;
}

TEST(UsbFaults, TheUdevRuleLineIsTheFormTheShippedRulesFileUsesForEveryBuiltinModel) {
  std::ifstream in(std::string(FOLDKIT_SOURCE_DIR) + "/profiles/udev/" + kUdevRulesFile);
  ASSERT_TRUE(in);
  std::stringstream ss;
  ss << in.rdbuf();
  for (const auto& id : builtin_usb_ids()) {
    std::string line = udev_rule_line(id.vendor, id.product);
    const std::string prefix = "SUBSYSTEM==\"usb\", ";
    ASSERT_EQ(line.rfind(prefix, 0), 0u) << line;
    // The shipped file checks SUBSYSTEM once at the top; each model line is the rest.
    EXPECT_NE(ss.str().find(line.substr(prefix.size())), std::string::npos) << id.model;
  }
}

TEST(UsbFaults, BusyMentionsOtherProgramsAndTheKernelDriver) {
  auto c = cameo3();
  c.operation = "claiming interface 0";
  const std::string m = usb_fault_message(UsbFault::Busy, c);
  EXPECT_NE(m.find("busy"), std::string::npos) << m;
  EXPECT_NE(m.find("kernel printer driver"), std::string::npos) << m;
  EXPECT_NE(m.find("Silhouette Cameo 3"), std::string::npos) << m;
}

TEST(UsbFaults, UnplugMidJobSaysHowMuchWasSent) {
  auto c = cameo3();
  c.operation = "writing";
  c.bytes_sent = 1200;
  c.bytes_total = 5000;
  const std::string m = usb_fault_message(UsbFault::Unplugged, c);
  EXPECT_NE(m.find("unplugged"), std::string::npos) << m;
  EXPECT_NE(m.find("after 1200 of 5000 bytes"), std::string::npos) << m;
}

TEST(UsbFaults, TimeoutSaysHowLongItWaited) {
  auto c = cameo3();
  c.waited = std::chrono::milliseconds(120000);
  EXPECT_NE(usb_fault_message(UsbFault::Timeout, c).find("120 s"), std::string::npos);
  c.waited = std::chrono::milliseconds(2500);
  EXPECT_NE(usb_fault_message(UsbFault::Timeout, c).find("2.5 s"), std::string::npos);
}

TEST(UsbFaults, NoMediaTellsTheUserToLoadTheMat) {
  const std::string m = usb_fault_message(UsbFault::NoMedia, cameo3());
  EXPECT_NE(m.find("no media"), std::string::npos) << m;
  EXPECT_NE(m.find("Load"), std::string::npos) << m;
}

TEST(UsbFaults, EveryMessageIsOneLineAndNamesTheDevice) {
  for (int f = static_cast<int>(UsbFault::None); f <= static_cast<int>(UsbFault::Io); ++f) {
    auto c = cameo3();
    c.operation = "writing";
    c.bytes_total = 10;
    const std::string m = usb_fault_message(static_cast<UsbFault>(f), c);
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    EXPECT_NE(m.find("Silhouette Cameo 3"), std::string::npos) << m;
  }
}
