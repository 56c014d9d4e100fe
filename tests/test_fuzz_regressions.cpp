// Every input a fuzzer ever found a problem with (tests/fuzz/regressions/<target>/), and every input of
// its seed corpus (tests/fuzz/corpus/), is replayed through the same code path as its target, in every
// test run and under the asan preset: a foldkit::Error is the expected outcome; a crash, sanitizer report
// or any other exception fails, and so does a target with nothing to replay.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "foldkit/devices/profile.hpp"
#include "foldkit/error.hpp"
#include "foldkit/unfold/mesh_io.hpp"
#include "fuzz/fuzz_device_sim.hpp"
#include "fuzz/fuzz_device_streams.hpp"
#include "test_paths.hpp"

namespace fs = std::filesystem;

namespace {

fs::path regressions() {
  return foldkit::test::source_dir() / "tests/fuzz/regressions";
}

// The seed corpus tests/fuzz/run starts `target` from (the same mapping as the script's).
fs::path corpus_of(const std::string& target) {
  const fs::path corpus = foldkit::test::source_dir() / "tests/fuzz/corpus";
  const std::string load = "fuzz_load_";
  if (target.rfind(load, 0) == 0) return corpus / target.substr(load.size());
  return corpus / target.substr(std::string("fuzz_").size());
}

std::vector<fs::path> files_in(const fs::path& dir) {
  std::vector<fs::path> out;
  if (!fs::is_directory(dir)) return out;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_regular_file()) out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

// What a fuzz target was found failing on (regressions/<target>/), then its seed corpus.
std::vector<fs::path> inputs_of(const std::string& target) {
  std::vector<fs::path> out = files_in(regressions() / target);
  for (const fs::path& p : files_in(corpus_of(target)))
    out.push_back(p);
  return out;
}

// The targets with checked-in findings (regressions/<target>/): losing that folder or its files must fail
// the target's replay, not leave it replaying the seed corpus alone.
constexpr std::array<std::string_view, 7> kTargetsWithFindings = {
    "fuzz_load_obj", "fuzz_load_off",    "fuzz_load_ply",      "fuzz_load_gltf",
    "fuzz_load_glb", "fuzz_device_gpgl", "fuzz_device_streams"};

bool has_findings(std::string_view target) {
  return std::find(kTargetsWithFindings.begin(), kTargetsWithFindings.end(), target) !=
         kTargetsWithFindings.end();
}

// What to replay for `target`; records a failure when it has nothing to replay or has lost its findings.
std::vector<fs::path> replay_inputs(const std::string& target) {
  if (has_findings(target)) {
    EXPECT_FALSE(files_in(regressions() / target).empty())
        << "tests/fuzz/regressions/" << target << " is missing or empty";
  }
  std::vector<fs::path> inputs = inputs_of(target);
  EXPECT_FALSE(inputs.empty()) << target << ": nothing replayed";
  return inputs;
}

std::span<const std::uint8_t> bytes_of(const std::string& data) {
  return {reinterpret_cast<const std::uint8_t*>(data.data()), data.size()};
}

using foldkit::test::slurp;

}  // namespace

TEST(FuzzRegressions, EveryRegressionFolderNamesAFuzzTarget) {
  const std::vector<std::string> targets = {
      "fuzz_load_obj", "fuzz_load_off",    "fuzz_load_stl",    "fuzz_load_ply",       "fuzz_load_gltf",
      "fuzz_load_glb", "fuzz_device_gpgl", "fuzz_device_hpgl", "fuzz_device_profile", "fuzz_device_streams"};
  for (const auto& e : fs::directory_iterator(regressions())) {
    if (!e.is_directory()) continue;
    EXPECT_NE(std::find(targets.begin(), targets.end(), e.path().filename().string()), targets.end())
        << e.path() << " is replayed by no test";
    EXPECT_FALSE(files_in(e.path()).empty()) << e.path() << " holds no input to replay";
  }
  // Every folder with findings is one the replays insist on.
  for (const auto& e : fs::directory_iterator(regressions())) {
    if (e.is_directory() && !files_in(e.path()).empty()) {
      EXPECT_TRUE(has_findings(e.path().filename().string()))
          << e.path() << " holds findings its replay does not insist on";
    }
  }
  // Every target has inputs to replay: its findings or, at least, its seed corpus.
  for (const auto& target : targets)
    EXPECT_FALSE(inputs_of(target).empty()) << target << ": no regression or corpus input to replay";
}

TEST(FuzzRegressions, MeshInputsEndInAnInputErrorOrLoad) {
  for (const std::string ext : {"obj", "off", "stl", "ply", "gltf", "glb"}) {
    const auto inputs = replay_inputs("fuzz_load_" + ext);
    for (const auto& input : inputs) {
      SCOPED_TRACE(input.string());
      const fs::path dir = foldkit::test::temp_dir("fuzz_regression");
      const fs::path copy = dir / ("input." + ext);  // load_mesh dispatches on the extension
      fs::copy_file(input, copy);
      try {
        foldkit::unfold::load_mesh(copy);
      } catch (const foldkit::Error&) {
      }
      fs::remove_all(dir);
    }
  }
}

TEST(FuzzRegressions, TheProfilesOfAProtocolAllSpeakIt) {
  // Asked for GP-GL first, then HP-GL: a cache of the first answer would give GP-GL devices twice.
  for (const auto protocol : {foldkit::devices::Protocol::Gpgl, foldkit::devices::Protocol::Hpgl}) {
    const auto profiles = foldkit::fuzz::profiles_of(protocol);
    EXPECT_FALSE(profiles.empty());
    for (const auto& d : profiles)
      EXPECT_EQ(d.protocol, protocol) << d.id;
  }
}

TEST(FuzzRegressions, DeviceStreamsEndInADeviceErrorOrRun) {
  using foldkit::devices::Protocol;
  for (const auto& [target, protocol] :
       {std::pair{"fuzz_device_gpgl", Protocol::Gpgl}, std::pair{"fuzz_device_hpgl", Protocol::Hpgl}}) {
    const auto profiles = foldkit::fuzz::profiles_of(protocol);
    const auto inputs = replay_inputs(target);
    for (const auto& input : inputs) {
      SCOPED_TRACE(input.string());
      const std::string data = slurp(input);
      foldkit::fuzz::run_simulated_device(profiles, bytes_of(data).data(), data.size());
    }
  }
  // fuzz_device_streams' findings through its own body, and on the built-in devices of both protocols.
  const auto inputs = replay_inputs("fuzz_device_streams");
  for (const auto& input : inputs) {
    SCOPED_TRACE(input.string());
    const std::string data = slurp(input);
    foldkit::fuzz::run_device_streams(bytes_of(data).data(), data.size());
    for (const auto protocol : {Protocol::Gpgl, Protocol::Hpgl})
      foldkit::fuzz::run_simulated_device(foldkit::fuzz::profiles_of(protocol), bytes_of(data).data(),
                                          data.size());
  }
}

TEST(FuzzRegressions, ProfileInputsEndInAnInputErrorOrLoad) {
  const auto inputs = replay_inputs("fuzz_device_profile");
  for (const auto& input : inputs) {
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
