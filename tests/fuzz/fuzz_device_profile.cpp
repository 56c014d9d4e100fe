// libFuzzer target: device and media profile parsing (TOML through toml++, then foldkit's key checks).
// The loaders read files, so the input is written to one per process. Any foldkit::Error is an
// accepted outcome; a crash, sanitizer report, hang or other exception (toml++'s own included) is a bug.
#include <cstdint>
#include <filesystem>

#include "foldkit/devices/profile.hpp"
#include "foldkit/error.hpp"
#include "scratch_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const foldkit::fuzz::ScratchFile scratch("foldkit-fuzz-profile", ".toml");
  const std::filesystem::path& path = scratch.write(data, size);
  try {
    foldkit::devices::load_device_profile(path);
  } catch (const foldkit::Error&) {
  }
  try {
    foldkit::devices::load_media_profile(path);
  } catch (const foldkit::Error&) {
  }
  return 0;
}
