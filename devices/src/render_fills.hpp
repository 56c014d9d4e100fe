#pragma once
// Internal to the renderers: a sheet's fills (flat colours and affinely mapped texture regions).
// Images are decoded once per document and never embedded finer than the print resolution asks.
#include <cairo.h>

#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "foldkit/devices/render.hpp"

namespace foldkit::devices::detail {

/// The decoded texture images of a set of sheets, each scaled down so that no fill shows more than
/// `max_dpi` texels per inch of paper. An image that cannot be decoded has no surface: its fills print
/// in their flat colour.
/// One decoded image: `surface` holds the w x h image inside a border of `pad` pixels that repeat its
/// edges, so that coordinates a little outside [0,1] (common at texture seams) still find colour
/// without Cairo's EXTEND_PAD, which its PDF backend turns into one padded copy of the image per use.
struct FillImage {
  cairo_surface_t* surface = nullptr;
  int w = 0, h = 0, pad = 0;
};

class FillImages {
 public:
  FillImages(std::span<const Sheet> sheets, double max_dpi);
  FillImages(const FillImages&) = delete;
  FillImages& operator=(const FillImages&) = delete;
  ~FillImages();
  /// Image `index` of `sheet` (one of the sheets given), nullptr when it did not decode.
  const FillImage* image(const Sheet& sheet, int index) const;
  /// Images that did not decode, one name each.
  const std::vector<std::string>& failed() const { return failed_; }

 private:
  std::vector<FillImage> images_;                  // per distinct image
  std::map<const Sheet*, std::vector<int>> slot_;  // sheet image index -> distinct image
  std::vector<std::string> failed_;
};

/// The map from the sheet (mm) to a fill's image (pixels, y down), or false when the face or its
/// texture coordinates are degenerate.
bool fill_matrix(const Fill& fill, const FillImage& image, cairo_matrix_t& sheet_to_image);

/// Paints every fill of `sheet` (textures clipped to their outlines, multiplied by their colour).
void paint_fills(cairo_t* cr, const Sheet& sheet, const FillImages& images);

/// The fills of a sheet as one JPEG for the vector formats (PDF, SVG): painted on white at the texture's
/// own density (at least kMinRasterDpi, at most max_dpi) over the box that holds them, and shown through
/// a clip to the fills' outlines so that edges stay sharp. One image per sheet keeps files small and
/// viewers fast, where one clipped copy of the texture per face made a viewer scale the whole texture
/// hundreds of times.
struct FillRaster {
  Box2 box_mm;
  int width_px = 0, height_px = 0;
  std::string jpeg;  ///< empty when the sheet has no fills or encoding failed
};
FillRaster raster_fills(const Sheet& sheet, const FillImages& images, double max_dpi);

/// Adds every fill outline as a counter-clockwise sub-path: a winding clip of them is their union.
void trace_fill_outlines(cairo_t* cr, const Sheet& sheet);

/// `bytes` in base64, for data: URIs.
std::string base64(const std::string& bytes);

/// The colour a fill prints in when it has no usable image: its colour times the texel at its first
/// corner's coordinates (or its colour alone).
Rgb flat_colour(const Fill& fill, const FillImage* image);

}  // namespace foldkit::devices::detail
