#pragma once
// Cairo image helpers shared by the modules that post-process a rendered sheet (bundle parts, the
// print-and-cut preview): owning handles and PNG bytes in and out of memory.
#include <cairo.h>

#include <memory>
#include <ostream>
#include <string>

namespace foldkit::devices::detail {

struct SurfaceDeleter {
  void operator()(cairo_surface_t* s) const { cairo_surface_destroy(s); }
};
struct ContextDeleter {
  void operator()(cairo_t* c) const { cairo_destroy(c); }
};
using SurfacePtr = std::unique_ptr<cairo_surface_t, SurfaceDeleter>;
using ContextPtr = std::unique_ptr<cairo_t, ContextDeleter>;

/// An image surface decoded from PNG bytes; check cairo_surface_status for failure.
SurfacePtr decode_png(const std::string& bytes);

/// The PNG bytes of `surface`; false when Cairo fails.
bool encode_png(cairo_surface_t* surface, std::ostream& out);

/// `png` with a pHYs chunk saying `dpi`, so that programs which honour it (cutting software, image
/// viewers, print dialogs) open the image at its physical size; Cairo writes none. `png` unchanged when
/// it is not a PNG starting with IHDR.
std::string with_resolution(const std::string& png, double dpi);

}  // namespace foldkit::devices::detail
