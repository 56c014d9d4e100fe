// SVG written by hand rather than through Cairo's SVG surface: Cairo 1.16 cannot name groups, and
// cutting software (Silhouette Studio, Inkscape, Cricut Design Space) picks layers by group id. Every
// role gets its own <g id="…"> (also marked as an Inkscape layer), present even when empty so that
// tools can rely on its ids, and texts stay <text> elements so they remain editable.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <ostream>
#include <string>
#include <string_view>

#include "render_fills.hpp"
#include "render_internal.hpp"

namespace foldkit::devices::detail {
namespace {

// Micrometre precision, locale-independent, no trailing zeros.
std::string num(double v) {
  if (!std::isfinite(v)) return "0";
  if (std::abs(v) < 5e-5) v = 0;
  char buffer[64];
  auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v, std::chars_format::fixed, 4);
  std::string s(buffer, ec == std::errc() ? end : buffer);
  if (s.find('.') != std::string::npos) {
    while (!s.empty() && s.back() == '0')
      s.pop_back();
    if (!s.empty() && s.back() == '.') s.pop_back();
  }
  return s.empty() || s == "-0" ? "0" : s;
}

std::string colour(Rgb c) {
  auto channel = [](double v) {
    const int i = static_cast<int>(std::lround(std::fmin(std::fmax(v, 0.0), 1.0) * 255));
    constexpr char hex[] = "0123456789abcdef";
    return std::string{hex[i >> 4], hex[i & 15]};
  };
  // Appended piecewise: GCC 12 warns falsely (-Wrestrict) on chained literal + string concatenation.
  std::string out("#");
  out.append(channel(c.r)).append(channel(c.g)).append(channel(c.b));
  return out;
}

std::string escape(std::string_view text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        // Control characters are not allowed in XML 1.0; they carry no meaning on a sheet.
        if (static_cast<unsigned char>(c) >= 0x20 || c == '\t') out += c;
    }
  }
  return out;
}

void write_group_open(std::ostream& out, PathRole role, const RoleStyle& style) {
  const char* name = role_name(role);
  out << "  <g id=\"" << name << "\" inkscape:groupmode=\"layer\" inkscape:label=\"" << name << "\"";
  out << " fill=\"none\" stroke=\"" << colour(style.stroke) << "\" stroke-width=\"" << num(style.width_mm)
      << "\" stroke-linejoin=\"round\" stroke-linecap=\"butt\"";
  double total = 0;
  for (double d : style.dash_mm)
    total += d;
  if (!style.dash_mm.empty() && total > 0) {
    out << " stroke-dasharray=\"";
    for (std::size_t i = 0; i < style.dash_mm.size(); ++i)
      out << (i ? " " : "") << num(style.dash_mm[i]);
    out << "\"";
  }
  out << ">\n";
}

void write_path(std::ostream& out, const Path& path, const RoleStyle& style) {
  out << "    <path d=\"";
  for (std::size_t i = 0; i < path.points_mm.size(); ++i) {
    out << (i == 0 ? "M" : " L") << num(path.points_mm[i].x) << " " << num(path.points_mm[i].y);
  }
  if (path.closed) out << " Z";
  out << "\"";
  if (path.filled && path.tint >= 0) {
    const std::string fill = colour(shaded_fill(path));
    out << " stroke=\"" << fill << "\" fill=\"" << fill << "\"/>\n";
    return;
  }
  if (path.tint >= 0) out << " stroke=\"" << colour(tint_colour(path.tint)) << "\"";
  if (path.filled) {
    out << " fill=\"" << colour(style.stroke) << "\"";
  } else if (path.closed && style.fill_closed) {
    out << " fill=\"" << colour(style.fill) << "\"";
  }
  out << "/>\n";
}

// Fills in a group of their own under the role groups: one embedded JPEG per sheet (see FillRaster)
// through a clip to the fills' outlines.
void write_fills(std::ostream& out, const Sheet& sheet, const RenderOptions& options) {
  if (sheet.fills.empty()) return;
  const FillImages images(std::span<const Sheet>(&sheet, 1), options.image_dpi);
  const FillRaster raster = raster_fills(sheet, images, options.image_dpi);
  if (raster.jpeg.empty()) return;
  out << "  <defs>\n    <clipPath id=\"fills\">\n";
  for (const Fill& fill : sheet.fills) {
    out << "      <path d=\"";
    for (std::size_t i = 0; i < fill.outline_mm.size(); ++i)
      out << (i == 0 ? "M" : " L") << num(fill.outline_mm[i].x) << " " << num(fill.outline_mm[i].y);
    out << " Z\"/>\n";
  }
  out << "    </clipPath>\n  </defs>\n";
  out << "  <g id=\"fill\" inkscape:groupmode=\"layer\" inkscape:label=\"fill\" clip-path=\"url(#fills)\">\n"
      << "    <image x=\"" << num(raster.box_mm.min.x) << "\" y=\"" << num(raster.box_mm.min.y)
      << "\" width=\"" << num(raster.box_mm.width()) << "\" height=\"" << num(raster.box_mm.height())
      << "\" preserveAspectRatio=\"none\" xlink:href=\"data:image/jpeg;base64," << base64(raster.jpeg)
      << "\"/>\n  </g>\n";
}

// A text in its colour, or (`halo`) its white halo.
void write_text(std::ostream& out, const Text& text, const RenderOptions& options, double cap_ratio,
                bool halo) {
  constexpr double kDegPerRad = 57.29577951308232;
  out << "    <text x=\"" << num(text.at_mm.x) << "\" y=\"" << num(text.at_mm.y) << "\" font-size=\""
      << num(text.height_mm / cap_ratio) << "\"";
  // The viewer's fonts are not ours: whatever family it finds, the text takes the length reserved.
  if (text.width_mm > 0)
    out << " textLength=\"" << num(text.width_mm) << "\" lengthAdjust=\"spacingAndGlyphs\"";
  // y points down in SVG too, so a positive angle is clockwise on the page, as in Text.
  if (text.angle_rad != 0) {
    out << " transform=\"rotate(" << num(text.angle_rad * kDegPerRad) << " " << num(text.at_mm.x) << " "
        << num(text.at_mm.y) << ")\"";
  }
  if (halo)
    out << " stroke=\"#ffffff\" stroke-width=\"" << num(kHaloPerCap * text.height_mm)
        << "\" stroke-linejoin=\"round\" fill=\"#ffffff\">";
  else
    out << " fill=\"" << colour(options.style(text.role).stroke) << "\">";
  out << escape(text.text) << "</text>\n";
}

// On coloured sheets a white halo keeps texts readable on dark textures: a white copy of every text,
// stroked, in a group before the lines, so a label close to its edge never whitens the line beside it.
void write_text_halos(std::ostream& out, const Sheet& sheet, const RenderOptions& options,
                      const CapRatios& caps) {
  if (sheet.fills.empty()) return;
  out << "  <g id=\"halo\">\n";
  for (PathRole role : kPaintOrder) {
    const bool label_font = in_label_font(role);
    out << "    <g font-family=\"" << escape(label_font ? options.label_font_family : options.font_family)
        << "\">\n";
    for (const Text& text : sheet.texts)
      if (text.role == role && !text.text.empty())
        write_text(out, text, options, label_font ? caps.label : caps.text, true);
    out << "    </g>\n";
  }
  out << "  </g>\n";
}

// The halos painted over the paths of `role` (Text::halo_over_paths), in its group after them.
void write_halos_over(std::ostream& out, const Sheet& sheet, const RenderOptions& options, double cap_ratio,
                      PathRole role, const std::string& family) {
  const auto over = [role](const Text& t) { return t.role == role && t.halo_over_paths && !t.text.empty(); };
  if (std::none_of(sheet.texts.begin(), sheet.texts.end(), over)) return;
  out << "    <g font-family=\"" << escape(family) << "\">\n";
  for (const Text& text : sheet.texts)
    if (over(text)) write_text(out, text, options, cap_ratio, true);
  out << "    </g>\n";
}

// The legend of line styles in the box layout kept for it, inside the sheet group.
void write_legend(std::ostream& out, const Sheet& sheet, const RenderOptions& options, double cap_ratio) {
  if (sheet.legend_mm.empty()) return;
  for (std::size_t i = 0; i < kLegend.size(); ++i) {
    const LegendRow& row = kLegend[i];
    const RoleStyle& style = options.style(row.role);
    const auto [x, y] = legend_entry_mm(sheet, i);
    out << "    <path d=\"M" << num(x) << " " << num(row.box ? y - 1.5 : y) << " L"
        << num(x + kLegendSample_mm) << " " << num(row.box ? y - 1.5 : y);
    if (row.box)
      out << " L" << num(x + kLegendSample_mm) << " " << num(y + 1.5) << " L" << num(x) << " " << num(y + 1.5)
          << " Z";
    out << "\" stroke=\"" << colour(style.stroke) << "\" stroke-width=\"" << num(style.width_mm) << "\"";
    if (!style.dash_mm.empty()) {
      out << " stroke-dasharray=\"";
      for (std::size_t d = 0; d < style.dash_mm.size(); ++d)
        out << (d ? " " : "") << num(style.dash_mm[d]);
      out << "\"";
    }
    out << " fill=\"" << (row.box ? colour(style.fill) : std::string("none")) << "\"/>\n";
    out << "    <text x=\"" << num(x + kLegendSample_mm + 1.5) << "\" y=\"" << num(y + 0.5 * kLegendText_mm)
        << "\" font-size=\"" << num(kLegendText_mm / cap_ratio) << "\" stroke=\"none\" font-family=\""
        << escape(options.font_family) << "\" fill=\"" << colour(options.sheet.stroke) << "\">" << row.name
        << "</text>\n";
  }
}

}  // namespace

void write_svg(std::ostream& out, const Sheet& sheet, const RenderOptions& options, const CapRatios& caps) {
  const std::string w = num(sheet.size_mm.x), h = num(sheet.size_mm.y);
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" "
         "xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\" "
         "xmlns:xlink=\"http://www.w3.org/1999/xlink\" version=\"1.1\" width=\""
      << w << "mm\" height=\"" << h << "mm\" viewBox=\"0 0 " << w << " " << h << "\">\n";
  write_fills(out, sheet, options);
  write_text_halos(out, sheet, options, caps);
  for (PathRole role : kPaintOrder) {
    const std::optional<RoleStyle> drawn = sheet_style(options, sheet, role);
    const RoleStyle& style = drawn ? *drawn : options.style(role);
    write_group_open(out, role, style);
    for (const Path& path : sheet.paths) {
      if (drawn && path.role == role && !path.points_mm.empty()) write_path(out, path, style);
    }
    const bool label_font = in_label_font(role);
    write_halos_over(out, sheet, options, label_font ? caps.label : caps.text, role,
                     label_font ? options.label_font_family : options.font_family);
    bool any_text = false;
    for (const Text& text : sheet.texts) {
      if (text.role != role || text.text.empty()) continue;
      if (!any_text) {
        // Texts are filled glyphs, not outlines: undo the group's stroke for them.
        out << "    <g stroke=\"none\" font-family=\""
            << escape(label_font ? options.label_font_family : options.font_family) << "\">\n";
        any_text = true;
      }
      write_text(out, text, options, label_font ? caps.label : caps.text, false);
    }
    if (any_text) out << "    </g>\n";
    if (role == PathRole::Sheet) write_legend(out, sheet, options, caps.text);
    out << "  </g>\n";
  }
  out << "</svg>\n";
}

}  // namespace foldkit::devices::detail
