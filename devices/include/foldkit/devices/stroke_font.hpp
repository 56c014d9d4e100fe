#pragma once
// Single-stroke text for pens on plotters and cutters: Hershey fonts in the .jhf format of Debian's
// hershey-fonts-data. Outline fonts would be drawn as their outlines, twice per stroke; a Hershey
// glyph is the centre line a pen follows once. Labels use "futural" (simplex sans), found by
// install_paths.hpp's find_stroke_font.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "foldkit/geom/vec.hpp"
#include "foldkit/sheet/sheet.hpp"

namespace foldkit::devices {

/// One glyph in font units (y down, as in the .jhf data): strokes relative to the glyph's centre,
/// and the left and right limits that give its advance.
struct StrokeGlyph {
  double left = 0, right = 0;              ///< advance = right - left
  std::vector<std::vector<Vec2>> strokes;  ///< pen-down polylines
};

/// A loaded Hershey font. Glyph i draws the character with code `first_code + i` (ASCII from 32).
struct StrokeFont {
  std::string name;          ///< file stem, e.g. "futural"
  char32_t first_code = 32;  ///< code of glyphs[0]
  std::vector<StrokeGlyph> glyphs;
  double baseline = 9;     ///< y of the baseline in font units (bottom of "H")
  double cap_height = 21;  ///< height of capitals in font units (height of "H")

  /// The glyph for `code`, or nullptr when the font has none.
  const StrokeGlyph* glyph(char32_t code) const;
};

/// Reads a .jhf Hershey font (glyphs in file order from ASCII 32; records may continue over several
/// lines). Throws InputError naming the file and line for a missing, empty or malformed file.
StrokeFont load_stroke_font(const std::filesystem::path& path);

/// Polylines (sheet mm, y down) a pen draws for `text`, placed like sheet.hpp's Text: `at_mm` is the
/// left end of the baseline, capitals and digits are `height_mm` tall, the text runs along
/// `angle_rad` (positive = clockwise on the page). UTF-8 input; characters the font lacks are drawn
/// as "?" (or skipped when there is no "?"), control characters are ignored. With `width_mm` > 0 a
/// text whose advance is longer is squeezed along its baseline to that length (its height kept).
std::vector<std::vector<Vec2>> text_strokes(const StrokeFont& font, std::string_view text, Vec2 at_mm,
                                            double height_mm, double angle_rad = 0, double width_mm = 0);

/// The strokes of a sheet Text, squeezed to its width_mm when it has one.
std::vector<std::vector<Vec2>> text_strokes(const StrokeFont& font, const Text& text);

/// Length of `text` along its baseline in mm at `height_mm` (sum of glyph advances).
double text_advance_mm(const StrokeFont& font, std::string_view text, double height_mm);

}  // namespace foldkit::devices
