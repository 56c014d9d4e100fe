// libFuzzer target: device and media profile parsing (TOML through toml++, then foldkit's key checks).
// The loaders read files, so the input is written to one per process. Any foldkit::Error is an
// accepted outcome; a crash, sanitizer report, hang or other exception (toml++'s own included) is a bug.
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "foldkit/devices/profile.hpp"
#include "foldkit/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::filesystem::path path = std::filesystem::temp_directory_path() /
                                            ("foldkit-fuzz-profile-" + std::to_string(::getpid()) + ".toml");
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
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
