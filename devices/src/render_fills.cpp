// Fills through Cairo: a texture is a surface pattern whose matrix takes the sheet (mm) to the image's
// pixels, chosen from three corner correspondences, so each face shows exactly its own region of the
// texture, never mirrored (the map keeps the orientation the face's coordinates give it). A border of
// repeated edge texels (FillImage) carries colour into the bleed where coordinates reach the image's edge.
#include "render_fills.hpp"

#include <stb_image.h>
#include <stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>

namespace foldkit::devices::detail {
namespace {

constexpr double kMmPerInch = 25.4;
// Images larger than this a side are refused rather than decoded: 16k x 16k is 1 GB of texels.
constexpr int kMaxImageSide = 16384;
// Below this many texels per millimetre in some direction a face's map is degenerate (see matrix_for).
constexpr double kMinTexelsPerMm = 0.05;
// Flat colours and texture borders inside a piece stay crisp enough at this resolution (0.17 mm).
constexpr double kMinRasterDpi = 150;
// A sheet's fill image is at most this many pixels (an A0 sheet at 300 dpi is 140 million).
constexpr double kMaxRasterPixels = 40e6;
// JPEG quality of the fill image: no visible blocks on a 300 dpi print.
constexpr int kJpegQuality = 92;

struct Decoded {
  int w = 0, h = 0;
  std::vector<unsigned char> rgba;
};

bool decode(const SheetImage& image, Decoded& out) {
  std::vector<unsigned char> bytes = image.data;
  if (bytes.empty()) {
    std::ifstream in(image.file, std::ios::binary);
    if (!in) return false;
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  if (bytes.empty() || bytes.size() > (std::size_t{1} << 30)) return false;
  int w = 0, h = 0, channels = 0;
  const int size = static_cast<int>(bytes.size());
  if (!stbi_info_from_memory(bytes.data(), size, &w, &h, &channels) || w <= 0 || h <= 0 ||
      w > kMaxImageSide || h > kMaxImageSide)
    return false;
  unsigned char* pixels = stbi_load_from_memory(bytes.data(), size, &w, &h, &channels, 4);
  if (!pixels) return false;
  out.w = w;
  out.h = h;
  out.rgba.assign(pixels, pixels + static_cast<std::size_t>(w) * h * 4);
  stbi_image_free(pixels);
  return true;
}

cairo_surface_t* to_surface(const Decoded& d) {
  cairo_surface_t* s = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, d.w, d.h);
  if (cairo_surface_status(s) != CAIRO_STATUS_SUCCESS) {
    cairo_surface_destroy(s);
    return nullptr;
  }
  cairo_surface_flush(s);
  unsigned char* data = cairo_image_surface_get_data(s);
  const int stride = cairo_image_surface_get_stride(s);
  for (int y = 0; y < d.h; ++y) {
    auto* row = reinterpret_cast<std::uint32_t*>(data + static_cast<std::ptrdiff_t>(y) * stride);
    for (int x = 0; x < d.w; ++x) {
      const unsigned char* p = &d.rgba[(static_cast<std::size_t>(y) * d.w + x) * 4];
      const unsigned a = p[3];
      // Cairo wants premultiplied alpha in native-endian 32-bit words.
      const auto pre = [a](unsigned c) { return (c * a + 127) / 255; };
      row[x] = (a << 24) | (pre(p[0]) << 16) | (pre(p[1]) << 8) | pre(p[2]);
    }
  }
  cairo_surface_mark_dirty(s);
  return s;
}

// `src` scaled by `factor` (<= 1) inside a border of repeated edge pixels (see FillImage).
FillImage padded(cairo_surface_t* src, double factor) {
  // Spot's coordinates reach 0.06 past the image's edges; 1/8 of the side covers that with room.
  constexpr double kPadFraction = 0.125;
  const int w = std::max(1, static_cast<int>(std::lround(cairo_image_surface_get_width(src) * factor)));
  const int h = std::max(1, static_cast<int>(std::lround(cairo_image_surface_get_height(src) * factor)));
  const int pad = static_cast<int>(std::ceil(kPadFraction * std::max(w, h)));
  cairo_surface_t* dst = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, w + 2 * pad, h + 2 * pad);
  cairo_t* cr = cairo_create(dst);
  cairo_translate(cr, pad, pad);
  cairo_scale(cr, static_cast<double>(w) / cairo_image_surface_get_width(src),
              static_cast<double>(h) / cairo_image_surface_get_height(src));
  cairo_set_source_surface(cr, src, 0, 0);
  cairo_pattern_set_filter(cairo_get_source(cr), CAIRO_FILTER_GOOD);
  cairo_pattern_set_extend(cairo_get_source(cr), CAIRO_EXTEND_PAD);
  cairo_paint(cr);
  cairo_destroy(cr);
  return {dst, w, h, pad};
}

// The affine map taking the fill's corners (mm) to its texture coordinates in a w x h image (pixels).
bool matrix_for(const Fill& fill, double w, double h, double pad, cairo_matrix_t& m) {
  const Vec2 c0 = fill.corners_mm[0], e1 = fill.corners_mm[1] - c0, e2 = fill.corners_mm[2] - c0;
  auto px = [&](Vec2 uv) { return Vec2{pad + uv.x * w, pad + (1 - uv.y) * h}; };
  const Vec2 p0 = px(fill.uv[0]), f1 = px(fill.uv[1]) - p0, f2 = px(fill.uv[2]) - p0;
  const double det_e = cross(e1, e2), det_f = cross(f1, f2);
  // Faces under a hundredth of a square millimetre, or mapped to under a thousandth of a texel: no map.
  if (!(std::abs(det_e) > 1e-2) || !(std::abs(det_f) > 1e-3)) return false;
  // A = F E^-1, with E = [e1 e2] and F = [f1 f2] as columns.
  const double inv00 = e2.y / det_e, inv01 = -e2.x / det_e, inv10 = -e1.y / det_e, inv11 = e1.x / det_e;
  const double a00 = f1.x * inv00 + f2.x * inv10, a01 = f1.x * inv01 + f2.x * inv11;
  const double a10 = f1.y * inv00 + f2.y * inv10, a11 = f1.y * inv01 + f2.y * inv11;
  cairo_matrix_init(&m, a00, a10, a01, a11, p0.x - (a00 * c0.x + a01 * c0.y),
                    p0.y - (a10 * c0.x + a11 * c0.y));
  if (!(std::isfinite(m.xx) && std::isfinite(m.yx) && std::isfinite(m.xy) && std::isfinite(m.yy) &&
        std::isfinite(m.x0) && std::isfinite(m.y0)))
    return false;
  // A face whose coordinates (nearly) collapse to a line stretches a texel over the whole face: PDF
  // viewers then scale the full image to an enormous size. Such a face prints in one colour instead.
  const double s = a00 * a00 + a01 * a01 + a10 * a10 + a11 * a11, det = a00 * a11 - a01 * a10;
  const double smallest =
      std::sqrt(std::max(0.0, 0.5 * (s - std::sqrt(std::max(0.0, s * s - 4 * det * det)))));
  return smallest >= kMinTexelsPerMm;
}

// Texels per millimetre of paper along the most stretched direction of the map.
double texels_per_mm(const cairo_matrix_t& m) {
  const double a = m.xx, b = m.xy, c = m.yx, d = m.yy;
  const double s = a * a + b * b + c * c + d * d, det = a * d - b * c;
  return std::sqrt(0.5 * (s + std::sqrt(std::max(0.0, s * s - 4 * det * det))));
}

void trace(cairo_t* cr, const std::vector<Vec2>& outline) {
  cairo_new_path(cr);
  for (std::size_t i = 0; i < outline.size(); ++i)
    (i == 0 ? cairo_move_to : cairo_line_to)(cr, outline[i].x, outline[i].y);
  cairo_close_path(cr);
}

bool is_white(Colour c) {
  return c.r >= 1 && c.g >= 1 && c.b >= 1;
}

}  // namespace

FillImages::FillImages(std::span<const Sheet> sheets, double max_dpi) {
  std::map<std::pair<std::string, std::size_t>, int> distinct;
  std::vector<cairo_surface_t*> full;
  std::vector<double> density;
  for (const Sheet& sheet : sheets) {
    std::vector<int>& slots = slot_[&sheet];
    for (const SheetImage& image : sheet.images) {
      const auto key = std::make_pair(image.file, image.data.size());
      auto [it, inserted] = distinct.try_emplace(key, static_cast<int>(full.size()));
      if (inserted) {
        Decoded d;
        full.push_back(decode(image, d) ? to_surface(d) : nullptr);
        if (!full.back()) failed_.push_back(image.file);
        density.push_back(0);
      }
      slots.push_back(it->second);
    }
    for (const Fill& fill : sheet.fills) {
      if (fill.image < 0 || fill.image >= static_cast<int>(slots.size())) continue;
      cairo_surface_t* s = full[slots[fill.image]];
      cairo_matrix_t m;
      if (s && matrix_for(fill, cairo_image_surface_get_width(s), cairo_image_surface_get_height(s), 0, m))
        density[slots[fill.image]] = std::max(density[slots[fill.image]], texels_per_mm(m));
    }
  }
  // Finer than the printer prints is only bytes: each image is scaled down to the print resolution.
  const double wanted = max_dpi / kMmPerInch;
  for (std::size_t i = 0; i < full.size(); ++i) {
    if (!full[i]) {
      images_.push_back({});
      continue;
    }
    images_.push_back(padded(full[i], density[i] > wanted * 1.05 ? wanted / density[i] : 1.0));
    cairo_surface_destroy(full[i]);
  }
}

FillImages::~FillImages() {
  for (const FillImage& image : images_)
    if (image.surface) cairo_surface_destroy(image.surface);
}

const FillImage* FillImages::image(const Sheet& sheet, int index) const {
  const auto it = slot_.find(&sheet);
  if (it == slot_.end() || index < 0 || index >= static_cast<int>(it->second.size())) return nullptr;
  const FillImage& image = images_[it->second[index]];
  return image.surface ? &image : nullptr;
}

bool fill_matrix(const Fill& fill, const FillImage& image, cairo_matrix_t& sheet_to_image) {
  return matrix_for(fill, image.w, image.h, image.pad, sheet_to_image);
}

Rgb flat_colour(const Fill& fill, const FillImage* image) {
  Rgb c{fill.colour.r, fill.colour.g, fill.colour.b};
  if (!image) return c;
  const int x =
      std::clamp(static_cast<int>(image->pad + fill.uv[0].x * image->w), 0, image->w + 2 * image->pad - 1);
  const int y = std::clamp(static_cast<int>(image->pad + (1 - fill.uv[0].y) * image->h), 0,
                           image->h + 2 * image->pad - 1);
  cairo_surface_flush(image->surface);
  const auto* row = reinterpret_cast<const std::uint32_t*>(
      cairo_image_surface_get_data(image->surface) +
      static_cast<std::ptrdiff_t>(y) * cairo_image_surface_get_stride(image->surface));
  const std::uint32_t p = row[x];
  const double a = std::max(1u, p >> 24) / 255.0;
  return {c.r * ((p >> 16) & 255) / 255.0 / a, c.g * ((p >> 8) & 255) / 255.0 / a,
          c.b * (p & 255) / 255.0 / a};
}

void paint_fills(cairo_t* cr, const Sheet& sheet, const FillImages& images) {
  for (const Fill& fill : sheet.fills) {
    if (fill.outline_mm.size() < 3) continue;
    const FillImage* image = fill.image >= 0 ? images.image(sheet, fill.image) : nullptr;
    cairo_matrix_t m;
    cairo_save(cr);
    trace(cr, fill.outline_mm);
    if (image && fill_matrix(fill, *image, m)) {
      cairo_clip(cr);
      cairo_pattern_t* pattern = cairo_pattern_create_for_surface(image->surface);
      cairo_pattern_set_matrix(pattern, &m);
      cairo_pattern_set_extend(pattern, CAIRO_EXTEND_NONE);
      cairo_pattern_set_filter(pattern, CAIRO_FILTER_GOOD);
      cairo_set_source(cr, pattern);
      cairo_paint(cr);
      cairo_pattern_destroy(pattern);
      if (!is_white(fill.colour)) {
        cairo_set_operator(cr, CAIRO_OPERATOR_MULTIPLY);
        cairo_set_source_rgb(cr, fill.colour.r, fill.colour.g, fill.colour.b);
        cairo_paint(cr);
      }
    } else {
      const Rgb c = flat_colour(fill, image);
      cairo_set_source_rgb(cr, c.r, c.g, c.b);
      cairo_fill(cr);
    }
    cairo_restore(cr);
  }
}

std::string base64(const std::string& bytes) {
  static const char* kB64 = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve(bytes.size() / 3 * 4 + 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const auto byte = [&](std::size_t k) {
      return k < bytes.size() ? static_cast<unsigned char>(bytes[k]) : 0u;
    };
    const unsigned n = (byte(i) << 16) | (byte(i + 1) << 8) | byte(i + 2);
    out += kB64[(n >> 18) & 63];
    out += kB64[(n >> 12) & 63];
    out += i + 1 < bytes.size() ? kB64[(n >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? kB64[n & 63] : '=';
  }
  return out;
}

void trace_fill_outlines(cairo_t* cr, const Sheet& sheet) {
  cairo_new_path(cr);
  for (const Fill& fill : sheet.fills) {
    const auto& o = fill.outline_mm;
    if (o.size() < 3) continue;
    double area = 0;
    for (std::size_t i = 0; i < o.size(); ++i)
      area += cross(o[i], o[(i + 1) % o.size()]);
    for (std::size_t k = 0; k < o.size(); ++k) {
      const Vec2 p = area >= 0 ? o[k] : o[o.size() - 1 - k];
      (k == 0 ? cairo_move_to : cairo_line_to)(cr, p.x, p.y);
    }
    cairo_close_path(cr);
  }
}

FillRaster raster_fills(const Sheet& sheet, const FillImages& images, double max_dpi) {
  FillRaster out;
  if (sheet.fills.empty()) return out;
  double density = kMinRasterDpi / kMmPerInch;
  for (const Fill& fill : sheet.fills) {
    for (Vec2 p : fill.outline_mm)
      out.box_mm.add(p);
    cairo_matrix_t m;
    const FillImage* image = fill.image >= 0 ? images.image(sheet, fill.image) : nullptr;
    if (image && fill_matrix(fill, *image, m)) density = std::max(density, texels_per_mm(m));
  }
  double px_per_mm = std::min(density, std::max(max_dpi, kMinRasterDpi) / kMmPerInch);
  const double area_mm2 = std::max(out.box_mm.width() * out.box_mm.height(), 1.0);
  px_per_mm = std::min(px_per_mm, std::sqrt(kMaxRasterPixels / area_mm2));
  out.width_px = std::max(1, static_cast<int>(std::ceil(out.box_mm.width() * px_per_mm)));
  out.height_px = std::max(1, static_cast<int>(std::ceil(out.box_mm.height() * px_per_mm)));
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, out.width_px, out.height_px);
  cairo_t* cr = cairo_create(surface);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  cairo_scale(cr, out.width_px / out.box_mm.width(), out.height_px / out.box_mm.height());
  cairo_translate(cr, -out.box_mm.min.x, -out.box_mm.min.y);
  paint_fills(cr, sheet, images);
  cairo_destroy(cr);
  cairo_surface_flush(surface);
  if (cairo_surface_status(surface) == CAIRO_STATUS_SUCCESS) {
    const unsigned char* data = cairo_image_surface_get_data(surface);
    const int stride = cairo_image_surface_get_stride(surface);
    std::vector<unsigned char> rgb(static_cast<std::size_t>(out.width_px) * out.height_px * 3);
    for (int y = 0; y < out.height_px; ++y) {
      const auto* row =
          reinterpret_cast<const std::uint32_t*>(data + static_cast<std::ptrdiff_t>(y) * stride);
      for (int x = 0; x < out.width_px; ++x) {
        unsigned char* q = &rgb[(static_cast<std::size_t>(y) * out.width_px + x) * 3];
        q[0] = static_cast<unsigned char>(row[x] >> 16);
        q[1] = static_cast<unsigned char>(row[x] >> 8);
        q[2] = static_cast<unsigned char>(row[x]);
      }
    }
    stbi_write_jpg_to_func(
        [](void* closure, void* bytes, int size) {
          static_cast<std::string*>(closure)->append(static_cast<const char*>(bytes),
                                                     static_cast<std::size_t>(size));
        },
        &out.jpeg, out.width_px, out.height_px, 3, rgb.data(), kJpegQuality);
  }
  cairo_surface_destroy(surface);
  return out;
}

}  // namespace foldkit::devices::detail
