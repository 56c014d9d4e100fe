// `foldkit devices`, and libusb discovery and a session against a real Cameo 3's recorded descriptors
// and URBs replayed by Debian's umockdev (tests/data/umockdev/SOURCE.md).
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cmd_devices.hpp"
#include "device_fixtures.hpp"
#include "foldkit/devices/usb_transport.hpp"
#include "foldkit/error.hpp"
#include "in_process.hpp"
#include "test_paths.hpp"

namespace fs = std::filesystem;
using namespace foldkit::devices;

namespace {

struct Outcome {
  int exit_code = -1;
  std::string out, err;
};

std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s)
    q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

using foldkit::test::slurp;

Outcome run(const std::vector<std::string>& argv, const std::string& env = "") {
  const fs::path dir = foldkit::test::temp_dir("cli_devices");
  // Built with append: GCC 12 warns falsely (-Wrestrict) on `" " + std::string` chains.
  std::string cmd = env;
  for (const auto& a : argv)
    cmd.append(" ").append(quote(a));
  cmd.append(" >").append(quote((dir / "out").string()));
  cmd.append(" 2>").append(quote((dir / "err").string())).append(" </dev/null");
  const int status = std::system(cmd.c_str());
  Outcome r;
  if (WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
  r.out = slurp(dir / "out");
  r.err = slurp(dir / "err");
  fs::remove_all(dir);
  return r;
}

fs::path recording() {
  return foldkit::test::source_dir() / "tests/data/umockdev";
}

bool have_umockdev() {
  return std::system("command -v umockdev-run >/dev/null 2>&1") == 0;
}

// The recorded device node, as named in the .umockdev file; the ioctl transcript is bound to it.
std::vector<std::string> umockdev_prefix(bool with_ioctl) {
  // umockdev preloads its library ahead of everything: under the asan preset, ASan must be told that
  // this link order is intended, and umockdev's own allocations are not ours to leak-check.
  std::vector<std::string> argv = {"env",
                                   "ASAN_OPTIONS=abort_on_error=1:detect_leaks=0:verify_asan_link_order=0",
                                   "umockdev-run", "-d", (recording() / "cameo3.umockdev").string()};
  if (with_ioctl) {
    argv.push_back("-i");
    argv.push_back("/dev/bus/usb/003/017=" + (recording() / "cameo3.ioctl").string());
  }
  argv.push_back("--");
  return argv;
}

std::vector<std::string> concat(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

using foldkit::test::bytes_of;

std::string hex4(std::uint16_t v) {
  char text[8];
  std::snprintf(text, sizeof text, "%04x", v);
  return text;
}

// Set in the child process that runs the session tests inside umockdev-run.
bool inside_umockdev() {
  return std::getenv("FOLDKIT_UMOCKDEV_CHILD") != nullptr;
}

// `foldkit devices --json [--usb-id ID]...` run in this process.
nlohmann::json devices_json(const std::vector<std::string>& usb_ids) {
  foldkit::cli::DevicesArgs args;
  args.json = true;
  args.usb_ids = usb_ids;
  return nlohmann::json::parse(foldkit::test::stdout_of([&] { foldkit::cli::run_devices(args); }));
}

}  // namespace

TEST(CliDevices, ListsTheKnownModelsAndExitsZero) {
  const Outcome r = run({foldkit::test::foldkit_binary().string(), "devices"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("Device profiles (--device):"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Known USB cutter models"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("0b4d:112f  Silhouette Cameo 3"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Cutters on USB:"), std::string::npos) << r.out;
}

TEST(CliDevices, JsonListsEveryBuiltinModelWithHexIds) {
  const auto j = devices_json({});
  for (const auto& id : builtin_usb_ids()) {
    bool listed = false;
    for (const auto& m : j["known_models"])
      listed |= m["vendor"] == hex4(id.vendor) && m["product"] == hex4(id.product);
    EXPECT_TRUE(listed) << id.model;
  }
  EXPECT_TRUE(j["usb_devices"].is_array());
  bool cameo4 = false;
  for (const auto& m : j["known_models"])
    cameo4 |= m["vendor"] == "0b4d" && m["product"] == "1137" && m["model"] == "Silhouette Cameo 4";
  EXPECT_TRUE(cameo4) << j.dump();
}

TEST(CliDevices, AUsbIdFromTheCommandLineJoinsTheKnownModels) {
  const auto j = devices_json({"0b4d:11ff=Cameo 6 (prototype)"});
  bool listed = false;
  for (const auto& m : j["known_models"])
    listed |= m["vendor"] == "0b4d" && m["product"] == "11ff" && m["model"] == "Cameo 6 (prototype)";
  EXPECT_TRUE(listed) << j.dump();
}

TEST(CliDevices, ListsTheDeviceProfilesWithTheirUsbIds) {
  const auto j = devices_json({});
  bool cameo3 = false;
  for (const auto& p : j["profiles"])
    cameo3 |=
        p["id"] == "cameo3" && p["vendor"] == "0b4d" && p["product"] == "112f" && p["protocol"] == "gpgl";
  EXPECT_TRUE(cameo3) << j.dump();
}

TEST(CliDevices, ABadUserProfileIsAnInputErrorNamingTheFile) {
  const fs::path dir = foldkit::test::temp_dir("cli_devices_profile");
  std::ofstream(dir / "mine.toml") << "kind = \"device\"\nid = \"mine\"\nbogus_key = 1\n";
  const Outcome r =
      run({foldkit::test::foldkit_binary().string(), "devices", "--profile", (dir / "mine.toml").string()});
  EXPECT_EQ(r.exit_code, 3) << r.out << r.err;
  EXPECT_NE(r.err.find("mine.toml"), std::string::npos) << r.err;
  fs::remove_all(dir);
}

TEST(CliDevices, AMalformedUsbIdIsAUsageError) {
  const Outcome r = run({foldkit::test::foldkit_binary().string(), "devices", "--usb-id", "cameo"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--usb-id cameo"), std::string::npos) << r.err;
}

TEST(CliDevicesUmockdev, TheRecordedCameo3IsListedWithBusAndAddress) {
  if (!have_umockdev()) GTEST_SKIP() << "umockdev-run not installed (Debian package umockdev)";
  const Outcome r =
      run(concat(umockdev_prefix(false), {foldkit::test::foldkit_binary().string(), "devices"}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("0b4d:112f  Silhouette Cameo 3  bus 003 address 017  --device cameo3"),
            std::string::npos)
      << r.out;
  // The recording's hubs (vendor 214b) and root hub are not cutters.
  EXPECT_EQ(r.out.find("214b"), std::string::npos) << r.out;
}

TEST(CliDevicesUmockdev, JsonGivesTheCameo3AsAKnownAccessibleModel) {
  if (!have_umockdev()) GTEST_SKIP() << "umockdev-run not installed (Debian package umockdev)";
  const Outcome r =
      run(concat(umockdev_prefix(false), {foldkit::test::foldkit_binary().string(), "devices", "--json"}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["usb_devices"].size(), 1u) << r.out;
  const auto& d = j["usb_devices"][0];
  EXPECT_EQ(d["vendor"], "0b4d");
  EXPECT_EQ(d["product"], "112f");
  EXPECT_EQ(d["model"], "Silhouette Cameo 3");
  EXPECT_EQ(d["known_model"], true);
  EXPECT_EQ(d["bus"], 3);
  EXPECT_EQ(d["address"], 17);
  EXPECT_EQ(d["profile"], "cameo3");
  EXPECT_TRUE(j["usb_error"].is_null());
}

// The session tests run in a child process under umockdev-run (which preloads its libusb shim),
// started by the test below; on their own they skip.
TEST(UmockdevChild, DiscoveryWithoutTheModelInTheTableCallsItAnUnknownModel) {
  if (!inside_umockdev()) GTEST_SKIP() << "runs only inside umockdev-run";
  const std::vector<UsbId> none;
  const auto found = find_usb_cutters(none);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_FALSE(found[0].known_model);
  EXPECT_EQ(found[0].id.model, "unknown model");
  EXPECT_EQ(found[0].id.product, 0x112f);
}

TEST(UmockdevChild, TheRecordedCameo3AnswersStatusAndModelQueriesThroughUsbTransport) {
  if (!inside_umockdev()) GTEST_SKIP() << "runs only inside umockdev-run";
  UsbOptions o;
  o.status_timeout = std::chrono::milliseconds(2000);
  auto usb = open_usb_cutter({{0x0b4d, 0x112f, "Silhouette Cameo 3"}, 3, 17}, o);
  EXPECT_EQ(usb->describe(), "Silhouette Cameo 3 (usb 003:017, 0b4d:112f)");
  EXPECT_EQ(usb->out_packet_bytes(), 64u);
  EXPECT_EQ(usb->in_packet_bytes(), 64u);
  EXPECT_EQ(usb->status(), DeviceState::Ready);
  const auto fg = usb->request(bytes_of("FG\x03"), std::chrono::milliseconds(2000));
  ASSERT_TRUE(fg);
  const std::string model(reinterpret_cast<const char*>(fg->data()), fg->size());
  EXPECT_EQ(model, "CAMEO 3 V1.60    \x03");
  // The rest of the recorded handshake: initialise (ESC 04, paced by a status poll), then the
  // registration-mark offset query TB71 answered in 5-character fields.
  usb->write(bytes_of("\x1b\x04"));
  EXPECT_EQ(usb->bytes_sent(), 2u);
  const auto tb71 = usb->request(bytes_of("TB71\x03"), std::chrono::milliseconds(2000));
  ASSERT_TRUE(tb71);
  EXPECT_EQ(std::string(reinterpret_cast<const char*>(tb71->data()), tb71->size()), "    0,    0\x03");
  usb->close();
  usb->close();  // closing twice is harmless
}

TEST(UmockdevChild, AModelThatIsNotConnectedIsNotFound) {
  if (!inside_umockdev()) GTEST_SKIP() << "runs only inside umockdev-run";
  try {
    open_usb_cutter({{0x0b4d, 0x1137, "Silhouette Cameo 4"}, {}, {}});
    FAIL() << "opened a device that is not there";
  } catch (const foldkit::DeviceError& e) {
    EXPECT_NE(std::string(e.what()).find("no cutter found for Silhouette Cameo 4 (0b4d:1137)"),
              std::string::npos)
        << e.what();
  }
}

TEST(CliDevicesUmockdev, UsbTransportSessionAgainstTheRecordingPasses) {
  if (!have_umockdev()) GTEST_SKIP() << "umockdev-run not installed (Debian package umockdev)";
  if (inside_umockdev()) GTEST_SKIP() << "this is the parent of the umockdev session";
  const fs::path self = fs::read_symlink("/proc/self/exe");
  const Outcome r = run(concat(umockdev_prefix(true), {self.string(), "--gtest_filter=UmockdevChild.*"}),
                        "FOLDKIT_UMOCKDEV_CHILD=1");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("[  PASSED  ] 3 tests"), std::string::npos) << r.out;
}
