// libFuzzer target: mesh loading for one format. The input bytes are written to a file with the
// extension given at compile time (FOLDKIT_FUZZ_EXT), because load_mesh dispatches on the extension.
// Any foldkit::Error is an accepted outcome; a crash, sanitizer report, hang or other exception is a bug.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "foldkit/error.hpp"
#include "foldkit/unfold/mesh_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::filesystem::path path = std::filesystem::temp_directory_path() /
                                            ("foldkit-fuzz-" + std::to_string(::getpid()) + FOLDKIT_FUZZ_EXT);
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  try {
    foldkit::unfold::load_mesh(path);
  } catch (const foldkit::Error&) {
  }
  return 0;
}
