#include "foldkit/devices/stroke_font.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <optional>
#include <string>

#include "foldkit/error.hpp"
#include "test_paths.hpp"

namespace fs = std::filesystem;
using foldkit::Box2;
using foldkit::InputError;
using foldkit::Vec2;
using foldkit::devices::load_stroke_font;
using foldkit::devices::StrokeFont;
using foldkit::devices::text_advance_mm;
using foldkit::devices::text_strokes;

namespace {

using Strokes = std::vector<std::vector<Vec2>>;

Box2 bounds(const Strokes& strokes) {
  Box2 box;
  for (const auto& s : strokes) {
    for (Vec2 p : s)
      box.add(p);
  }
  return box;
}

std::size_t point_count(const Strokes& strokes) {
  std::size_t n = 0;
  for (const auto& s : strokes)
    n += s.size();
  return n;
}

// Hershey fonts are a Debian package; the project's set-up installs it, but a bare machine may lack it.
const StrokeFont* futural() {
  static const std::optional<StrokeFont> font =
      fs::exists(foldkit::test::stroke_font_path())
          ? std::optional(load_stroke_font(foldkit::test::stroke_font_path()))
          : std::nullopt;
  return font ? &*font : nullptr;
}

fs::path write_file(const std::string& name, const std::string& contents) {
  const fs::path p = foldkit::test::temp_dir("font") / name;
  std::ofstream(p, std::ios::binary) << contents;
  return p;
}

#define REQUIRE_FONT()      \
  if (futural() == nullptr) \
  GTEST_SKIP() << "hershey-fonts-data not installed (" << foldkit::test::stroke_font_path() << ")"

}  // namespace

TEST(StrokeFont, LoadsThePrintableAsciiGlyphsOfFutural) {
  REQUIRE_FONT();
  const StrokeFont& font = *futural();
  EXPECT_EQ(font.name, "futural");
  ASSERT_GE(font.glyphs.size(), 95u);
  EXPECT_TRUE(font.glyph(U' ')->strokes.empty());
  EXPECT_FALSE(font.glyph(U'A')->strokes.empty());
  EXPECT_EQ(font.glyph(U'\u00e9'), nullptr);
  // "H" in futural: x from -7 to 7 around the centre, y from -12 (top) to 9 (baseline).
  EXPECT_DOUBLE_EQ(font.baseline, 9);
  EXPECT_DOUBLE_EQ(font.cap_height, 21);
}

TEST(StrokeFont, EveryDigitIsNonEmptyAndLiesInItsBox) {
  REQUIRE_FONT();
  const StrokeFont& font = *futural();
  const double height = 4;
  for (char digit = '0'; digit <= '9'; ++digit) {
    const std::string text(1, digit);
    const Strokes strokes = text_strokes(font, text, {50, 80}, height);
    ASSERT_FALSE(strokes.empty()) << digit;
    const Box2 box = bounds(strokes);
    const double advance = text_advance_mm(font, text, height);
    // Digits stand on the baseline and reach cap height; nothing leaves the advance cell.
    EXPECT_NEAR(box.max.y, 80, 1e-9) << digit;
    EXPECT_NEAR(box.min.y, 80 - height, 1e-9) << digit;
    EXPECT_GE(box.min.x, 50 - 1e-9) << digit;
    EXPECT_LE(box.max.x, 50 + advance + 1e-9) << digit;
    EXPECT_GT(box.width(), 0.2 * height) << digit << " is not a sliver";
  }
}

TEST(StrokeFont, WidthScalesWithHeight) {
  REQUIRE_FONT();
  const StrokeFont& font = *futural();
  const Box2 small = bounds(text_strokes(font, "1234", {0, 0}, 3));
  const Box2 large = bounds(text_strokes(font, "1234", {0, 0}, 7.5));
  EXPECT_NEAR(large.width() / small.width(), 2.5, 1e-9);
  EXPECT_NEAR(large.height() / small.height(), 2.5, 1e-9);
  EXPECT_NEAR(text_advance_mm(font, "1234", 7.5) / text_advance_mm(font, "1234", 3), 2.5, 1e-9);
}

TEST(StrokeFont, ATextLongerThanItsReservedWidthIsSqueezedAlongItsBaselineOnly) {
  REQUIRE_FONT();
  const StrokeFont& font = *futural();
  const Box2 natural = bounds(text_strokes(font, "B12 p3", {0, 0}, 4));
  const double advance = text_advance_mm(font, "B12 p3", 4);
  const Box2 squeezed = bounds(text_strokes(font, "B12 p3", {0, 0}, 4, 0, 0.7 * advance));
  EXPECT_NEAR(squeezed.width(), 0.7 * natural.width(), 1e-9);
  EXPECT_NEAR(squeezed.height(), natural.height(), 1e-9);
  EXPECT_LE(squeezed.max.x, 0.7 * advance + 1e-9) << "inside the reserved length";
  const Box2 roomy = bounds(text_strokes(font, "B12 p3", {0, 0}, 4, 0, 2 * advance));
  EXPECT_NEAR(roomy.width(), natural.width(), 1e-9) << "a shorter text is not stretched";
}

TEST(StrokeFont, RotationTurnsTheTextClockwiseAboutItsAnchor) {
  REQUIRE_FONT();
  const StrokeFont& font = *futural();
  const Vec2 at{100, 100};
  const Strokes flat = text_strokes(font, "42", at, 5, 0);
  const Strokes turned = text_strokes(font, "42", at, 5, std::numbers::pi / 2);
  ASSERT_EQ(point_count(flat), point_count(turned));
  for (std::size_t s = 0; s < flat.size(); ++s) {
    for (std::size_t i = 0; i < flat[s].size(); ++i) {
      const Vec2 d = flat[s][i] - at;
      // A quarter turn clockwise on a y-down page maps (x, y) to (-y, x).
      EXPECT_NEAR(turned[s][i].x, at.x - d.y, 1e-9);
      EXPECT_NEAR(turned[s][i].y, at.y + d.x, 1e-9);
    }
  }
  // Running downwards the page: the text extends below its anchor, not above.
  EXPECT_GT(bounds(turned).max.y, at.y + text_advance_mm(font, "42", 5) * 0.9);
}

TEST(StrokeFont, MissingCharactersAreDrawnAsAQuestionMark) {
  REQUIRE_FONT();
  const StrokeFont& font = *futural();
  const Strokes unknown = text_strokes(font, "\xc3\xa9", {0, 0}, 5);  // é
  const Strokes question = text_strokes(font, "?", {0, 0}, 5);
  EXPECT_EQ(point_count(unknown), point_count(question));
  EXPECT_TRUE(text_strokes(font, "\n\t", {0, 0}, 5).empty()) << "control characters draw nothing";
  EXPECT_EQ(point_count(text_strokes(font, "\xff", {0, 0}, 5)), point_count(question)) << "malformed UTF-8";
}

TEST(StrokeFont, TextStrokesOfASheetTextMatchTheExplicitCall) {
  REQUIRE_FONT();
  const StrokeFont& font = *futural();
  const foldkit::Text text{"12", {30, 40}, 3.5, 0.3};
  EXPECT_EQ(text_strokes(font, text), text_strokes(font, "12", {30, 40}, 3.5, 0.3));
}

TEST(StrokeFont, LoadsEveryFontOfTheDebianPackage) {
  const fs::path dir = foldkit::test::stroke_font_path().parent_path();
  if (!fs::is_directory(dir)) GTEST_SKIP() << "hershey-fonts-data not installed (" << dir << ")";
  int fonts = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.path().extension() != ".jhf") continue;
    const StrokeFont font = load_stroke_font(entry.path());
    EXPECT_GE(font.glyphs.size(), 90u) << entry.path();
    EXPECT_GT(font.cap_height, 0) << entry.path();
    ++fonts;
  }
  EXPECT_GE(fonts, 10);
}

TEST(StrokeFont, ReadsRecordsWrappedOverSeveralLines) {
  // Space, then "I" as in futural but with its pairs wrapped after the first one.
  const fs::path p = write_file("wrapped.jhf", "12345  1JZ\n12345  3NVRF\nR[\n");
  const StrokeFont font = load_stroke_font(p);
  ASSERT_EQ(font.glyphs.size(), 2u);
  ASSERT_EQ(font.glyph(U'!')->strokes.size(), 1u);
  EXPECT_EQ(font.glyph(U'!')->strokes[0], (std::vector<Vec2>{{0, -12}, {0, 9}}));
}

TEST(StrokeFont, AMissingFileIsAnInputError) {
  EXPECT_THROW(load_stroke_font("/nonexistent/font.jhf"), InputError);
}

TEST(StrokeFont, AnEmptyFileIsAnInputError) {
  EXPECT_THROW(load_stroke_font(write_file("empty.jhf", "")), InputError);
}

TEST(StrokeFont, ATruncatedRecordIsAnInputErrorNamingTheLine) {
  const fs::path p = write_file("short.jhf", "12345  1JZ\n12345  9MWRFRT RRYQZ\n");
  try {
    load_stroke_font(p);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), p.string());
    EXPECT_NE(e.problem().find("line 2"), std::string::npos) << e.what();
  }
}

TEST(StrokeFont, ANonNumericVertexCountIsAnInputError) {
  EXPECT_THROW(load_stroke_font(write_file("count.jhf", "12345 abJZRRRR\n")), InputError);
}

TEST(StrokeFont, ABinaryFileIsAnInputError) {
  EXPECT_THROW(load_stroke_font(write_file("binary.jhf", std::string("12345  2JZ\x01\x02\n"))), InputError);
}
