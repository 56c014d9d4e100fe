// Every input a fuzzer ever found a problem with (tests/fuzz/regressions/<target>/) is replayed through
// the same code path as its target, in every test run and under the asan preset: a foldkit::Error is
// the expected outcome; a crash, sanitizer report or any other exception fails.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "foldkit/devices/profile.hpp"
#include "foldkit/error.hpp"
#include "foldkit/unfold/mesh_io.hpp"
#include "fuzz/fuzz_device_sim.hpp"
#include "test_paths.hpp"

namespace fs = std::filesystem;

namespace {

fs::path regressions() {
  return foldkit::test::source_dir() / "tests/fuzz/regressions";
}

std::vector<fs::path> inputs_of(const std::string& target) {
  std::vector<fs::path> out;
  if (!fs::is_directory(regressions() / target)) return out;
  for (const auto& e : fs::directory_iterator(regressions() / target))
    if (e.is_regular_file()) out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace

TEST(FuzzRegressions, EveryRegressionFolderNamesAFuzzTarget) {
  const std::vector<std::string> targets = {
      "fuzz_load_obj", "fuzz_load_off",    "fuzz_load_stl",    "fuzz_load_ply",       "fuzz_load_gltf",
      "fuzz_load_glb", "fuzz_device_gpgl", "fuzz_device_hpgl", "fuzz_device_profile", "fuzz_device_streams"};
  for (const auto& e : fs::directory_iterator(regressions())) {
    if (!e.is_directory()) continue;
    EXPECT_NE(std::find(targets.begin(), targets.end(), e.path().filename().string()), targets.end())
        << e.path() << " is replayed by no test";
    EXPECT_FALSE(inputs_of(e.path().filename().string()).empty()) << e.path() << " holds no input to replay";
  }
  // The folders with checked-in findings; losing one (or its files) must fail here, not skip silently.
  for (const std::string target :
       {"fuzz_load_obj", "fuzz_load_off", "fuzz_load_ply", "fuzz_device_gpgl", "fuzz_device_streams"})
    EXPECT_FALSE(inputs_of(target).empty()) << "tests/fuzz/regressions/" << target << " is missing or empty";
}

TEST(FuzzRegressions, MeshInputsEndInAnInputErrorOrLoad) {
  int replayed = 0;
  for (const std::string ext : {"obj", "off", "stl", "ply", "gltf", "glb"}) {
    for (const auto& input : inputs_of("fuzz_load_" + ext)) {
      const fs::path dir = foldkit::test::temp_dir("fuzz_regression");
      const fs::path copy = dir / ("input." + ext);  // load_mesh dispatches on the extension
      fs::copy_file(input, copy);
      try {
        foldkit::unfold::load_mesh(copy);
      } catch (const foldkit::Error&) {
      }
      fs::remove_all(dir);
      ++replayed;
    }
  }
  EXPECT_GT(replayed, 0) << "the OFF count-overflow input at least is checked in";
}

TEST(FuzzRegressions, DeviceStreamsEndInADeviceErrorOrRun) {
  // fuzz_device_streams builds its device in code; its inputs are replayed on both real protocols here.
  for (const auto& [target, protocol] :
       {std::pair{"fuzz_device_gpgl", foldkit::devices::Protocol::Gpgl},
        std::pair{"fuzz_device_hpgl", foldkit::devices::Protocol::Hpgl},
        std::pair{"fuzz_device_streams", foldkit::devices::Protocol::Gpgl},
        std::pair{"fuzz_device_streams", foldkit::devices::Protocol::Hpgl}}) {
    for (const auto& input : inputs_of(target)) {
      const std::string data = slurp(input);
      SCOPED_TRACE(input.string());
      foldkit::fuzz::run_simulated_device(protocol, reinterpret_cast<const std::uint8_t*>(data.data()),
                                          data.size());
    }
  }
}

TEST(FuzzRegressions, ProfileInputsEndInAnInputErrorOrLoad) {
  for (const auto& input : inputs_of("fuzz_device_profile")) {
    SCOPED_TRACE(input.string());
    try {
      foldkit::devices::load_device_profile(input);
    } catch (const foldkit::Error&) {
    }
    try {
      foldkit::devices::load_media_profile(input);
    } catch (const foldkit::Error&) {
    }
  }
}

TEST(FuzzRegressions, AnOffFaceLineWithAHugeCountAndNoIndicesIsRefusedNamingTheFace) {
  // OpenMesh read 3,689,023 indices from a failed stream for this line: 464 million triangles and
  // seconds of work before any limit could say no (found by fuzz_load_off in CI).
  const fs::path input = regressions() / "fuzz_load_off" / "face_count_without_indices.off";
  try {
    foldkit::unfold::load_mesh(input);
    FAIL() << "loaded";
  } catch (const foldkit::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("unparsable vertex list '3689023'"), std::string::npos) << e.what();
  }
}
