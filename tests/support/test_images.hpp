#pragma once
// Rendered pages read back for tests that check what a user would see on them.
#include <array>
#include <filesystem>
#include <vector>

namespace foldkit::test {

/// An 8-bit RGB picture; empty (w == 0) when the file could not be read.
struct RgbImage {
  int w = 0, h = 0;
  std::vector<unsigned char> rgb;  ///< row-major, three bytes per pixel

  const unsigned char* px(int x, int y) const { return &rgb[(static_cast<std::size_t>(y) * w + x) * 3]; }
  /// Components in [0, 1]; coordinates clamped to the picture.
  std::array<double, 3> at(int x, int y) const;
};

/// Reads a PNG (or any format stb_image knows) as RGB.
RgbImage read_image(const std::filesystem::path& path);

}  // namespace foldkit::test
