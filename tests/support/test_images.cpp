#include "test_images.hpp"

#include <algorithm>

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>

namespace foldkit::test {

std::array<double, 3> RgbImage::at(int x, int y) const {
  const unsigned char* p = px(std::clamp(x, 0, w - 1), std::clamp(y, 0, h - 1));
  return {p[0] / 255.0, p[1] / 255.0, p[2] / 255.0};
}

RgbImage read_image(const std::filesystem::path& path) {
  RgbImage img;
  int channels = 0;
  unsigned char* data = stbi_load(path.string().c_str(), &img.w, &img.h, &channels, 3);
  if (!data) return {};
  img.rgb.assign(data, data + static_cast<std::size_t>(img.w) * img.h * 3);
  stbi_image_free(data);
  return img;
}

}  // namespace foldkit::test
