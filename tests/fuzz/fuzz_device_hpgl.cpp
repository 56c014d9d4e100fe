// libFuzzer target: HP-GL streams executed by the simulated device (tokeniser, state, bounds checks).
#include "fuzz_device_sim.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // Read once per process: libFuzzer's entry point has no context to keep them in.
  static const auto profiles = foldkit::fuzz::profiles_of(foldkit::devices::Protocol::Hpgl);
  return foldkit::fuzz::run_simulated_device(profiles, data, size);
}
