#include "foldkit/devices/render.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "foldkit/error.hpp"
#include "foldkit/layout/edge_numbers.hpp"
#include "test_images.hpp"
#include "test_paths.hpp"

namespace fs = std::filesystem;
using foldkit::OutputError;
using foldkit::Path;
using foldkit::PathRole;
using foldkit::Sheet;
using foldkit::Text;
using foldkit::Vec2;
using foldkit::devices::render_sheets;
using foldkit::devices::RenderOptions;

namespace {

constexpr double kPtPerMm = 72.0 / 25.4;

// A sheet with something of every role at known places, so rasterised output can be probed.
Sheet sample_sheet(Vec2 size_mm) {
  Sheet s;
  s.size_mm = size_mm;
  s.printable_mm.add(Vec2{10, 10});
  s.printable_mm.add(size_mm - Vec2{10, 10});
  s.paths.push_back({PathRole::Cut, {{20, 20}, {100, 20}, {100, 100}, {20, 100}}, true, 0});
  s.paths.push_back({PathRole::Valley, {{20, 20}, {100, 100}}, false, 0});
  s.paths.push_back({PathRole::Mountain, {{100, 20}, {20, 100}}, false, 0});
  s.paths.push_back({PathRole::Tab, {{100, 40}, {106, 44}, {106, 76}, {100, 80}}, true, 0});
  s.paths.push_back({PathRole::Hint, {{120, 120}, {150, 120}}, false});
  Path mark{PathRole::RegMark, {{10, 10}, {15, 10}, {15, 15}, {10, 15}}, true};
  mark.filled = true;
  s.paths.push_back(mark);
  s.paths.push_back(
      {PathRole::RegMark, {{size_mm.x - 30, 10}, {size_mm.x - 10, 10}, {size_mm.x - 10, 30}}, false});
  s.texts.push_back({"17", {40, 60}, 5.0, 0.0, PathRole::Label, 0});
  s.texts.push_back({"3 <&> 'q'", {120, 130}, 4.0, 0.5, PathRole::Hint, -1});
  return s;
}

std::vector<Sheet> two_sheets() {
  return {sample_sheet({210, 297}), sample_sheet({420, 297})};
}

std::string run(const std::string& command) {
  std::string out;
  FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) return out;
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe) != nullptr)
    out += buffer.data();
  ::pclose(pipe);
  return out;
}

bool have(const std::string& tool) {
  return std::system(("command -v " + tool + " >/dev/null 2>&1").c_str()) == 0;
}

using foldkit::test::slurp;

// A binary greyscale PGM (P5, maxval 255) as written by pdftoppm -gray.
struct Gray {
  int width = 0, height = 0;
  std::string pixels;
  int at_mm(double x_mm, double y_mm, double px_per_mm) const {
    const int x = static_cast<int>(x_mm * px_per_mm), y = static_cast<int>(y_mm * px_per_mm);
    return static_cast<unsigned char>(pixels[static_cast<std::size_t>(y) * width + x]);
  }
};

Gray read_pgm(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::string magic;
  int maxval = 0;
  Gray g;
  in >> magic >> g.width >> g.height >> maxval;
  in.get();
  g.pixels.resize(static_cast<std::size_t>(g.width) * g.height);
  in.read(g.pixels.data(), static_cast<std::streamsize>(g.pixels.size()));
  if (magic != "P5" || maxval != 255 || !in) g = {};
  return g;
}

std::array<unsigned, 2> png_dimensions(const fs::path& p) {
  const std::string bytes = slurp(p);
  if (bytes.size() < 24 || bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0) return {0, 0};
  auto be32 = [&](std::size_t at) {
    unsigned v = 0;
    for (std::size_t i = 0; i < 4; ++i)
      v = (v << 8) | static_cast<unsigned char>(bytes[at + i]);
    return v;
  };
  return {be32(16), be32(20)};
}

using foldkit::test::count_entries;

}  // namespace

TEST(RenderPdf, HasOnePagePerSheetWithThePageSizeOfTheSheetInMillimetres) {
  if (!have("pdfinfo")) GTEST_SKIP() << "poppler-utils (pdfinfo) not installed";
  const fs::path pdf = foldkit::test::temp_dir("render") / "model.pdf";
  const auto written = render_sheets(two_sheets(), pdf);
  ASSERT_EQ(written, std::vector<fs::path>{pdf});
  const std::string info = run("pdfinfo -f 1 -l 2 '" + pdf.string() + "'");
  EXPECT_NE(info.find("Pages:           2"), std::string::npos) << info;
  std::smatch m;
  std::regex page_size(R"(Page\s+(\d+) size:\s+([0-9.]+) x ([0-9.]+) pts)");
  std::vector<std::array<double, 2>> sizes_mm;
  for (auto it = std::sregex_iterator(info.begin(), info.end(), page_size); it != std::sregex_iterator();
       ++it) {
    sizes_mm.push_back({std::stod((*it)[2]) / kPtPerMm, std::stod((*it)[3]) / kPtPerMm});
  }
  ASSERT_EQ(sizes_mm.size(), 2u) << info;
  EXPECT_NEAR(sizes_mm[0][0], 210, 0.05);
  EXPECT_NEAR(sizes_mm[0][1], 297, 0.05);
  EXPECT_NEAR(sizes_mm[1][0], 420, 0.05);
  EXPECT_NEAR(sizes_mm[1][1], 297, 0.05);
}

TEST(RenderPdf, EmbedsTheFontOfItsTexts) {
  if (!have("pdffonts")) GTEST_SKIP() << "poppler-utils (pdffonts) not installed";
  const fs::path pdf = foldkit::test::temp_dir("render") / "fonts.pdf";
  render_sheets(two_sheets(), pdf);
  const std::string fonts = run("pdffonts '" + pdf.string() + "'");
  // One line per font after the two header lines; the "emb" column must say yes for every one.
  std::istringstream lines(fonts);
  std::string line;
  int font_lines = 0;
  for (int i = 0; std::getline(lines, line); ++i) {
    if (i < 2 || line.empty()) continue;
    ++font_lines;
    EXPECT_TRUE(std::regex_search(line, std::regex(R"(\s(yes|no)\s+yes\s+(yes|no)\s+\d+\s+\d+\s*$)")))
        << "font not embedded: " << line;
  }
  EXPECT_GE(font_lines, 1) << fonts;
}

TEST(RenderPdf, PutsTextAtItsBaselinePointWithItsCapHeight) {
  if (!have("pdftotext")) GTEST_SKIP() << "poppler-utils (pdftotext) not installed";
  const fs::path pdf = foldkit::test::temp_dir("render") / "text.pdf";
  render_sheets({sample_sheet({210, 297})}, pdf);
  const std::string html = run("pdftotext -bbox -f 1 -l 1 '" + pdf.string() + "' -");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(
      html, m,
      std::regex(
          R"re(<word xMin="([0-9.]+)" yMin="([0-9.]+)" xMax="([0-9.]+)" yMax="([0-9.]+)">17</word>)re")))
      << html;
  const double x_min = std::stod(m[1]) / kPtPerMm, y_min = std::stod(m[2]) / kPtPerMm;
  const double y_max = std::stod(m[4]) / kPtPerMm;
  EXPECT_NEAR(x_min, 40, 0.8) << "text starts at its anchor";
  // poppler's box spans the font's ascent and descent around the 60 mm baseline.
  EXPECT_LT(y_min, 60 - 5.0);
  EXPECT_GT(y_max, 60);
  EXPECT_LT(y_max, 60 + 3.0);
}

namespace {
// Seam labels as the layout sets them: each one word, `width_mm` the length label_width_mm reserves.
const std::vector<std::string> kLabelWords{"12", "9.", "B12.", "MW108", "(3)", "Zp3", "AI47"};
constexpr double kLabelCap_mm = 4;

Sheet label_sheet() {
  Sheet s;
  s.size_mm = {210, 297};
  for (std::size_t i = 0; i < kLabelWords.size(); ++i) {
    Text t{kLabelWords[i], {20, 20 + 12 * static_cast<double>(i)}, kLabelCap_mm, 0, PathRole::Label, 0};
    t.width_mm = foldkit::layout::label_width_mm(t.text, t.height_mm, foldkit::layout::LabelOptions{});
    s.texts.push_back(t);
  }
  return s;
}

// Width in mm of each word pdftotext finds on the first page, by its text.
std::vector<std::pair<std::string, double>> word_widths_mm(const fs::path& pdf) {
  const std::string html = run("pdftotext -bbox -f 1 -l 1 '" + pdf.string() + "' -");
  const std::regex word(
      R"re(<word xMin="([0-9.]+)" yMin="[0-9.]+" xMax="([0-9.]+)" yMax="[0-9.]+">([^<]*)</word>)re");
  std::vector<std::pair<std::string, double>> out;
  for (auto it = std::sregex_iterator(html.begin(), html.end(), word); it != std::sregex_iterator(); ++it)
    out.emplace_back((*it)[3], (std::stod((*it)[2]) - std::stod((*it)[1])) / kPtPerMm);
  return out;
}
}  // namespace

// The layout reserves label_width_mm for a label; in the label family the glyphs take about that, no
// more (a wider font would run into the lines the layout kept it from), and not much less (room wasted).
TEST(RenderPdf, SeamLabelsInTheNarrowFamilyTakeTheLengthTheLayoutReserves) {
  if (!have("pdftotext") || !have("pdffonts")) GTEST_SKIP() << "poppler-utils not installed";
  const fs::path pdf = foldkit::test::temp_dir("render") / "narrow.pdf";
  render_sheets({label_sheet()}, pdf);
  EXPECT_NE(run("pdffonts '" + pdf.string() + "'").find("LiberationSansNarrow"), std::string::npos)
      << "the label family is embedded (Debian fonts-liberation)";
  const auto words = word_widths_mm(pdf);
  ASSERT_EQ(words.size(), kLabelWords.size());
  for (std::size_t i = 0; i < words.size(); ++i) {
    const double reserved = label_sheet().texts[i].width_mm;
    EXPECT_EQ(words[i].first, kLabelWords[i]);
    EXPECT_LE(words[i].second, reserved + 0.05) << words[i].first;
    EXPECT_GE(words[i].second, 0.8 * reserved) << words[i].first;
  }
}

TEST(RenderPdf, ALabelFamilyWiderThanReservedIsSqueezedToTheReservedLength) {
  if (!have("pdftotext")) GTEST_SKIP() << "poppler-utils not installed";
  const fs::path pdf = foldkit::test::temp_dir("render") / "squeezed.pdf";
  RenderOptions wide;
  wide.label_font_family = "DejaVu Sans";  // digits 0.87 of the cap height against 0.70 reserved
  render_sheets({label_sheet()}, pdf, wide);
  const auto words = word_widths_mm(pdf);
  ASSERT_EQ(words.size(), kLabelWords.size());
  for (std::size_t i = 0; i < words.size(); ++i)
    EXPECT_LE(words[i].second, label_sheet().texts[i].width_mm + 0.05) << words[i].first;
}

// On a coloured sheet every text has a white halo; a label 0.3 mm above its edge must not whiten the
// cut line under its halo (the print is what the cutter's lines are checked against).
TEST(RenderPng, TheHaloOfALabelBesideItsEdgeLeavesTheLineVisible) {
  Sheet s;
  s.size_mm = {100, 100};
  s.fills.push_back({{{10, 10}, {90, 10}, {90, 90}, {10, 90}}, foldkit::Colour{0.2, 0.5, 0.2}});
  s.paths.push_back({PathRole::Cut, {{10, 50}, {90, 50}}, false, 0});
  s.texts.push_back({"88888888", {20, 49.7}, 3.0, 0.0, PathRole::Label, 0});
  const fs::path png = foldkit::test::temp_dir("render") / "halo.png";
  RenderOptions o;
  o.png_dpi = 300;
  render_sheets({s}, png, o);
  const foldkit::test::RgbImage image = foldkit::test::read_image(png);
  ASSERT_EQ(image.w, 1181);
  const double px_per_mm = 300 / 25.4;
  const int row = static_cast<int>(std::lround(50 * px_per_mm));
  int whitened = 0, columns = 0;
  for (int x = static_cast<int>(22 * px_per_mm); x < static_cast<int>(38 * px_per_mm); ++x, ++columns) {
    const unsigned char* p = image.px(x, row);
    whitened += p[0] + p[1] + p[2] > 300;
  }
  EXPECT_EQ(whitened, 0) << "of " << columns << " pixels of the cut line under the label";
  int white_in_band = 0;
  for (int y = static_cast<int>(47 * px_per_mm); y < row - 2; ++y)
    for (int x = static_cast<int>(20 * px_per_mm); x < static_cast<int>(38 * px_per_mm); ++x) {
      const unsigned char* p = image.px(x, y);
      white_in_band += p[0] + p[1] + p[2] > 700;
    }
  EXPECT_GT(white_in_band, 100) << "the halo is there, around the digits";
}

// The guide's letters stand on its shaded views: a letter asking for a halo over the paths gets white
// around its glyphs on a dark filled triangle, where without it there is none.
namespace {

Sheet letter_on_a_dark_face(bool halo) {
  Sheet s;
  s.size_mm = {60, 60};
  Path face{PathRole::Piece, {{5, 5}, {55, 5}, {55, 55}, {5, 55}}, true, -1, true, 3};
  face.shade = 0.3;
  s.paths.push_back(face);
  Text letter{"M", {24, 36}, 10.0, 0.0, PathRole::Piece, -1};
  letter.halo_over_paths = halo;
  s.texts.push_back(letter);
  return s;
}

int white_pixels_around_the_letter(const Sheet& sheet, const std::string& name) {
  const fs::path png = foldkit::test::temp_dir("render") / name;
  RenderOptions o;
  o.png_dpi = 150;
  render_sheets({sheet}, png, o);
  const foldkit::test::RgbImage image = foldkit::test::read_image(png);
  const double px_per_mm = 150 / 25.4;
  int white = 0;
  for (int y = static_cast<int>(22 * px_per_mm); y < static_cast<int>(40 * px_per_mm); ++y)
    for (int x = static_cast<int>(20 * px_per_mm); x < static_cast<int>(40 * px_per_mm); ++x) {
      const unsigned char* p = image.px(x, y);
      white += p[0] + p[1] + p[2] > 700;
    }
  return white;
}

}  // namespace

TEST(RenderPng, ALetterAskingForAHaloReadsOnADarkFilledFace) {
  EXPECT_EQ(white_pixels_around_the_letter(letter_on_a_dark_face(false), "dark_plain.png"), 0);
  EXPECT_GT(white_pixels_around_the_letter(letter_on_a_dark_face(true), "dark_halo.png"), 200);
}

TEST(RenderSvg, ALetterAskingForAHaloHasItsWhiteCopyAfterTheFacesItStandsOn) {
  const fs::path svg = foldkit::test::temp_dir("render") / "dark_halo.svg";
  render_sheets({letter_on_a_dark_face(true)}, svg);
  const std::string text = slurp(svg);
  const auto face = text.find("<path d=\"M5 5");
  const auto halo = text.find("stroke=\"#ffffff\"");
  const auto letter = text.find(">M</text>", halo == std::string::npos ? 0 : halo + 1);
  ASSERT_NE(face, std::string::npos);
  ASSERT_NE(halo, std::string::npos);
  ASSERT_NE(letter, std::string::npos);
  EXPECT_LT(face, halo);
  EXPECT_LT(halo, letter);
}

TEST(RenderSvg, ALabelTakesItsReservedLengthWhateverFontTheViewerHas) {
  const fs::path svg = foldkit::test::temp_dir("render") / "narrow.svg";
  render_sheets({label_sheet()}, svg);
  const std::string text = slurp(svg);
  EXPECT_NE(text.find("font-family=\"Liberation Sans Narrow\""), std::string::npos);
  const Sheet sheet = label_sheet();
  const Text& first = sheet.texts.front();
  std::ostringstream length;
  length << "textLength=\"" << first.width_mm << "\" lengthAdjust=\"spacingAndGlyphs\"";
  EXPECT_NE(text.find(length.str()), std::string::npos) << length.str();
}

TEST(RenderPdf, DrawsLinesWhereTheSheetSaysInMillimetres) {
  if (!have("pdftoppm")) GTEST_SKIP() << "poppler-utils (pdftoppm) not installed";
  const fs::path dir = foldkit::test::temp_dir("render");
  render_sheets(two_sheets(), dir / "lines.pdf");
  // 254 dpi = 10 pixels per millimetre.
  const std::string out = run("pdftoppm -r 254 -gray -f 2 -l 2 -singlefile '" + (dir / "lines.pdf").string() +
                              "' '" + (dir / "page2").string() + "'");
  const Gray g = read_pgm(dir / "page2.pgm");
  ASSERT_NEAR(g.width, 4200, 1) << out;  // poppler rounds page sizes up
  ASSERT_NEAR(g.height, 2970, 1) << out;
  EXPECT_LT(g.at_mm(20, 60, 10), 100) << "left cut edge at x = 20 mm";
  EXPECT_LT(g.at_mm(60, 100, 10), 100) << "bottom cut edge at y = 100 mm";
  EXPECT_LT(g.at_mm(12.5, 12.5, 10), 50) << "filled registration square";
  EXPECT_GT(g.at_mm(103, 60, 10), 200) << "tab fill is light";
  EXPECT_LT(g.at_mm(103, 60, 10), 250) << "tab fill is not white";
  EXPECT_EQ(g.at_mm(60, 30, 10), 255) << "blank paper inside the piece";
  EXPECT_EQ(g.at_mm(300, 200, 10), 255) << "blank paper outside";
}

TEST(RenderPdf, DrawsFoldLinesDashed) {
  if (!have("pdftoppm")) GTEST_SKIP() << "poppler-utils (pdftoppm) not installed";
  const fs::path dir = foldkit::test::temp_dir("render");
  Sheet s;
  s.size_mm = {100, 60};
  s.paths.push_back({PathRole::Valley, {{10, 20}, {90, 20}}, false});
  s.paths.push_back({PathRole::Mountain, {{10, 40}, {90, 40}}, false});
  RenderOptions options;
  options.valley.width_mm = options.mountain.width_mm = 0.5;
  render_sheets({s}, dir / "dash.pdf", options);
  run("pdftoppm -r 254 -gray -singlefile '" + (dir / "dash.pdf").string() + "' '" + (dir / "dash").string() +
      "'");
  const Gray g = read_pgm(dir / "dash.pgm");
  ASSERT_NEAR(g.width, 1000, 1);
  for (double y : {20.0, 40.0}) {
    int ink = 0, paper = 0;
    for (double x = 11; x < 89; x += 0.1)
      (g.at_mm(x, y, 10) < 128 ? ink : paper)++;
    EXPECT_GT(ink, 200) << "line at y=" << y << " is drawn";
    EXPECT_GT(paper, 100) << "line at y=" << y << " has gaps";
  }
}

TEST(RenderPng, WritesOneImagePerSheetSizedByTheResolution) {
  const fs::path dir = foldkit::test::temp_dir("render");
  RenderOptions options;
  options.png_dpi = 50;
  const auto written = render_sheets(two_sheets(), dir / "preview.png", options);
  ASSERT_EQ(written, (std::vector<fs::path>{dir / "preview.png", dir / "preview-2.png"}));
  const auto first = png_dimensions(written[0]), second = png_dimensions(written[1]);
  EXPECT_EQ(first[0], static_cast<unsigned>(std::lround(210 / 25.4 * 50)));
  EXPECT_EQ(first[1], static_cast<unsigned>(std::lround(297 / 25.4 * 50)));
  EXPECT_EQ(second[0], static_cast<unsigned>(std::lround(420 / 25.4 * 50)));
  EXPECT_EQ(second[1], first[1]);
  EXPECT_EQ(count_entries(dir), 2);
}

TEST(RenderPng, PixelCountFollowsTheDpiOption) {
  const fs::path dir = foldkit::test::temp_dir("render");
  RenderOptions options;
  options.png_dpi = 100;
  render_sheets({sample_sheet({254, 127})}, dir / "sheet.png", options);
  EXPECT_EQ(png_dimensions(dir / "sheet.png"), (std::array<unsigned, 2>{1000, 500}));
}

TEST(RenderSvg, HasOneGroupPerRoleAndMillimetreDimensions) {
  const fs::path dir = foldkit::test::temp_dir("render");
  const auto written = render_sheets(two_sheets(), dir / "layers.SVG");
  ASSERT_EQ(written.size(), 2u);
  EXPECT_EQ(written[1], dir / "layers-2.SVG");
  const std::string svg = slurp(written[0]);
  EXPECT_NE(svg.find("width=\"210mm\" height=\"297mm\" viewBox=\"0 0 210 297\""), std::string::npos);
  EXPECT_NE(slurp(written[1]).find("width=\"420mm\" height=\"297mm\" viewBox=\"0 0 420 297\""),
            std::string::npos);
  for (const char* id : {"cut", "mountain", "valley", "tab", "label", "hint", "regmark"}) {
    EXPECT_NE(svg.find("<g id=\"" + std::string(id) + "\""), std::string::npos) << id;
  }
  EXPECT_NE(svg.find("M20 20 L100 20 L100 100 L20 100 Z"), std::string::npos) << "cut outline in mm";
  EXPECT_NE(svg.find(">17</text>"), std::string::npos);
  EXPECT_NE(svg.find("3 &lt;&amp;&gt; &apos;q&apos;"), std::string::npos) << "text is escaped";
  EXPECT_NE(svg.find("stroke-dasharray=\"2 1\""), std::string::npos) << "valley dashes";
}

TEST(RenderSvg, PutsEveryPathInTheGroupOfItsRole) {
  const fs::path dir = foldkit::test::temp_dir("render");
  render_sheets({sample_sheet({210, 297})}, dir / "roles.svg");
  const std::string svg = slurp(dir / "roles.svg");
  auto group = [&](const std::string& id) {
    const auto start = svg.find("<g id=\"" + id + "\"");
    return svg.substr(start, svg.find("\n  </g>", start) - start);
  };
  EXPECT_NE(group("valley").find("M20 20 L100 100\""), std::string::npos);
  EXPECT_NE(group("mountain").find("M100 20 L20 100\""), std::string::npos);
  EXPECT_NE(group("tab").find("M100 40 L106 44"), std::string::npos);
  EXPECT_NE(group("regmark").find("M10 10 L15 10 L15 15 L10 15 Z\" fill=\"#000000\""), std::string::npos);
  EXPECT_NE(group("label").find(">17</text>"), std::string::npos);
  EXPECT_NE(group("hint").find("rotate("), std::string::npos);
  EXPECT_EQ(group("cut").find("<text"), std::string::npos);
}

TEST(RenderSvg, IsWellFormedXml) {
  if (!have("xmllint")) GTEST_SKIP() << "xmllint not installed";
  const fs::path dir = foldkit::test::temp_dir("render");
  render_sheets({sample_sheet({210, 297})}, dir / "xml.svg");
  const std::string out = run("xmllint --noout '" + (dir / "xml.svg").string() + "' && echo OK");
  EXPECT_EQ(out, "OK\n");
}

TEST(Render, AnUnknownExtensionIsAnOutputErrorAndWritesNothing) {
  const fs::path dir = foldkit::test::temp_dir("render");
  EXPECT_THROW(render_sheets(two_sheets(), dir / "model.docx"), OutputError);
  EXPECT_THROW(render_sheets(two_sheets(), dir / "model"), OutputError);
  EXPECT_EQ(count_entries(dir), 0);
}

TEST(Render, AMissingDirectoryIsAnOutputErrorNamingTheFile) {
  const fs::path dir = foldkit::test::temp_dir("render");
  const fs::path pdf = dir / "missing" / "model.pdf";
  try {
    render_sheets(two_sheets(), pdf);
    FAIL() << "expected OutputError";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find(pdf.string()), std::string::npos) << e.what();
  }
  EXPECT_EQ(count_entries(dir), 0);
}

TEST(Render, AFailureOnALaterSheetLeavesNoFileOfTheRun) {
  const fs::path dir = foldkit::test::temp_dir("render");
  // The second sheet is too large for a PNG at this resolution, so the run fails after sheet 1 was drawn.
  std::vector<Sheet> sheets = {sample_sheet({210, 297}), sample_sheet({20000, 297})};
  RenderOptions options;
  options.png_dpi = 100;
  try {
    render_sheets(sheets, dir / "big.png", options);
    FAIL() << "expected OutputError";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("big-2.png"), std::string::npos) << e.what();
  }
  EXPECT_EQ(count_entries(dir), 0) << "neither big.png nor a temporary file remains";
}

TEST(Render, ACompanionThatCannotBeDrawnLeavesNoSheetOfTheRunAndKeepsTheOldOnes) {
  const fs::path dir = foldkit::test::temp_dir("render");
  std::ofstream(dir / "m.png") << "old sheet";
  // The guide is too large for a PNG at this resolution: it fails after both sheets were drawn.
  const Sheet guide = sample_sheet({20000, 297});
  RenderOptions options;
  options.png_dpi = 100;
  try {
    render_sheets(two_sheets(), dir / "m.png", options, {&guide, dir / "m-guide.png"});
    FAIL() << "expected OutputError";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("m-guide.png"), std::string::npos) << e.what();
  }
  EXPECT_EQ(count_entries(dir), 1) << "only the old m.png remains";
  EXPECT_EQ(slurp(dir / "m.png"), "old sheet");
}

TEST(Render, ACompanionGoesToItsOwnFileInTheFormatOfTheSheets) {
  const fs::path dir = foldkit::test::temp_dir("render");
  const Sheet guide = sample_sheet({148, 210});
  const auto written = render_sheets(two_sheets(), dir / "m.svg", {}, {&guide, dir / "m-guide.svg"});
  EXPECT_EQ(written, (std::vector<fs::path>{dir / "m.svg", dir / "m-2.svg", dir / "m-guide.svg"}));
  EXPECT_NE(slurp(dir / "m-guide.svg").find("height=\"210mm\""), std::string::npos);
  EXPECT_EQ(count_entries(dir), 3);
}

TEST(Render, NoSheetsIsAnOutputError) {
  const fs::path dir = foldkit::test::temp_dir("render");
  EXPECT_THROW(render_sheets({}, dir / "empty.pdf"), OutputError);
  EXPECT_EQ(count_entries(dir), 0);
}

TEST(Render, ReplacesAnExistingFile) {
  if (!have("pdfinfo")) GTEST_SKIP() << "poppler-utils (pdfinfo) not installed";
  const fs::path pdf = foldkit::test::temp_dir("render") / "again.pdf";
  render_sheets(two_sheets(), pdf);
  render_sheets({sample_sheet({148, 210})}, pdf);
  EXPECT_NE(run("pdfinfo '" + pdf.string() + "'").find("Pages:           1"), std::string::npos);
}

namespace {
// The legend's names in an SVG with where they start, in the order written.
std::vector<std::pair<std::string, Vec2>> legend_names(const std::string& svg) {
  static const std::regex name(
      R"re(<text x="([0-9.]+)" y="([0-9.]+)"[^>]*>(cut|mountain fold|valley fold|glue tab)</text>)re");
  std::vector<std::pair<std::string, Vec2>> names;
  for (std::sregex_iterator it(svg.begin(), svg.end(), name), end; it != end; ++it)
    names.push_back({(*it)[3], Vec2{std::stod((*it)[1]), std::stod((*it)[2])}});
  return names;
}
}  // namespace

TEST(RenderSvg, TheLegendIsStackedInItsBoxOrSideBySideInARow) {
  const fs::path dir = foldkit::test::temp_dir("render");
  Sheet stacked = sample_sheet({210, 297});
  stacked.legend_mm = foldkit::Box2{{150, 250}, {180, 277}};
  Sheet row = stacked;
  row.legend_mm = foldkit::Box2{{10, 3}, {154, 7}};
  row.legend_in_row = true;
  const auto written = render_sheets({stacked, row}, dir / "legend.svg");
  ASSERT_EQ(written.size(), 2u);
  const auto column = legend_names(slurp(written[0]));
  const auto side_by_side = legend_names(slurp(written[1]));
  ASSERT_EQ(column.size(), 4u);
  ASSERT_EQ(side_by_side.size(), 4u);
  for (std::size_t i = 1; i < 4; ++i) {
    EXPECT_EQ(column[i].second.x, column[0].second.x);
    EXPECT_GT(column[i].second.y, column[i - 1].second.y) << column[i].first;
    EXPECT_EQ(side_by_side[i].second.y, side_by_side[0].second.y);
    // A quarter of the row each: room for the longest name after its sample.
    EXPECT_NEAR(side_by_side[i].second.x - side_by_side[i - 1].second.x, 36, 1e-9) << side_by_side[i].first;
  }
  for (const auto& [name, at] : side_by_side)
    EXPECT_TRUE(at.y > 3 && at.y < 7 + 1.5) << name << " stays in the margin row";
}
