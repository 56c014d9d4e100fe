// DXF: the group codes a reader needs (units, layers, polylines at (x, -y)), labels as strokes, one file
// per sheet written all-or-nothing, and an independent reader (ezdxf) agreeing with the SVG of the same
// sheet within 0.01 mm on a real laid-out mesh.
#include "foldkit/devices/dxf.hpp"

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "dxf_reader.hpp"
#include "foldkit/devices/render.hpp"
#include "foldkit/error.hpp"
#include "sample_sheets.hpp"
#include "test_paths.hpp"

namespace fs = std::filesystem;
using namespace foldkit;
using foldkit::devices::dxf_document;
using foldkit::devices::DxfOptions;

namespace {

std::vector<foldkit::test::DxfGroup> parse(const std::string& text) {
  return foldkit::test::dxf_groups(text);
}

const devices::StrokeFont& font() {
  static const devices::StrokeFont f = devices::load_stroke_font(foldkit::test::stroke_font_path());
  return f;
}

using foldkit::test::slurp;

bool have_ezdxf() {
  return std::system((test::debian_python() + " -c 'import ezdxf' >/dev/null 2>&1").c_str()) == 0;
}

std::string text_of(const std::vector<foldkit::test::DxfGroup>& groups) {
  std::string out;
  for (const auto& g : groups)
    out += std::to_string(g.code) + "\n" + g.value + "\n";
  return out;
}

// Runs tests/tools/dxf_vs_svg.py on one sheet's pair: its exit code, and what it printed in `log`.
int check_with_ezdxf(const fs::path& svg, const fs::path& dxf, std::string& log) {
  const fs::path out = dxf.string() + ".log";
  const std::string cmd = test::debian_python() + " " +
                          (test::source_dir() / "tests/tools/dxf_vs_svg.py").string() + " " + svg.string() +
                          " " + dxf.string() + " >" + out.string() + " 2>&1";
  const int status = std::system(cmd.c_str());
  log = slurp(out);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

TEST(Dxf, TheHeaderSaysMillimetresAndSpansThePageWithTheOriginAtTheTopLeft) {
  const Sheet s = test::two_piece_sheet();
  const auto g = parse(dxf_document(s, {&font()}));
  EXPECT_EQ(foldkit::test::dxf_header_value(g, "$ACADVER"), "AC1009");
  EXPECT_EQ(foldkit::test::dxf_header_value(g, "$INSUNITS"), "4");
  EXPECT_EQ(foldkit::test::dxf_header_value(g, "$MEASUREMENT"), "1");
  EXPECT_EQ(foldkit::test::dxf_header_value(g, "$EXTMAX"), std::to_string(static_cast<int>(s.size_mm.x)));
  EXPECT_EQ(g.back().value, "EOF");
}

TEST(Dxf, EveryNamedLayerIsDeclaredEvenWhenEmpty) {
  Sheet s;
  s.size_mm = {210, 297};
  s.paths.push_back(test::rect_path(PathRole::Cut, {10, 10}, {20, 20}));
  const auto layers = foldkit::test::dxf_declared_layers(parse(dxf_document(s, {})));
  EXPECT_EQ(layers, (std::vector<std::string>{"CUT", "MOUNTAIN", "VALLEY", "TAB", "LABEL", "REGMARK"}));
}

TEST(Dxf, PathsBecomePolylinesOnTheirRolesLayerWithYFlipped) {
  const Sheet s = test::two_piece_sheet();
  const auto lines = foldkit::test::dxf_polylines(parse(dxf_document(s, {&font()})));
  std::map<std::string, int> per_layer;
  for (const auto& l : lines)
    ++per_layer[l.layer];
  EXPECT_EQ(per_layer["CUT"], 3);
  EXPECT_EQ(per_layer["MOUNTAIN"], 1);
  EXPECT_EQ(per_layer["VALLEY"], 1);
  EXPECT_EQ(per_layer.count("HINT"), 0u) << "hints are print-only";
  // The first sheet path is the second piece's outline: same points, y negated, closed.
  const Path& first = s.paths[0];
  ASSERT_EQ(lines[0].layer, "CUT");
  ASSERT_EQ(lines[0].points.size(), first.points_mm.size());
  EXPECT_TRUE(lines[0].closed);
  for (std::size_t i = 0; i < first.points_mm.size(); ++i) {
    EXPECT_NEAR(lines[0].points[i].x, first.points_mm[i].x, 1e-4);
    EXPECT_NEAR(lines[0].points[i].y, -first.points_mm[i].y, 1e-4);
  }
}

TEST(Dxf, LabelsAreStrokesWhereTheTextIsPrinted) {
  Sheet s;
  s.size_mm = {100, 100};
  s.texts.push_back({"A1", {40, 60}, 5, 0, PathRole::Label, 0});
  const auto lines = foldkit::test::dxf_polylines(parse(dxf_document(s, {&font()})));
  ASSERT_GE(lines.size(), 3u) << "A is three strokes, 1 at least one";
  for (const auto& l : lines) {
    EXPECT_EQ(l.layer, "LABEL");
    EXPECT_FALSE(l.closed);
    for (Vec2 p : l.points) {
      // Baseline at y = 60 on the sheet: glyphs rise up to 5 mm above it, i.e. DXF y in [-60, -55].
      EXPECT_GE(p.x, 39.0);
      EXPECT_LE(p.x, 40.0 + 2 * 5.0);
      EXPECT_GE(p.y, -60.5);
      EXPECT_LE(p.y, -54.5);
    }
  }
}

TEST(Dxf, PartLettersAndSheetFurnitureAreLabelsAndHintsAreLeftOut) {
  EXPECT_EQ(devices::dxf_layer(PathRole::Piece), "LABEL");
  EXPECT_EQ(devices::dxf_layer(PathRole::Sheet), "LABEL");
  EXPECT_EQ(devices::dxf_layer(PathRole::Hint), "");
  Sheet s;
  s.size_mm = {100, 100};
  s.texts.push_back({"B", {40, 60}, 8, 0, PathRole::Piece, 1});
  s.texts.push_back({"3", {20, 20}, 3, 0, PathRole::Hint, -1});
  const auto g = parse(dxf_document(s, {&font()}));
  const auto lines = foldkit::test::dxf_polylines(g);
  ASSERT_FALSE(lines.empty());
  for (const auto& l : lines)
    EXPECT_EQ(l.layer, "LABEL");
  EXPECT_EQ(foldkit::test::dxf_declared_layers(g).size(), 6u);
}

TEST(Dxf, TextsWithoutAFontAreAnErrorNotSilentlyDropped) {
  const Sheet s = test::two_piece_sheet();
  EXPECT_THROW(dxf_document(s, {}), OutputError);
}

TEST(Dxf, ANonFinitePointIsAnErrorNamingThePath) {
  Sheet s;
  s.size_mm = {100, 100};
  s.paths.push_back(test::line_path(PathRole::Cut, {1, 1}, {std::numeric_limits<double>::quiet_NaN(), 2}));
  try {
    dxf_document(s, {}, "x.dxf");
    FAIL() << "no error";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("cut path 1"), std::string::npos) << e.what();
  }
}

TEST(Dxf, EachSheetGetsItsOwnFileAndAFailureReplacesNone) {
  const fs::path dir = test::temp_dir("dxf-sheets");
  const fs::path target = dir / "model.dxf";
  const std::vector<Sheet> sheets = {test::two_piece_sheet(), test::two_piece_sheet({20, 20})};
  const auto written = devices::write_dxf_sheets(sheets, target, {&font()});
  ASSERT_EQ(written.size(), 2u);
  EXPECT_EQ(written[1], dir / "model-2.dxf");
  const std::string old1 = slurp(written[0]), old2 = slurp(written[1]);
  EXPECT_NE(old1, old2);

  std::vector<Sheet> bad = sheets;
  bad[0].paths.push_back(test::rect_path(PathRole::Cut, {1, 1}, {2, 2}));
  bad[1].size_mm = {0, 0};
  EXPECT_THROW(devices::write_dxf_sheets(bad, target, {&font()}), OutputError);
  EXPECT_EQ(slurp(written[0]), old1) << "sheet 1 replaced although sheet 2 failed";
  EXPECT_EQ(slurp(written[1]), old2);
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir))
    ++entries;
  EXPECT_EQ(entries, 2u) << "temporary files left behind";
}

TEST(Dxf, EzdxfReadsTheSameOutlinesAsTheSvgOnEverySheetOfARealModel) {
  if (std::system((test::debian_python() + " -c 'import ezdxf' >/dev/null 2>&1").c_str()) != 0)
    GTEST_SKIP() << "python3-ezdxf is not installed (bootstrap installs it): DXF not checked by ezdxf";
  const fs::path dir = test::temp_dir("dxf-ezdxf");
  const std::string mesh = test::example_mesh("spot_350.obj").string();
  // Registration marks so that every layer has something on it; 200 mm so the model takes two sheets.
  const std::vector<std::string> common = {"make", mesh, "--size", "200mm", "--regmarks", "-q"};
  for (const char* ext : {".svg", ".dxf"}) {
    auto args = common;
    args.insert(args.end(), {"-o", (dir / (std::string("spot") + ext)).string()});
    const auto run = test::run_foldkit(args);
    ASSERT_EQ(run.exit_code, 0) << run.err;
  }
  int sheets = 0;
  for (std::size_t i = 0;; ++i) {
    const std::string suffix = i == 0 ? "" : "-" + std::to_string(i + 1);
    const fs::path svg = dir / ("spot" + suffix + ".svg"), dxf = dir / ("spot" + suffix + ".dxf");
    if (!fs::exists(svg)) break;
    ASSERT_TRUE(fs::exists(dxf)) << dxf;
    const fs::path log = dir / ("check" + suffix + ".txt");
    const std::string cmd = test::debian_python() + " " +
                            (test::source_dir() / "tests/tools/dxf_vs_svg.py").string() + " " + svg.string() +
                            " " + dxf.string() + " >" + log.string() + " 2>&1";
    EXPECT_EQ(std::system(cmd.c_str()), 0) << slurp(log);
    ++sheets;
  }
  EXPECT_GE(sheets, 2) << "the model was meant to take two sheets";
}

// The independent check must be able to fail: the same sheet's DXF, with one cut corner moved by 0.02 mm,
// the units changed to inches, a label written as TEXT (which a program without the font shows as
// nothing) or the page origin moved, is each reported.
TEST(Dxf, TheEzdxfCheckRejectsADxfThatDiffersFromItsSvg) {
  if (!have_ezdxf()) GTEST_SKIP() << "python3-ezdxf is not installed (bootstrap installs it)";
  const fs::path dir = test::temp_dir("dxf-tamper");
  Sheet s = test::two_piece_sheet();
  test::add_regmarks(s, {10, 5}, {s.size_mm.x - 10, s.size_mm.y - 5});
  devices::RenderOptions svg_options;
  svg_options.format = "svg";
  devices::render_sheets({s}, dir / "sheet.svg", svg_options);
  const auto groups = foldkit::test::dxf_groups(dxf_document(s, {&font()}));
  std::string log;
  {
    std::ofstream(dir / "good.dxf") << text_of(groups);
    ASSERT_EQ(check_with_ezdxf(dir / "sheet.svg", dir / "good.dxf", log), 0) << log;
    EXPECT_NE(log.find(" 0 problems"), std::string::npos) << log;
  }
  auto tampered = [&](const std::string& name, auto change, const std::string& complaint) {
    auto g = groups;
    change(g);
    std::ofstream(dir / name) << text_of(g);
    EXPECT_EQ(check_with_ezdxf(dir / "sheet.svg", dir / name, log), 1) << name << ": " << log;
    EXPECT_NE(log.find(complaint), std::string::npos) << name << ": " << log;
  };
  tampered(
      "moved.dxf",
      [](auto& g) {
        // The first VERTEX's x of the first polyline (a cut outline) by 0.02 mm.
        for (std::size_t i = 0; i + 2 < g.size(); ++i)
          if (g[i].code == 0 && g[i].value == "VERTEX") {
            for (std::size_t j = i + 1; g[j].code != 0; ++j)
              if (g[j].code == 10) {
                g[j].value = std::to_string(std::stod(g[j].value) + 0.02);
                return;
              }
          }
      },
      "cut: path starting at");
  tampered(
      "inches.dxf",
      [](auto& g) {
        for (std::size_t i = 0; i + 1 < g.size(); ++i)
          if (g[i].code == 9 && g[i].value == "$INSUNITS") g[i + 1].value = "1";
      },
      "$INSUNITS is 1");
  tampered(
      "text.dxf",
      [](auto& g) {
        // A TEXT entity just before the end of the ENTITIES section.
        for (std::size_t i = 1; i < g.size(); ++i)
          if (g[i].code == 0 && g[i].value == "ENDSEC" && i > 0) {
            const std::vector<foldkit::test::DxfGroup> text = {
                {0, "TEXT"}, {8, "LABEL"}, {10, "20"}, {20, "-20"}, {30, "0"}, {40, "3"}, {1, "A1"}};
            if (std::any_of(g.begin(), g.begin() + static_cast<long>(i),
                            [](const auto& x) { return x.code == 0 && x.value == "POLYLINE"; })) {
              g.insert(g.begin() + static_cast<long>(i), text.begin(), text.end());
              return;
            }
          }
      },
      "1 TEXT entities");
  tampered(
      "origin.dxf",
      [](auto& g) {
        for (std::size_t i = 0; i + 2 < g.size(); ++i)
          if (g[i].code == 9 && g[i].value == "$EXTMIN") g[i + 2].value = "0";
      },
      "$EXTMIN is");
}
