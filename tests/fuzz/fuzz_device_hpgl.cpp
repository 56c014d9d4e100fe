// libFuzzer target: HP-GL streams executed by the simulated device (tokeniser, state, bounds checks).
#include "fuzz_device_sim.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return foldkit::fuzz::run_simulated_device(foldkit::devices::Protocol::Hpgl, data, size);
}
