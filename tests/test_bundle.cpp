// The hand-off bundle: a folder that holds exactly what its README.txt lists (per sheet PDF, PNG at
// 300 dpi, DXF, SVG; per part a transparent PNG), written all-or-nothing, with a smaller bundle
// replacing a larger one without leaving its extra sheets behind, and nothing else in the folder touched.
#include "foldkit/devices/bundle.hpp"

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "dxf_reader.hpp"
#include "foldkit/error.hpp"
#include "sample_sheets.hpp"
#include "test_images.hpp"
#include "test_paths.hpp"

namespace fs = std::filesystem;
using namespace foldkit;

namespace {

using foldkit::test::slurp;

// The file names under the README's FILES heading.
std::set<std::string> readme_files(const fs::path& readme) {
  std::istringstream in(slurp(readme));
  std::set<std::string> names;
  std::string line;
  bool in_files = false;
  while (std::getline(in, line)) {
    if (line == "FILES") {
      in_files = true;
    } else if (in_files) {
      if (line.empty()) break;
      names.insert(line.substr(0, line.find(' ')));
    }
  }
  return names;
}

std::set<std::string> folder_files(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir))
    names.insert(e.path().filename().string());
  return names;
}

// Width, height and colour type from a PNG's IHDR chunk.
struct PngHeader {
  unsigned width = 0, height = 0;
  int colour_type = -1;
};

PngHeader png_header(const fs::path& p) {
  const std::string b = slurp(p);
  PngHeader h;
  if (b.size() < 26 || b.compare(1, 3, "PNG") != 0) return h;
  auto be32 = [&](std::size_t at) {
    return (static_cast<unsigned>(static_cast<unsigned char>(b[at])) << 24) |
           (static_cast<unsigned>(static_cast<unsigned char>(b[at + 1])) << 16) |
           (static_cast<unsigned>(static_cast<unsigned char>(b[at + 2])) << 8) |
           static_cast<unsigned>(static_cast<unsigned char>(b[at + 3]));
  };
  h.width = be32(16);
  h.height = be32(20);
  h.colour_type = static_cast<unsigned char>(b[25]);
  return h;
}

const devices::StrokeFont& font() {
  static const devices::StrokeFont f = devices::load_stroke_font(foldkit::test::stroke_font_path());
  return f;
}

devices::BundleOptions options(const std::string& name) {
  devices::BundleOptions o;
  o.name = name;
  o.font = &font();
  return o;
}

// The share of a print's pixels that are tinted (not white, grey or black): the model's colour.
double tinted_share(const test::RgbImage& img) {
  std::size_t tinted = 0;
  for (std::size_t i = 0; i + 2 < img.rgb.size(); i += 3) {
    const auto [lo, hi] = std::minmax({img.rgb[i], img.rgb[i + 1], img.rgb[i + 2]});
    tinted += hi - lo > 20;
  }
  return img.rgb.empty() ? 0 : static_cast<double>(tinted) / (img.rgb.size() / 3);
}

// A DXF header point's (x, y): the values of codes 10 and 20 after the variable's name.
Vec2 dxf_header_point(const std::vector<test::DxfGroup>& g, const std::string& name) {
  Vec2 p{NAN, NAN};
  for (std::size_t i = 0; i + 2 < g.size(); ++i)
    if (g[i].code == 9 && g[i].value == name) {
      for (std::size_t j = i + 1; j < g.size() && g[j].code != 9; ++j) {
        if (g[j].code == 10) p.x = std::stod(g[j].value);
        if (g[j].code == 20) p.y = std::stod(g[j].value);
      }
      break;
    }
  return p;
}

// The share of points every 0.5 mm along the DXF's CUT polylines, moved by `shift_mm` on the page, that
// fall within a pixel of a dark pixel of the 300 dpi print: the cut lines lying on the printed ones.
double cut_on_print(const std::vector<test::DxfPolyline>& lines, const test::RgbImage& print, Vec2 shift_mm) {
  const double px_per_mm = 300 / 25.4;
  auto dark_near = [&](Vec2 page_mm) {
    const int cx = static_cast<int>(std::lround(page_mm.x * px_per_mm));
    const int cy = static_cast<int>(std::lround(page_mm.y * px_per_mm));
    for (int y = cy - 1; y <= cy + 1; ++y)
      for (int x = cx - 1; x <= cx + 1; ++x)
        if (x >= 0 && y >= 0 && x < print.w && y < print.h &&
            print.px(x, y)[0] + print.px(x, y)[1] + print.px(x, y)[2] < 330)
          return true;
    return false;
  };
  std::size_t on = 0, all = 0;
  for (const test::DxfPolyline& l : lines) {
    if (l.layer != "CUT") continue;
    std::vector<Vec2> pts = l.points;
    if (l.closed) pts.push_back(pts.front());
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
      const Vec2 a{pts[i].x, -pts[i].y}, b{pts[i + 1].x, -pts[i + 1].y};  // DXF y up -> page y down
      const int n = std::max(1, static_cast<int>(norm(b - a) / 0.5));
      for (int k = 0; k < n; ++k) {
        on += dark_near(a + (b - a) * (static_cast<double>(k) / n) + shift_mm);
        ++all;
      }
    }
  }
  return all ? static_cast<double>(on) / all : 0;
}

}  // namespace

TEST(Bundle, HoldsExactlyTheFilesItsReadmeLists) {
  const fs::path dir = test::temp_dir("bundle") / "out";
  const std::vector<Sheet> sheets = {test::two_piece_sheet(), test::two_piece_sheet({20, 20})};
  devices::write_bundle(sheets, dir, options("box"));
  const auto listed = readme_files(dir / "README.txt");
  EXPECT_EQ(folder_files(dir), listed);
  // Per sheet: the print twice, the cut lines twice, one PNG per part (two pieces a sheet).
  for (const char* f :
       {"box-sheet-1.pdf", "box-sheet-1.png", "box-sheet-1.dxf", "box-sheet-1.svg", "box-sheet-1-part-1.png",
        "box-sheet-1-part-2.png", "box-sheet-2.pdf", "box-sheet-2-part-2.png", "README.txt"})
    EXPECT_EQ(listed.count(f), 1u) << f;
  EXPECT_EQ(listed.size(), 2 * 6 + 1u);
}

TEST(Bundle, PartFilesAreNamedByTheLetterPrintedOnThePart) {
  const fs::path dir = test::temp_dir("bundle-letters") / "out";
  Sheet s = test::two_piece_sheet();
  s.texts.push_back({"B", {30, 30}, 6, 0, PathRole::Piece, 0});
  s.texts.push_back({"../x", {80, 30}, 6, 0, PathRole::Piece, 1});  // not a file name: the number stays
  devices::write_bundle({s}, dir, options("box"));
  EXPECT_TRUE(fs::exists(dir / "box-sheet-1-part-B.png"));
  EXPECT_TRUE(fs::exists(dir / "box-sheet-1-part-2.png"));
  EXPECT_NE(slurp(dir / "README.txt").find("part B for Print Then Cut"), std::string::npos);
}

TEST(Bundle, SheetPngsAre300DpiAndPartPngsHaveAnAlphaChannel) {
  const fs::path dir = test::temp_dir("bundle-png") / "out";
  const Sheet s = test::two_piece_sheet();
  devices::write_bundle({s}, dir, options("box"));
  const PngHeader sheet = png_header(dir / "box-sheet-1.png");
  EXPECT_NEAR(sheet.width, s.size_mm.x / 25.4 * 300, 1.0);
  const PngHeader part = png_header(dir / "box-sheet-1-part-1.png");
  EXPECT_EQ(part.colour_type, 6) << "RGBA";
  // 40 x 30 mm piece plus 1 mm of transparent border on each side, at 300 dpi.
  EXPECT_NEAR(part.width, 42 / 25.4 * 300, 1.0);
  EXPECT_NEAR(part.height, 32 / 25.4 * 300, 1.0);
}

TEST(Bundle, PngsSayTheirResolutionSoProgramsOpenThemAtPrintSize) {
  const fs::path dir = test::temp_dir("bundle-dpi") / "out";
  devices::write_bundle({test::two_piece_sheet()}, dir, options("box"));
  for (const char* f : {"box-sheet-1.png", "box-sheet-1-part-1.png"}) {
    const std::string b = slurp(dir / f);
    // pHYs right after IHDR: 300 dpi = 11811 pixels per metre on both axes, unit metre.
    ASSERT_GT(b.size(), 54u);
    EXPECT_EQ(b.substr(37, 4), "pHYs") << f;
    EXPECT_EQ(b.substr(41, 9), std::string("\0\0\x2e\x23\0\0\x2e\x23\x01", 9)) << f;
  }
  // Still a PNG every reader takes (the chunk's CRC is right): the alpha check decodes it.
  if (std::system((test::debian_python() + " -c pass >/dev/null 2>&1").c_str()) == 0) {
    const std::string cmd = test::debian_python() +
                            " -c \"import zlib,struct,sys; b=open(sys.argv[1],'rb').read(); "
                            "l,=struct.unpack('>I',b[33:37]); "
                            "sys.exit(0 if zlib.crc32(b[37:41+l])==struct.unpack('>I',b[41+l:45+l])[0] "
                            "else 1)\" " +
                            (dir / "box-sheet-1.png").string();
    EXPECT_EQ(std::system(cmd.c_str()), 0) << "pHYs CRC";
  }
}

TEST(Bundle, PartPngsAreTransparentOutsideThePieceAndOpaqueInside) {
  const fs::path dir = test::temp_dir("bundle-alpha") / "out";
  if (std::system((test::debian_python() + " -c pass >/dev/null 2>&1").c_str()) != 0)
    GTEST_SKIP() << "python3 is not installed: the part PNG's pixels are not checked";
  devices::write_bundle({test::two_piece_sheet()}, dir, options("box"));
  const fs::path out = dir.parent_path() / "alpha.txt";
  const std::string cmd = test::debian_python() + " " +
                          (test::source_dir() / "tests/tools/png_alpha.py").string() + " " +
                          (dir / "box-sheet-1-part-1.png").string() + " >" + out.string() + " 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << slurp(out);
  const std::string result = slurp(out);
  EXPECT_NE(result.find("corner=0 "), std::string::npos) << result;
  // The 40 x 30 mm piece has a 5 x 5 mm hole; inside its 42 x 32 mm image: (1200 - 25) / 1344 = 0.87.
  const double opaque = std::stod(result.substr(result.find("opaque=") + 7));
  EXPECT_NEAR(opaque, (1200.0 - 25) / (42 * 32), 0.03) << result;
}

TEST(Bundle, ASmallerBundleRemovesTheSheetsOfALargerOneAndNothingElse) {
  const fs::path dir = test::temp_dir("bundle-replace") / "out";
  fs::create_directory(dir);
  std::ofstream(dir / "my-notes.txt") << "mine";
  devices::write_bundle({test::two_piece_sheet(), test::two_piece_sheet({20, 20})}, dir, options("box"));
  devices::write_bundle({test::two_piece_sheet()}, dir, options("box"));
  auto expected = readme_files(dir / "README.txt");
  expected.insert("my-notes.txt");
  EXPECT_EQ(folder_files(dir), expected);
  EXPECT_FALSE(fs::exists(dir / "box-sheet-2.pdf"));
}

TEST(Bundle, AFailureLeavesTheEarlierBundleAsItWas) {
  const fs::path dir = test::temp_dir("bundle-fail") / "out";
  devices::write_bundle({test::two_piece_sheet()}, dir, options("box"));
  const std::string readme = slurp(dir / "README.txt");
  const auto before = folder_files(dir);
  Sheet bad = test::two_piece_sheet();
  bad.paths[0].points_mm[1].x = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(devices::write_bundle({test::two_piece_sheet(), bad}, dir, options("box")), OutputError);
  EXPECT_EQ(folder_files(dir), before);
  EXPECT_EQ(slurp(dir / "README.txt"), readme);
}

TEST(Bundle, TheReadmeNamesEveryProgramAndASourceForItsFigures) {
  const fs::path dir = test::temp_dir("bundle-readme") / "out";
  devices::write_bundle({test::two_piece_sheet()}, dir, options("box"));
  const std::string readme = slurp(dir / "README.txt");
  for (const char* s : {"Silhouette Studio", "Cricut Design Space", "CanvasWorkspace", "Print Then Cut",
                        "box-sheet-1.dxf", "no source found", "[1] ", "[5] "})
    EXPECT_NE(readme.find(s), std::string::npos) << s;
}

TEST(Bundle, MakeWritesTheBundleOfATwoSheetModel) {
  const fs::path dir = test::temp_dir("bundle-cli") / "fish";
  // 190 mm: fish_350 takes two A4 sheets (one from 150 to 200 mm when this was written).
  const auto run = test::run_foldkit({"make", test::example_mesh("fish_350.obj").string(), "--size", "190mm",
                                      "--bundle", dir.string(), "--json", "-q"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto report = nlohmann::json::parse(run.out);
  const int sheets = report["sheet_count"];
  ASSERT_GE(sheets, 2);
  const auto listed = readme_files(dir / "README.txt");
  EXPECT_EQ(folder_files(dir), listed);
  EXPECT_EQ(listed.count("fish_350-sheet-" + std::to_string(sheets + 1) + ".pdf"), 0u);
  EXPECT_EQ(listed.count("fish_350-guide.pdf"), 1u) << "the assembly guide goes with the bundle";
  for (int sheet = 1; sheet <= sheets; ++sheet) {
    const std::string stem = "fish_350-sheet-" + std::to_string(sheet);
    for (const char* ext : {".pdf", ".png", ".dxf", ".svg"})
      EXPECT_EQ(listed.count(stem + ext), 1u) << stem << ext;
    EXPECT_TRUE(std::any_of(listed.begin(), listed.end(),
                            [&](const std::string& f) { return f.rfind(stem + "-part-", 0) == 0; }))
        << "no part PNG for sheet " << sheet;
  }
  EXPECT_EQ(png_header(dir / "fish_350-sheet-1.png").width, 2480u) << "A4 at 300 dpi";
  EXPECT_LT(tinted_share(test::read_image(dir / "fish_350-sheet-1.png")), 0.05)
      << "a model without colour prints without colour (but for the fold lines)";
}

// A real two-sheet bundle of a textured model, checked as a cutting program would use it: every file of
// a sheet on the same A4 page (PNG 2480 x 3508 px, PDF MediaBox, SVG size, DXF extents from the paper's
// top-left corner), the print in the model's colours, the DXF's cut lines on the print's cut lines (and
// not 1 mm beside them), the SVG the DXF's lines (ezdxf), and one RGBA PNG for each part on the sheet.
TEST(Bundle, ATexturedTwoSheetBundleHasOnePageInColourWithTheCutLinesOnThePrint) {
  const fs::path dir = test::temp_dir("bundle-spot") / "spot";
  const fs::path mesh = test::source_dir() / "examples/spot_textured/spot_triangulated.obj";
  const auto run = test::run_foldkit({"make", mesh.string(), "--max-faces", "200", "--size", "150mm",
                                      "--bundle", dir.string(), "--json", "-q"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto report = nlohmann::json::parse(run.out);
  ASSERT_EQ(report["sheet_count"], 2) << "the mesh was meant to take two sheets";
  EXPECT_EQ(folder_files(dir), readme_files(dir / "README.txt"));
  const bool ezdxf = std::system((test::debian_python() + " -c 'import ezdxf' >/dev/null 2>&1").c_str()) == 0;
  const std::regex svg_size(R"(width="([0-9.]+)mm" height="([0-9.]+)mm")");
  const std::regex media_box(R"(/MediaBox \[ *0 +0 +([0-9.]+) +([0-9.]+) *\])");
  const double pt_per_mm = 72 / 25.4;
  for (int sheet = 1; sheet <= 2; ++sheet) {
    SCOPED_TRACE("sheet " + std::to_string(sheet));
    const std::string stem = "spot_triangulated-sheet-" + std::to_string(sheet);
    const auto dxf = test::dxf_groups(slurp(dir / (stem + ".dxf")));
    EXPECT_EQ(dxf_header_point(dxf, "$EXTMIN"), (Vec2{0, -297}));
    EXPECT_EQ(dxf_header_point(dxf, "$EXTMAX"), (Vec2{210, 0}));
    std::smatch m;
    const std::string svg = slurp(dir / (stem + ".svg"));
    ASSERT_TRUE(std::regex_search(svg, m, svg_size));
    EXPECT_EQ(std::stod(m[1]), 210);
    EXPECT_EQ(std::stod(m[2]), 297);
    const std::string pdf = slurp(dir / (stem + ".pdf"));
    ASSERT_TRUE(std::regex_search(pdf, m, media_box));
    EXPECT_NEAR(std::stod(m[1]), 210 * pt_per_mm, 0.01);
    EXPECT_NEAR(std::stod(m[2]), 297 * pt_per_mm, 0.01);
    const test::RgbImage print = test::read_image(dir / (stem + ".png"));
    ASSERT_EQ(print.w, 2480);
    ASSERT_EQ(print.h, 3508);
    EXPECT_GT(tinted_share(print), 0.15) << "the texture's colours are printed";

    const auto lines = test::dxf_polylines(dxf);
    EXPECT_GT(cut_on_print(lines, print, {0, 0}), 0.93);
    EXPECT_LT(cut_on_print(lines, print, {1, 0}), 0.6) << "the check sees a cut line 1 mm off its print";
    EXPECT_LT(cut_on_print(lines, print, {0, 1}), 0.6);

    std::size_t parts = 0, part_files = 0;
    for (const auto& part : report["parts"])
      parts += part["sheet"] == sheet;
    for (const auto& e : fs::directory_iterator(dir)) {
      const std::string f = e.path().filename().string();
      if (f.rfind(stem + "-part-", 0) != 0) continue;
      ++part_files;
      EXPECT_EQ(png_header(e.path()).colour_type, 6) << f << ": RGBA, transparent around the part";
    }
    EXPECT_EQ(part_files, parts);
    if (ezdxf) {
      const fs::path log = dir.parent_path() / (stem + ".log");
      const std::string cmd = test::debian_python() + " " +
                              (test::source_dir() / "tests/tools/dxf_vs_svg.py").string() + " " +
                              (dir / (stem + ".svg")).string() + " " + (dir / (stem + ".dxf")).string() +
                              " >" + log.string() + " 2>&1";
      EXPECT_EQ(std::system(cmd.c_str()), 0) << slurp(log);
    }
  }
}

TEST(Bundle, MakeWithoutOutputOrBundleIsAUsageError) {
  const auto run = test::run_foldkit({"make", test::example_mesh("spot_128.obj").string(), "-q"});
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_NE(run.err.find("--bundle"), std::string::npos) << run.err;
}

TEST(Bundle, AHandEditedReadmeNeverMakesItDeleteOtherFiles) {
  const fs::path dir = test::temp_dir("bundle-edited") / "out";
  devices::write_bundle({test::two_piece_sheet()}, dir, options("box"));
  std::ofstream(dir / "my-notes.txt") << "mine";
  std::ofstream(dir.parent_path() / "outside.pdf") << "mine";
  {
    std::ofstream readme(dir / "README.txt");
    readme << "FILES\nmy-notes.txt  x\n../outside.pdf  x\nbox-sheet-9.txt  x\n\n";
  }
  devices::write_bundle({test::two_piece_sheet()}, dir, options("box"));
  EXPECT_TRUE(fs::exists(dir / "my-notes.txt"));
  EXPECT_TRUE(fs::exists(dir.parent_path() / "outside.pdf"));
}

TEST(Bundle, PaperTooLargeForA300DpiPrintIsRefusedBeforeAnythingIsWritten) {
  const fs::path dir = test::temp_dir("bundle-huge") / "out";
  Sheet huge = test::two_piece_sheet();
  huge.size_mm = {5000, 5000};
  EXPECT_THROW(devices::write_bundle({huge}, dir, options("box")), OutputError);
  EXPECT_FALSE(fs::exists(dir));
}

TEST(Bundle, AFailedFirstBundleLeavesNoFolderBehind) {
  const fs::path dir = test::temp_dir("bundle-first-fail") / "out";
  Sheet bad = test::two_piece_sheet();
  bad.paths[0].points_mm[1].x = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(devices::write_bundle({test::two_piece_sheet(), bad}, dir, options("box")), OutputError);
  EXPECT_FALSE(fs::exists(dir));
}

TEST(Bundle, MakeRefusesPaperTooLargeForTheBundleBeforeTheWork) {
  const fs::path dir = test::temp_dir("bundle-cli-huge");
  // The 5,856-face cow would take a minute to unfold: the refusal comes before.
  const auto run = test::run_foldkit(
      {"make", (test::source_dir() / "examples/spot_textured/spot_triangulated.obj").string(), "--paper",
       "2000x2000mm", "--bundle", (dir / "out").string(), "-q"});
  EXPECT_NE(run.exit_code, 0);
  EXPECT_NE(run.err.find("too large for a 300 dpi print"), std::string::npos) << run.err;
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

// 9.25 x 6.75 in (235 x 171 mm) is what Print Then Cut takes: a part beyond it, in both orientations,
// is marked in the README; one that fits turned is not.
TEST(Bundle, TheReadmeMarksPartsLargerThanPrintThenCutsArea) {
  const fs::path dir = test::temp_dir("bundle-ptc") / "out";
  Sheet s;
  s.size_mm = {420, 297};
  s.paths.push_back(test::rect_path(PathRole::Cut, {10, 10}, {190, 185}, 0));   // 180 x 175: too wide
  s.paths.push_back(test::rect_path(PathRole::Cut, {200, 10}, {370, 240}, 1));  // 170 x 230: fits
  devices::write_bundle({s}, dir, options("big"));
  std::istringstream readme(slurp(dir / "README.txt"));
  std::string line, part1, part2;
  while (std::getline(readme, line)) {
    if (line.rfind("big-sheet-1-part-1.png", 0) == 0) part1 = line;
    if (line.rfind("big-sheet-1-part-2.png", 0) == 0) part2 = line;
  }
  EXPECT_NE(part1.find("larger than Print Then Cut"), std::string::npos) << part1;
  EXPECT_EQ(part2.find("larger than Print Then Cut"), std::string::npos) << part2;
  EXPECT_FALSE(part2.empty());
}

// What foldkit's own commands add to a bundle is said at the top of its README: whether the sheets
// carry registration marks for `foldkit cut --regmarks`.
TEST(Bundle, TheReadmeSaysWhetherTheSheetsCarryRegistrationMarks) {
  const fs::path dir = test::temp_dir("bundle-marks");
  const std::string mesh = test::example_mesh("spot_128.obj").string();
  for (const bool marks : {true, false}) {
    std::vector<std::string> args = {
        "make", mesh, "--size", "80mm", "--bundle", (dir / (marks ? "m" : "n")).string(), "-q"};
    // The guide goes with the bundle unless --no-guide.
    args.push_back(marks ? "--regmarks" : "--no-guide");
    const auto run = test::run_foldkit(args);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(fs::exists(dir / (marks ? "m" : "n") / "spot_128-guide.pdf"), marks);
    const std::string readme = slurp(dir / (marks ? "m" : "n") / "README.txt");
    const std::string head = readme.substr(0, readme.find("FILES"));
    EXPECT_NE(head.find(marks ? "the sheets carry Silhouette marks" : "none of foldkit's"), std::string::npos)
        << head;
  }
}

TEST(Bundle, TheAssemblyGuideIsListedAndGoesWhenABundleWithoutItReplacesIt) {
  const fs::path dir = test::temp_dir("bundle-guide") / "out";
  const Sheet guide = test::two_piece_sheet();
  devices::BundleOptions with = options("box");
  with.guide = &guide;
  devices::write_bundle({test::two_piece_sheet()}, dir, with);
  EXPECT_EQ(readme_files(dir / "README.txt").count("box-guide.pdf"), 1u);
  EXPECT_EQ(slurp(dir / "box-guide.pdf").rfind("%PDF", 0), 0u);
  EXPECT_EQ(folder_files(dir), readme_files(dir / "README.txt"));
  devices::write_bundle({test::two_piece_sheet()}, dir, options("box"));
  EXPECT_FALSE(fs::exists(dir / "box-guide.pdf"));
  EXPECT_EQ(folder_files(dir), readme_files(dir / "README.txt"));
}
