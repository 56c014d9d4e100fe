#include "cairo_image.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace foldkit::devices::detail {
namespace {

struct ReadState {
  const std::string* bytes;
  std::size_t at = 0;
};

cairo_status_t read_from_string(void* closure, unsigned char* data, unsigned int length) {
  auto* s = static_cast<ReadState*>(closure);
  if (s->at + length > s->bytes->size()) return CAIRO_STATUS_READ_ERROR;
  std::copy_n(s->bytes->data() + s->at, length, data);
  s->at += length;
  return CAIRO_STATUS_SUCCESS;
}

cairo_status_t write_to_stream(void* closure, const unsigned char* data, unsigned int length) {
  auto* out = static_cast<std::ostream*>(closure);
  out->write(reinterpret_cast<const char*>(data), length);
  return *out ? CAIRO_STATUS_SUCCESS : CAIRO_STATUS_WRITE_ERROR;
}

constexpr std::size_t kSignatureBytes = 8;
constexpr std::size_t kIhdrChunkBytes = 4 + 4 + 13 + 4;  // length, type, data, CRC
constexpr double kMmPerInch = 25.4;

// CRC-32 of PNG chunks (ISO 3309, polynomial 0xEDB88320), over type and data.
std::uint32_t crc32(const std::string& bytes) {
  static const std::array<std::uint32_t, 256> table = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t n = 0; n < 256; ++n) {
      std::uint32_t c = n;
      for (int k = 0; k < 8; ++k)
        c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[n] = c;
    }
    return t;
  }();
  std::uint32_t c = 0xFFFFFFFFu;
  for (unsigned char b : bytes)
    c = table[(c ^ b) & 0xFF] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

void append_be32(std::string& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8)
    out.push_back(static_cast<char>((v >> shift) & 0xFF));
}

}  // namespace

std::string with_resolution(const std::string& png, double dpi) {
  if (png.size() < kSignatureBytes + kIhdrChunkBytes || png.compare(12, 4, "IHDR") != 0) return png;
  const auto px_per_m = static_cast<std::uint32_t>(std::lround(dpi / kMmPerInch * 1000));
  std::string body = "pHYs";
  append_be32(body, px_per_m);
  append_be32(body, px_per_m);
  body.push_back(1);  // unit: metre
  std::string chunk;
  append_be32(chunk, 9);
  chunk += body;
  append_be32(chunk, crc32(body));
  std::string out = png;
  out.insert(kSignatureBytes + kIhdrChunkBytes, chunk);
  return out;
}

SurfacePtr decode_png(const std::string& bytes) {
  ReadState state{&bytes};
  return SurfacePtr(cairo_image_surface_create_from_png_stream(read_from_string, &state));
}

bool encode_png(cairo_surface_t* surface, std::ostream& out) {
  cairo_surface_flush(surface);
  return cairo_surface_write_to_png_stream(surface, write_to_stream, &out) == CAIRO_STATUS_SUCCESS;
}

}  // namespace foldkit::devices::detail
