#pragma once
// The file a fuzz target writes each input to (the loaders read files), one per process, removed when the
// process ends so that fuzz runs leave nothing in the temp directory.
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

namespace foldkit::fuzz {

class ScratchFile {
 public:
  /// `/tmp/<stem>-<pid><extension>` (the system temp directory).
  ScratchFile(const std::string& stem, const std::string& extension)
      : owner_(::getpid()),
        path_(std::filesystem::temp_directory_path() / (stem + "-" + std::to_string(owner_) + extension)) {}
  ScratchFile(const ScratchFile&) = delete;
  ScratchFile& operator=(const ScratchFile&) = delete;
  ~ScratchFile() {
    if (::getpid() != owner_) return;
    std::error_code ignored;
    std::filesystem::remove(path_, ignored);
  }

  /// Replaces the file's contents with `size` bytes from `data` and returns its path.
  const std::filesystem::path& write(const std::uint8_t* data, std::size_t size) const {
    std::ofstream out(path_, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    return path_;
  }

 private:
  pid_t owner_;
  std::filesystem::path path_;
};

}  // namespace foldkit::fuzz
