#include "cairo_image.hpp"

#include <algorithm>

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

}  // namespace

SurfacePtr decode_png(const std::string& bytes) {
  ReadState state{&bytes};
  return SurfacePtr(cairo_image_surface_create_from_png_stream(read_from_string, &state));
}

bool encode_png(cairo_surface_t* surface, std::ostream& out) {
  cairo_surface_flush(surface);
  return cairo_surface_write_to_png_stream(surface, write_to_stream, &out) == CAIRO_STATUS_SUCCESS;
}

}  // namespace foldkit::devices::detail
