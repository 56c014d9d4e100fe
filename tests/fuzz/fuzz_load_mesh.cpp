// libFuzzer target: mesh loading for one format. The input bytes are written to a file with the
// extension given at compile time (FOLDKIT_FUZZ_EXT), because load_mesh dispatches on the extension.
// Any foldkit::Error is an accepted outcome; a crash, sanitizer report, hang or other exception is a bug.
#include <cstdint>
#include <filesystem>

#include "foldkit/error.hpp"
#include "foldkit/unfold/mesh_io.hpp"
#include "scratch_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const foldkit::fuzz::ScratchFile scratch("foldkit-fuzz", FOLDKIT_FUZZ_EXT);
  const std::filesystem::path& path = scratch.write(data, size);
  try {
    foldkit::unfold::load_mesh(path);
  } catch (const foldkit::Error&) {
  }
  return 0;
}
