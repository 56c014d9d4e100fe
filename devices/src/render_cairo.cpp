// PDF and PNG through Cairo. The sheet is drawn once, in millimetres, onto a surface whose user space
// is scaled to millimetres: points (1/72 in) for PDF, pixels at the requested dpi for PNG.
#include <cairo-pdf.h>
#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <ostream>

#include "cairo_image.hpp"
#include "render_fills.hpp"
#include "render_internal.hpp"

namespace foldkit::devices::detail {
namespace {

constexpr double kMmPerInch = 25.4;
constexpr double kPointsPerMm = 72.0 / kMmPerInch;
// Cairo image surfaces are limited to 32767 pixels a side.
constexpr int kMaxImageSide = 32767;

cairo_status_t write_to_stream(void* closure, const unsigned char* data, unsigned int length) {
  auto* out = static_cast<std::ostream*>(closure);
  out->write(reinterpret_cast<const char*>(data), length);
  return *out ? CAIRO_STATUS_SUCCESS : CAIRO_STATUS_WRITE_ERROR;
}

void set_source(cairo_t* cr, Rgb c) {
  cairo_set_source_rgb(cr, c.r, c.g, c.b);
}

void trace(cairo_t* cr, const Path& path) {
  cairo_new_path(cr);
  bool first = true;
  for (Vec2 p : path.points_mm) {
    if (first) {
      cairo_move_to(cr, p.x, p.y);
      first = false;
    } else {
      cairo_line_to(cr, p.x, p.y);
    }
  }
  if (path.closed) cairo_close_path(cr);
}

void apply_line_style(cairo_t* cr, const RoleStyle& style) {
  cairo_set_line_width(cr, style.width_mm);
  double total = 0;
  for (double d : style.dash_mm)
    total += d;
  if (style.dash_mm.empty() || !(total > 0)) {
    cairo_set_dash(cr, nullptr, 0, 0);
  } else {
    cairo_set_dash(cr, style.dash_mm.data(), static_cast<int>(style.dash_mm.size()), 0);
  }
}

void draw_paths(cairo_t* cr, const Sheet& sheet, const RenderOptions& options, PathRole role) {
  const std::optional<RoleStyle> drawn = sheet_style(options, sheet, role);
  if (!drawn) return;
  const RoleStyle& style = *drawn;
  apply_line_style(cr, style);
  for (const Path& path : sheet.paths) {
    if (path.role != role || path.points_mm.empty()) continue;
    trace(cr, path);
    if (path.filled && path.tint >= 0) {
      // Guide views: the outline in the fill colour closes hairline gaps between neighbouring faces.
      set_source(cr, shaded_fill(path));
      cairo_fill_preserve(cr);
      cairo_stroke(cr);
      continue;
    }
    if (path.filled) {
      set_source(cr, style.stroke);
      cairo_fill_preserve(cr);
    } else if (path.closed && style.fill_closed) {
      set_source(cr, style.fill);
      cairo_fill_preserve(cr);
    }
    set_source(cr, path.tint >= 0 ? tint_colour(path.tint) : style.stroke);
    cairo_stroke(cr);
  }
}

// A text wider in the font found than the layout reserved (a fallback family) is squeezed along its
// baseline to the reserved length rather than run over the lines the layout kept it clear of.
void squeeze_to_width(cairo_t* cr, const Text& text) {
  if (!(text.width_mm > 0)) return;
  cairo_text_extents_t extents;
  cairo_text_extents(cr, text.text.c_str(), &extents);
  if (extents.x_advance > text.width_mm) cairo_scale(cr, text.width_mm / extents.x_advance, 1);
}

// Moves to a text's baseline start in its own frame (placed, turned and squeezed as the Text says) and
// calls `draw()` there.
template <class Draw>
void at_text(cairo_t* cr, const Text& text, Draw draw) {
  cairo_save(cr);
  cairo_translate(cr, text.at_mm.x, text.at_mm.y);
  // y points down, so a positive Cairo rotation turns clockwise on the page: the Text convention.
  cairo_rotate(cr, text.angle_rad);
  squeeze_to_width(cr, text);
  cairo_move_to(cr, 0, 0);
  draw();
  cairo_restore(cr);
}

// Calls `draw(text)` for every drawn text, role by role in paint order, with its family and size set.
template <class Draw>
void for_each_text(cairo_t* cr, const Sheet& sheet, const RenderOptions& options, const CapRatios& caps,
                   Draw draw) {
  for (PathRole role : kPaintOrder) {
    const bool label_font = in_label_font(role);
    const std::string& family = label_font ? options.label_font_family : options.font_family;
    const double cap_ratio = label_font ? caps.label : caps.text;
    cairo_select_font_face(cr, family.c_str(), CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    for (const Text& text : sheet.texts) {
      if (text.role != role || text.text.empty() || !(text.height_mm > 0)) continue;
      cairo_set_font_size(cr, text.height_mm / cap_ratio);
      draw(text);
    }
  }
}

// A white halo under each text `which` accepts.
template <class Which>
void paint_halos(cairo_t* cr, const Sheet& sheet, const RenderOptions& options, const CapRatios& caps,
                 Which which) {
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  for_each_text(cr, sheet, options, caps, [&](const Text& text) {
    if (!which(text)) return;
    cairo_new_path(cr);
    at_text(cr, text, [&] { cairo_text_path(cr, text.text.c_str()); });
    cairo_set_line_width(cr, kHaloPerCap * text.height_mm);
    cairo_stroke_preserve(cr);
    cairo_fill(cr);
  });
}

// On coloured sheets a white halo keeps texts readable on dark textures. It is painted before the lines,
// so a label close to its edge never whitens the cut or fold line it stands beside.
void draw_text_halos(cairo_t* cr, const Sheet& sheet, const RenderOptions& options, const CapRatios& caps) {
  if (sheet.fills.empty()) return;
  paint_halos(cr, sheet, options, caps, [](const Text&) { return true; });
}

// The halos painted over the paths of their role (Text::halo_over_paths), as the SVG writer does.
void draw_halos_over(cairo_t* cr, const Sheet& sheet, const RenderOptions& options, const CapRatios& caps,
                     PathRole role) {
  paint_halos(cr, sheet, options, caps,
              [role](const Text& text) { return text.halo_over_paths && text.role == role; });
}

void draw_texts(cairo_t* cr, const Sheet& sheet, const RenderOptions& options, const CapRatios& caps) {
  // Shown as text, not as glyph paths, so that the PDF keeps it as text (pdftotext, search, copy).
  for_each_text(cr, sheet, options, caps, [&](const Text& text) {
    set_source(cr, options.style(text.role).stroke);
    at_text(cr, text, [&] { cairo_show_text(cr, text.text.c_str()); });
  });
}

double measure_cap_ratio(cairo_t* cr, const std::string& family) {
  cairo_save(cr);
  cairo_select_font_face(cr, family.c_str(), CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, 100);
  cairo_text_extents_t extents;
  cairo_text_extents(cr, "H", &extents);
  cairo_restore(cr);
  const double ratio = -extents.y_bearing / 100;
  // A font without an "H" (or a broken fontconfig) must not blow texts up or make them vanish.
  return ratio > 0.3 && ratio < 1.2 ? ratio : 0.72;
}

// The legend of line styles in the box layout kept for it: each row a sample and its name.
void draw_legend(cairo_t* cr, const Sheet& sheet, const RenderOptions& options, double cap_ratio) {
  if (sheet.legend_mm.empty()) return;
  cairo_select_font_face(cr, options.font_family.c_str(), CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, kLegendText_mm / cap_ratio);
  for (std::size_t i = 0; i < kLegend.size(); ++i) {
    const LegendRow& row = kLegend[i];
    const RoleStyle& style = options.style(row.role);
    const auto [x, y] = legend_entry_mm(sheet, i);
    cairo_new_path(cr);
    if (row.box) {
      cairo_rectangle(cr, x, y - 1.5, kLegendSample_mm, 3);
      set_source(cr, style.fill);
      cairo_fill_preserve(cr);
    } else {
      cairo_move_to(cr, x, y);
      cairo_line_to(cr, x + kLegendSample_mm, y);
    }
    apply_line_style(cr, style);
    set_source(cr, style.stroke);
    cairo_stroke(cr);
    set_source(cr, options.sheet.stroke);
    cairo_move_to(cr, x + kLegendSample_mm + 1.5, y + 0.5 * kLegendText_mm);
    cairo_show_text(cr, row.name);
  }
}

// The fills of a PDF page: one JPEG per sheet through a clip to the fills' outlines (see FillRaster).
void paint_fill_raster(cairo_t* cr, const Sheet& sheet, const FillImages& images, double max_dpi) {
  FillRaster raster = raster_fills(sheet, images, max_dpi);
  if (raster.jpeg.empty()) return;
  SurfacePtr image(cairo_image_surface_create(CAIRO_FORMAT_RGB24, raster.width_px, raster.height_px));
  // The PDF embeds the JPEG bytes as they are; the white surface itself is never drawn into the file.
  auto* bytes = new std::string(std::move(raster.jpeg));
  cairo_surface_set_mime_data(
      image.get(), CAIRO_MIME_TYPE_JPEG, reinterpret_cast<const unsigned char*>(bytes->data()), bytes->size(),
      [](void* data) { delete static_cast<std::string*>(data); }, bytes);
  cairo_save(cr);
  trace_fill_outlines(cr, sheet);
  cairo_set_fill_rule(cr, CAIRO_FILL_RULE_WINDING);
  cairo_clip(cr);
  cairo_translate(cr, raster.box_mm.min.x, raster.box_mm.min.y);
  cairo_scale(cr, raster.box_mm.width() / raster.width_px, raster.box_mm.height() / raster.height_px);
  cairo_set_source_surface(cr, image.get(), 0, 0);
  cairo_paint(cr);
  cairo_restore(cr);
}

// Fills painted directly (PNG), or as one image per sheet (PDF: raster_dpi > 0).
void draw_sheet(cairo_t* cr, const Sheet& sheet, const RenderOptions& options, const CapRatios& caps,
                const FillImages& images, double raster_dpi = 0) {
  if (raster_dpi > 0)
    paint_fill_raster(cr, sheet, images, raster_dpi);
  else
    paint_fills(cr, sheet, images);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
  draw_text_halos(cr, sheet, options, caps);
  for (PathRole role : kPaintOrder) {
    draw_paths(cr, sheet, options, role);
    draw_halos_over(cr, sheet, options, caps, role);
  }
  draw_texts(cr, sheet, options, caps);
  draw_legend(cr, sheet, options, caps.text);
}

}  // namespace

double cap_height_ratio(const std::string& family) {
  SurfacePtr surface(cairo_image_surface_create(CAIRO_FORMAT_A8, 1, 1));
  ContextPtr cr(cairo_create(surface.get()));
  return measure_cap_ratio(cr.get(), family);
}

CapRatios cap_height_ratios(const RenderOptions& options) {
  return {cap_height_ratio(options.font_family), cap_height_ratio(options.label_font_family)};
}

bool in_label_font(PathRole role) {
  return role == PathRole::Label || role == PathRole::Hint;
}

bool write_pdf(std::ostream& out, const std::vector<Sheet>& sheets, const RenderOptions& options,
               const std::string& title, std::string& error) {
  SurfacePtr surface(cairo_pdf_surface_create_for_stream(write_to_stream, &out,
                                                         sheets.front().size_mm.x * kPointsPerMm,
                                                         sheets.front().size_mm.y * kPointsPerMm));
  cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_TITLE, title.c_str());
  cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_CREATOR, "foldkit");
  {
    ContextPtr cr(cairo_create(surface.get()));
    const CapRatios caps = cap_height_ratios(options);
    const FillImages images(sheets, options.image_dpi);
    for (const Sheet& sheet : sheets) {
      // Page size may change between pages; it must be set before anything is drawn on the page.
      cairo_pdf_surface_set_size(surface.get(), sheet.size_mm.x * kPointsPerMm,
                                 sheet.size_mm.y * kPointsPerMm);
      cairo_save(cr.get());
      cairo_scale(cr.get(), kPointsPerMm, kPointsPerMm);
      draw_sheet(cr.get(), sheet, options, caps, images, options.image_dpi);
      cairo_restore(cr.get());
      cairo_show_page(cr.get());
    }
    if (cairo_status(cr.get()) != CAIRO_STATUS_SUCCESS) {
      error = cairo_status_to_string(cairo_status(cr.get()));
      return false;
    }
  }
  cairo_surface_finish(surface.get());
  if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS) {
    error = cairo_status_to_string(cairo_surface_status(surface.get()));
    return false;
  }
  return true;
}

std::array<int, 2> png_size_px(const Sheet& sheet, double dpi) {
  const double px_per_mm = dpi / kMmPerInch;
  return {static_cast<int>(std::lround(sheet.size_mm.x * px_per_mm)),
          static_cast<int>(std::lround(sheet.size_mm.y * px_per_mm))};
}

bool write_png(std::ostream& out, const Sheet& sheet, const RenderOptions& options, std::string& error) {
  const double px_per_mm = options.png_dpi / kMmPerInch;
  if (sheet.size_mm.x * px_per_mm > kMaxImageSide || sheet.size_mm.y * px_per_mm > kMaxImageSide) {
    error = "image too large at this resolution (more than 32767 pixels a side): lower the dpi";
    return false;
  }
  const auto [width_px, height_px] = png_size_px(sheet, options.png_dpi);
  SurfacePtr surface(
      cairo_image_surface_create(CAIRO_FORMAT_RGB24, std::max(width_px, 1), std::max(height_px, 1)));
  {
    ContextPtr cr(cairo_create(surface.get()));
    cairo_set_source_rgb(cr.get(), 1, 1, 1);
    cairo_paint(cr.get());
    cairo_scale(cr.get(), px_per_mm, px_per_mm);
    const FillImages images(std::span<const Sheet>(&sheet, 1), std::min(options.image_dpi, options.png_dpi));
    draw_sheet(cr.get(), sheet, options, cap_height_ratios(options), images);
    if (cairo_status(cr.get()) != CAIRO_STATUS_SUCCESS) {
      error = cairo_status_to_string(cairo_status(cr.get()));
      return false;
    }
  }
  const cairo_status_t status = cairo_surface_write_to_png_stream(surface.get(), write_to_stream, &out);
  if (status != CAIRO_STATUS_SUCCESS) {
    error = cairo_status_to_string(status);
    return false;
  }
  return true;
}

}  // namespace foldkit::devices::detail
