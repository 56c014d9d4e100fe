#include "foldkit/devices/stroke_font.hpp"

#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "foldkit/error.hpp"

namespace foldkit::devices {
namespace {

// In .jhf data every coordinate is a character whose offset from 'R' is the value, and the pair " R"
// lifts the pen. Each record: 5 columns glyph id, 3 columns vertex count (counting the left/right
// pair), then the pairs; long records of the original distribution wrap at 72 columns.
constexpr int kOrigin = 'R';

bool is_coordinate(char c) {
  return c >= ' ' && c <= '~';
}

std::string trim_right(std::string s) {
  while (!s.empty() && (s.back() == '\r' || s.back() == '\n'))
    s.pop_back();
  return s;
}

StrokeGlyph parse_glyph(const std::string& pairs, const std::string& file, int line) {
  auto fail = [&](const std::string& problem) {
    throw InputError(file, "line " + std::to_string(line) + ": " + problem);
  };
  StrokeGlyph glyph;
  for (char c : pairs) {
    if (!is_coordinate(c)) fail("invalid coordinate character");
  }
  glyph.left = pairs[0] - kOrigin;
  glyph.right = pairs[1] - kOrigin;
  if (glyph.right < glyph.left) fail("glyph's right limit is left of its left limit");
  std::vector<Vec2> stroke;
  for (std::size_t i = 2; i + 1 < pairs.size(); i += 2) {
    if (pairs[i] == ' ' && pairs[i + 1] == 'R') {
      if (!stroke.empty()) glyph.strokes.push_back(std::move(stroke));
      stroke.clear();
      continue;
    }
    stroke.push_back({static_cast<double>(pairs[i] - kOrigin), static_cast<double>(pairs[i + 1] - kOrigin)});
  }
  if (!stroke.empty()) glyph.strokes.push_back(std::move(stroke));
  return glyph;
}

// Capital height and baseline from "H" when the font has one; symbol fonts fall back to the extent
// of all glyphs so that height_mm still means the height of the tallest mark.
void measure(StrokeFont& font) {
  auto extent = [](const StrokeGlyph& g, double& top, double& bottom) {
    for (const auto& stroke : g.strokes) {
      for (Vec2 p : stroke) {
        top = std::fmin(top, p.y);
        bottom = std::fmax(bottom, p.y);
      }
    }
  };
  double top = 1e300, bottom = -1e300;
  if (const StrokeGlyph* h = font.glyph(U'H')) extent(*h, top, bottom);
  if (!(bottom > top)) {
    for (const StrokeGlyph& g : font.glyphs)
      extent(g, top, bottom);
  }
  if (bottom > top) {
    font.baseline = bottom;
    font.cap_height = bottom - top;
  }
}

// Decodes UTF-8 leniently: a malformed byte becomes U+FFFD so it is drawn as "?" and never skipped silently.
std::u32string decode_utf8(std::string_view text) {
  std::u32string out;
  for (std::size_t i = 0; i < text.size();) {
    const auto b = static_cast<unsigned char>(text[i]);
    const int extra = b < 0x80 ? 0 : (b >> 5) == 6 ? 1 : (b >> 4) == 14 ? 2 : (b >> 3) == 30 ? 3 : -1;
    const bool truncated = extra > 0 && i + static_cast<std::size_t>(extra) >= text.size();
    if (extra < 0 || truncated) {
      out.push_back(U'\uFFFD');
      ++i;
      continue;
    }
    char32_t code = extra == 0 ? b : static_cast<char32_t>(b & (0x3F >> extra));
    bool ok = true;
    for (int k = 1; k <= extra; ++k) {
      const auto c = static_cast<unsigned char>(text[i + k]);
      if ((c >> 6) != 2) ok = false;
      code = (code << 6) | (c & 0x3F);
    }
    out.push_back(ok ? code : U'\uFFFD');
    i += ok ? extra + 1 : 1;
  }
  return out;
}

const StrokeGlyph* glyph_or_replacement(const StrokeFont& font, char32_t code) {
  if (const StrokeGlyph* g = font.glyph(code)) return g;
  return font.glyph(U'?');
}

}  // namespace

const StrokeGlyph* StrokeFont::glyph(char32_t code) const {
  if (code < first_code || code - first_code >= glyphs.size()) return nullptr;
  return &glyphs[code - first_code];
}

StrokeFont load_stroke_font(const std::filesystem::path& path) {
  const std::string file = path.string();
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(file, "cannot open font file");
  StrokeFont font;
  font.name = path.stem().string();
  std::string line;
  int line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    line = trim_right(line);
    if (line.empty()) continue;
    const int record_line = line_number;
    if (line.size() < 10)
      throw InputError(file, "line " + std::to_string(line_number) + ": record too short");
    const std::string count_field = line.substr(5, 3);
    int vertices = 0;
    bool digits = false;
    for (char c : count_field) {
      if (c == ' ' && !digits) continue;
      if (!std::isdigit(static_cast<unsigned char>(c))) {
        throw InputError(file, "line " + std::to_string(line_number) + ": vertex count is not a number");
      }
      vertices = vertices * 10 + (c - '0');
      digits = true;
    }
    if (vertices < 1) throw InputError(file, "line " + std::to_string(line_number) + ": no vertices");
    std::string pairs = line.substr(8);
    const std::size_t wanted = static_cast<std::size_t>(vertices) * 2;
    while (pairs.size() < wanted && std::getline(in, line)) {
      ++line_number;
      pairs += trim_right(line);
    }
    if (pairs.size() != wanted) {
      throw InputError(file, "line " + std::to_string(record_line) + ": expected " +
                                 std::to_string(vertices) + " coordinate pairs, found " +
                                 std::to_string(pairs.size() / 2.0));
    }
    font.glyphs.push_back(parse_glyph(pairs, file, record_line));
  }
  if (in.bad()) throw InputError(file, "read error");
  if (font.glyphs.empty()) throw InputError(file, "no glyphs (not a Hershey .jhf font)");
  measure(font);
  return font;
}

double text_advance_mm(const StrokeFont& font, std::string_view text, double height_mm) {
  const double scale = height_mm / font.cap_height;
  double advance = 0;
  for (char32_t code : decode_utf8(text)) {
    if (code < 32 || code == 127) continue;
    if (const StrokeGlyph* g = glyph_or_replacement(font, code)) advance += (g->right - g->left) * scale;
  }
  return advance;
}

std::vector<std::vector<Vec2>> text_strokes(const StrokeFont& font, std::string_view text, Vec2 at_mm,
                                            double height_mm, double angle_rad, double width_mm) {
  std::vector<std::vector<Vec2>> out;
  if (!(height_mm > 0) || !std::isfinite(height_mm)) return out;
  const double scale = height_mm / font.cap_height;
  const double advance_mm = text_advance_mm(font, text, height_mm);
  // Along the baseline only: a stroke font squeezed to the reserved length keeps its height.
  const double squeeze = width_mm > 0 && advance_mm > width_mm ? width_mm / advance_mm : 1.0;
  double cursor = 0;  // font units along the baseline
  for (char32_t code : decode_utf8(text)) {
    if (code < 32 || code == 127) continue;
    const StrokeGlyph* g = glyph_or_replacement(font, code);
    if (g == nullptr) continue;
    for (const auto& stroke : g->strokes) {
      std::vector<Vec2> placed;
      placed.reserve(stroke.size());
      for (Vec2 p : stroke) {
        const Vec2 local{(cursor + p.x - g->left) * scale * squeeze, (p.y - font.baseline) * scale};
        // With y down, the standard rotation turns clockwise on the page: the Text convention.
        placed.push_back(at_mm + rotated(local, angle_rad));
      }
      out.push_back(std::move(placed));
    }
    cursor += g->right - g->left;
  }
  return out;
}

std::vector<std::vector<Vec2>> text_strokes(const StrokeFont& font, const Text& text) {
  return text_strokes(font, text.text, text.at_mm, text.height_mm, text.angle_rad, text.width_mm);
}

}  // namespace foldkit::devices
