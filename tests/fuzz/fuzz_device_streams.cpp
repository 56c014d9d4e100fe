// libFuzzer target: arbitrary bytes into the GP-GL and HP-GL parsers and the simulated device (see
// fuzz_device_streams.hpp, which test_fuzz_regressions replays its findings through).
#include "fuzz_device_streams.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return foldkit::fuzz::run_device_streams(data, size);
}
