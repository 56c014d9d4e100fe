// The simulated device's switches on the command line (cli/sim_faults, cut --preview): an unknown or
// malformed --sim-fault is a usage error listing the valid ones, before any work; --preview needs the
// simulated device.
#include <gtest/gtest.h>

#include <string>

#include "test_paths.hpp"

namespace fs = std::filesystem;
using foldkit::test::run_foldkit;

namespace {

const char* const kValidFaults = "not-ready, no-media, marks-not-found, disconnect=BYTES, stall=BYTES";

std::string mesh() {
  return foldkit::test::example_mesh("spot_128.obj").string();
}

}  // namespace

TEST(CliSimFaults, AnUnknownOrMalformedFaultIsAUsageErrorListingTheValidOnes) {
  for (const std::string fault : {"bogus", "stall", "stall=", "stall=-1", "stall=12x",
                                  "disconnect=99999999999999999999999", "not-ready=3", "no-media=0"}) {
    const auto cut = run_foldkit({"cut", mesh(), "--dry-run", "--sim-fault", fault, "--json"});
    EXPECT_EQ(cut.exit_code, 2) << fault << ": " << cut.err;
    EXPECT_NE(cut.err.find("--sim-fault " + fault), std::string::npos) << cut.err;
    EXPECT_NE(cut.err.find(kValidFaults), std::string::npos) << cut.err;
    EXPECT_TRUE(cut.out.empty()) << cut.out;
    const auto sim = run_foldkit({"sim", "job.gpgl", "--device", "cameo4", "--sim-fault", fault});
    EXPECT_EQ(sim.exit_code, 2) << fault << ": " << sim.err;
    EXPECT_NE(sim.err.find(kValidFaults), std::string::npos) << sim.err;
  }
}

TEST(CliSimFaults, AValidFaultReachesTheSimulatedDevice) {
  const fs::path dir = foldkit::test::temp_dir("sim-fault");
  const auto run = run_foldkit(
      {"cut", mesh(), "--dry-run", "--sim-fault", "disconnect=200", "--preview", (dir / "p.png").string()});
  EXPECT_EQ(run.exit_code, 6) << run.err;
}

TEST(CliSimFaults, AFaultOrAPreviewWithoutTheSimulatedDeviceIsAUsageError) {
  const fs::path dir = foldkit::test::temp_dir("preview");
  const std::string job = (dir / "job.gpgl").string();
  const auto preview =
      run_foldkit({"cut", mesh(), "--device", "cameo4", "-o", job, "--preview", (dir / "p.png").string()});
  EXPECT_EQ(preview.exit_code, 2) << preview.err;
  EXPECT_NE(preview.err.find("--dry-run"), std::string::npos) << preview.err;
  const auto usb = run_foldkit({"cut", mesh(), "--device", "cameo4", "--preview", (dir / "p.png").string()});
  EXPECT_EQ(usb.exit_code, 2) << usb.err;
  const auto fault = run_foldkit({"cut", mesh(), "--device", "cameo4", "-o", job, "--sim-fault", "no-media"});
  EXPECT_EQ(fault.exit_code, 2) << fault.err;
  EXPECT_FALSE(fs::exists(job));
  EXPECT_FALSE(fs::exists(dir / "p.png"));
}
