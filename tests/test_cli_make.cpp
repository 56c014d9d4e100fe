// `foldkit make`: the README's main job end to end. PDF pages readable by poppler, PNG previews at the
// asked resolution, SVG layers by role, the --json report, and one-line errors for bad requests.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "foldkit/layout/label_text.hpp"
#include "test_paths.hpp"

using namespace foldkit;
namespace fs = std::filesystem;

namespace {

using foldkit::test::slurp;

bool have(const char* tool) {
  return std::system((std::string("command -v ") + tool + " >/dev/null 2>&1").c_str()) == 0;
}

// Output of a shell command (only used with paths this test made).
std::string shell(const std::string& cmd) {
  const fs::path out = test::temp_dir("shell") / "out";
  const int rc = std::system((cmd + " >" + out.string() + " 2>&1").c_str());
  return (rc == 0 ? "" : "FAILED ") + slurp(out);
}

std::size_t count_lines(const std::string& s) {
  std::size_t n = 0;
  for (char c : s)
    n += c == '\n';
  return n;
}

}  // namespace

TEST(CliMake, TheReadmeCommandWritesAPdfThatPopplerReads) {
  if (!have("pdfinfo") || !have("pdftoppm"))
    GTEST_SKIP() << "poppler-utils (pdfinfo, pdftoppm) not installed";
  const fs::path dir = test::temp_dir("make-pdf");
  const fs::path pdf = dir / "spot.pdf";
  auto run = test::run_foldkit(
      {"make", test::example_mesh("spot_350.obj").string(), "--size", "160mm", "-o", pdf.string(), "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto report = nlohmann::json::parse(run.out);
  const int sheets = report["sheet_count"];
  ASSERT_GE(sheets, 1);
  const std::string info = shell("pdfinfo " + pdf.string());
  ASSERT_EQ(report["guide_page_count"].get<int>(), 1);
  EXPECT_NE(info.find("Pages:           " + std::to_string(sheets + 1)), std::string::npos) << info;
  EXPECT_NE(info.find("595.276 x 841.89 pts (A4)"), std::string::npos) << info;
  const std::string raster = shell("pdftoppm -r 20 -png " + pdf.string() + " " + (dir / "page").string());
  EXPECT_EQ(raster.rfind("FAILED", 0), std::string::npos) << raster;
  EXPECT_TRUE(fs::exists(dir / "page-1.png"));
  EXPECT_NEAR(report["size_mm"].get<double>(), 160, 1e-9);
  // Every page says which sheet it is and carries the scale check; the file asks viewers not to scale.
  for (int page = 1; page <= sheets + 1; ++page) {
    const std::string text = shell("pdftotext -f " + std::to_string(page) + " -l " + std::to_string(page) +
                                   " " + pdf.string() + " -");
    const int k = std::min(page, sheets);  // the guide, last, says it follows the last sheet
    EXPECT_NE(text.find(std::to_string(k) + "/" + std::to_string(sheets)), std::string::npos) << text;
    EXPECT_NE(text.find("spot_350"), std::string::npos) << text;
    EXPECT_NE(text.find("50 mm"), std::string::npos) << "page " << page;
  }
  EXPECT_NE(slurp(pdf).find("/ViewerPreferences << /PrintScaling /None >>"), std::string::npos);
  if (have("qpdf")) {
    const std::string check = shell("qpdf --check " + pdf.string() + " 2>&1");
    EXPECT_NE(check.find("No syntax or stream encoding errors"), std::string::npos) << check;
  }
}

TEST(CliMake, JsonReportsCoverageTabsAndLabelsPerSheetAndOverall) {
  const fs::path dir = test::temp_dir("make-json");
  // 8 s in a release build; under the sanitizers on a busy machine it once took more than the default
  // 60 s the command allows itself. The time limit is not what this test is about.
  auto run = test::run_foldkit({"make", test::example_mesh("bob_350.obj").string(), "--size", "120mm",
                                "--paper", "A5", "--landscape", "-o", (dir / "bob.pdf").string(), "--json",
                                "--hints", "--time-limit", "600"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto j = nlohmann::json::parse(run.out);
  EXPECT_DOUBLE_EQ(j["paper_mm"][0].get<double>(), 210);
  EXPECT_DOUBLE_EQ(j["paper_mm"][1].get<double>(), 148);
  ASSERT_EQ(j["sheets"].size(), j["sheet_count"].get<std::size_t>());
  int pieces = 0, tabs = 0, dropped = 0, split = 0;
  for (const auto& s : j["sheets"]) {
    // A sheet may hold only the glue-order list; one with pieces has some coverage.
    EXPECT_EQ(s["coverage"].get<double>() > 0, s["piece_count"].get<int>() > 0);
    EXPECT_LT(s["coverage"].get<double>(), 1);
    pieces += s["piece_count"].get<int>();
    tabs += s["tab_count"].get<int>();
    dropped += s["dropped_tab_count"].get<int>();
    split += s["split_tab_count"].get<int>();
  }
  EXPECT_EQ(pieces, j["piece_count"].get<int>());
  EXPECT_EQ(tabs, j["overall"]["tab_count"].get<int>());
  // A split tab's two halves count as two tabs of one seam.
  EXPECT_EQ(tabs - split + dropped, j["seam_count"].get<int>());
  EXPECT_GE(j["overall"]["min_label_mm"].get<double>(), 1.8 - 1e-9);
  EXPECT_EQ(j["assembly_steps"].size(), j["seam_count"].get<std::size_t>());
}

TEST(CliMake, JsonListsThePartsWithTheirSheetsAndFacesAndTheLabelCounts) {
  const fs::path dir = test::temp_dir("make-json-parts");
  auto run = test::run_foldkit({"make", test::example_mesh("spot_350.obj").string(), "--size", "150mm", "-o",
                                (dir / "spot.pdf").string(), "--json", "--hints"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto j = nlohmann::json::parse(run.out);
  ASSERT_EQ(j["parts"].size(), j["piece_count"].get<std::size_t>());
  std::vector<int> faces;
  int rank = 0;
  for (const auto& part : j["parts"]) {
    EXPECT_EQ(part["id"].get<std::string>(), layout::piece_letter(rank++)) << "parts in letter order";
    EXPECT_GE(part["sheet"].get<int>(), 1);
    EXPECT_LE(part["sheet"].get<int>(), j["sheet_count"].get<int>());
    for (int f : part["faces"])
      faces.push_back(f);
  }
  std::sort(faces.begin(), faces.end());
  ASSERT_EQ(static_cast<int>(faces.size()), j["face_count"].get<int>()) << "every face in exactly one part";
  for (std::size_t i = 0; i < faces.size(); ++i)
    ASSERT_EQ(faces[i], static_cast<int>(i));
  for (const char* key : {"labels_crossing_lines_count", "labels_touching_count", "labels_turned_count"})
    EXPECT_GE(j[key].get<int>(), 0) << key;
  EXPECT_EQ(j["labels_turned_count"].get<int>(), 0);
  // Notes are single lines; seam lists go to JSON fields.
  for (const auto& note : j["notes"])
    EXPECT_LT(note.get<std::string>().size(), 300u) << note;
  EXPECT_EQ(j["dropped_tab_seams"].size(), j["overall"]["dropped_tab_count"].get<std::size_t>());
}

// A maker told that labels lack room must be able to find them: each is listed with its part and sheet.
TEST(CliMake, JsonListsEveryLabelWithoutRoomWithItsPartAndSheet) {
  const fs::path dir = test::temp_dir("make-json-crowded");
  auto run = test::run_foldkit({"make", test::example_mesh("spot_350.obj").string(), "--size", "90mm", "-o",
                                (dir / "spot.svg").string(), "--json", "--no-guide"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto j = nlohmann::json::parse(run.out);
  const auto& listed = j["crowded_labels"];
  ASSERT_EQ(listed.size(), j["labels_without_room_count"].get<std::size_t>());
  ASSERT_GT(listed.size(), 0u) << "spot at 90 mm has faces too small for some labels";
  std::map<std::string, int> sheet_of_part;
  for (const auto& part : j["parts"])
    sheet_of_part[part["id"].get<std::string>()] = part["sheet"].get<int>();
  for (const auto& label : listed) {
    const std::string part = label["part"].get<std::string>();
    ASSERT_TRUE(sheet_of_part.count(part)) << part;
    EXPECT_EQ(label["sheet"].get<int>(), sheet_of_part[part]);
    const std::string text = label["text"].get<std::string>(), name = label["seam_name"].get<std::string>();
    const auto digits = text.find_first_of("0123456789");
    ASSERT_NE(digits, std::string::npos) << text;
    const std::string number = text.substr(digits, text.find_first_not_of("0123456789.", digits) - digits);
    EXPECT_NE(name.find(number), std::string::npos) << text << " is seam " << name;
    EXPECT_NE(name.find(part), std::string::npos) << "seam " << name << " touches part " << part;
  }
}

TEST(CliMake, PngPreviewsHaveThePixelSizeOfTheDpi) {
  const fs::path dir = test::temp_dir("make-png");
  const fs::path png = dir / "fish.png";
  auto run = test::run_foldkit({"make", test::example_mesh("fish_350.obj").string(), "--fit", "-o",
                                png.string(), "--dpi", "50", "-q"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string bytes = slurp(png);
  ASSERT_GT(bytes.size(), 24u);
  ASSERT_EQ(bytes.substr(1, 3), "PNG");
  auto be32 = [&](std::size_t at) {
    return (std::uint32_t(std::uint8_t(bytes[at])) << 24) |
           (std::uint32_t(std::uint8_t(bytes[at + 1])) << 16) |
           (std::uint32_t(std::uint8_t(bytes[at + 2])) << 8) | std::uint32_t(std::uint8_t(bytes[at + 3]));
  };
  // A4 at 50 dpi: 210 mm and 297 mm in pixels.
  EXPECT_NEAR(be32(16), 210 / 25.4 * 50, 1.0);
  EXPECT_NEAR(be32(20), 297 / 25.4 * 50, 1.0);
  EXPECT_FALSE(fs::exists(dir / "fish-2.png")) << "--fit puts the model on one sheet";
}

TEST(CliMake, SvgHasOneLayerPerRole) {
  const fs::path dir = test::temp_dir("make-svg");
  const fs::path svg = dir / "spot.svg";
  auto run = test::run_foldkit({"make", test::example_mesh("spot_128.obj").string(), "--size", "120mm", "-o",
                                svg.string(), "--regmarks", "--arrows", "--hints", "-q"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string text = slurp(svg);
  for (const char* id : {"cut", "mountain", "valley", "tab", "label", "hint", "regmark", "piece", "sheet"})
    EXPECT_NE(text.find(std::string("id=\"") + id + "\""), std::string::npos) << id;
  EXPECT_NE(text.find("width=\"210mm\""), std::string::npos);
}

TEST(CliMake, BadRequestsAreOneLineErrorsWithTheirExitCodes) {
  const fs::path dir = test::temp_dir("make-bad");
  const std::string mesh = test::example_mesh("spot_128.obj").string();
  const std::string out = (dir / "x.pdf").string();
  struct Case {
    std::vector<std::string> args;
    int exit_code;
    std::string says;
  };
  const std::vector<Case> cases = {
      {{"make", mesh, "-o", out, "--paper", "B7"}, 2, "unknown paper"},
      {{"make", mesh, "-o", out, "--size", "-3mm"}, 2, "must be between 1 mm and 10000 mm"},
      {{"make", mesh, "-o", out, "--size", "12parsecs"}, 2, "expected a length such as 5mm"},
      {{"make", mesh, "-o", (dir / "x.doc").string()}, 2, ".pdf, .svg, .png or .dxf"},
      {{"make", mesh, "-o", out, "--size", "5m"}, 2, "expected a length such as 5mm"},
      // Refusals once the mesh is read name it, so that a script running many files learns which one.
      {{"make", mesh, "-o", out, "--size", "4000mm"}, 5, mesh + ": --size 4000 mm: "},
      {{"make", mesh, "-o", out, "--size", "4000mm"}, 5, "largest --size that fits"},
      {{"make", mesh, "-o", out, "--size", "300mm", "--no-split"}, 5, mesh + ": piece 1 does not fit"},
      {{"make", mesh, "-o", out, "--size", "300mm", "--no-split"}, 5, "largest --size that fits"},
      {{"make", (dir / "missing.obj").string(), "-o", out}, 3, "missing.obj"},
      // Margins that leave a sliver: --fit scaled the model to 0 mm and wrote an empty sheet.
      {{"make", mesh, "-o", out, "--margin", "100mm"},
       5,
       "no room for a part in the 10x97 mm printable area"},
      {{"make", mesh, "-o", out, "--paper", "30x30mm", "--size", "50mm"}, 5, "no room for a part"},
      {{"make", mesh, "-o", out, "--regmarks", "--regmark-inset", "50mm", "--regmark-arm", "100mm"},
       5,
       "clear of the registration marks"},
      {{"unfold", mesh, "-o", (dir / "x.obj").string(), "--margin", "100mm", "--size", "50mm"},
       5,
       "no room for a part"},
  };
  for (const Case& c : cases) {
    auto run = test::run_foldkit(c.args);
    EXPECT_FALSE(run.signalled);
    EXPECT_EQ(run.exit_code, c.exit_code) << c.args.back() << ": " << run.err;
    EXPECT_NE(run.err.find(c.says), std::string::npos) << run.err;
    EXPECT_LE(count_lines(run.err), 2u) << run.err;
  }
  EXPECT_FALSE(fs::exists(out)) << "no output file after an error";
}

TEST(CliMake, SheetsSetByTheFacesShapesRatherThanTheirAreaAreExplained) {
  const fs::path dir = test::temp_dir("make-shape-bound");
  const auto notes_of = [&](const char* name, const char* size) {
    const fs::path mesh = test::source_dir() / "tests" / "data" / "lowpoly" / name;
    auto run = test::run_foldkit(
        {"make", mesh.string(), "--size", size, "-o", (dir / "m.svg").string(), "--no-guide", "--json"});
    EXPECT_EQ(run.exit_code, 0) << name << ": " << run.err;
    const auto j = nlohmann::json::parse(run.out);
    std::string notes;
    for (const auto& n : j["notes"])
      notes += n.get<std::string>() + "\n";
    return std::pair(j["sheet_count"].get<int>(), notes);
  };
  // 18 squares 104 mm a side go two to an A4 sheet: 9 sheets, where their area would fit 5.
  const auto [sheets, notes] = notes_of("rhombicuboctahedron.obj", "250mm");
  EXPECT_EQ(sheets, 9);
  EXPECT_NE(
      notes.find("9 sheets, the fewest that faces this large allow at 250 mm on 210x297 mm paper (their "
                 "area alone would fill 5): a smaller --size or a larger --paper takes fewer"),
      std::string::npos)
      << notes;
  // Where the area sets the count, nothing to explain.
  const auto [l_sheets, l_notes] = notes_of("l_block.obj", "150mm");
  EXPECT_EQ(l_sheets, 2);
  EXPECT_EQ(l_notes.find("the fewest that faces"), std::string::npos) << l_notes;
}

TEST(CliMake, NoInputFaceOfALowPolyModelIsSplitAcrossParts) {
  const fs::path dir = test::temp_dir("make-lowpoly-parts");
  for (const char* name : {"barn.obj", "drum.obj", "football.obj", "l_block.obj", "rhombicuboctahedron.obj",
                           "cube.obj", "cylinder12.obj", "dodecahedron.obj"})
    for (const char* size : {"150mm", "250mm"}) {
      const fs::path mesh = test::source_dir() / "tests" / "data" / "lowpoly" / name;
      // The parts are what is checked: SVG without the guide is the cheapest output that has them.
      auto run = test::run_foldkit(
          {"make", mesh.string(), "--size", size, "-o", (dir / "m.svg").string(), "--no-guide", "--json"});
      if (run.exit_code == 5) {
        // A face larger than A4 at this size (the drum's octagons are 231 mm across at 250 mm): refused,
        // never cut.
        EXPECT_NE(run.err.find(mesh.string() + ": a flat face"), std::string::npos) << run.err;
        EXPECT_NE(run.err.find("the largest --size that fits is"), std::string::npos) << run.err;
        continue;
      }
      ASSERT_EQ(run.exit_code, 0) << name << " " << size << ": " << run.err;
      const auto j = nlohmann::json::parse(run.out);
      std::vector<int> faces;
      for (const auto& part : j["parts"])
        for (int f : part["faces"])
          faces.push_back(f);
      std::sort(faces.begin(), faces.end());
      for (std::size_t i = 0; i < faces.size(); ++i)
        ASSERT_EQ(faces[i], static_cast<int>(i)) << name << " at " << size << ": face in two parts or none";
    }
}

TEST(CliMake, EveryLengthTakesUnits) {
  const fs::path dir = test::temp_dir("make-units");
  const auto run = test::run_foldkit({"make", test::example_mesh("spot_128.obj").string(), "-o",
                                      (dir / "x.svg").string(), "-q", "--json", "--margin", "1cm",
                                      "--tab-width", "0.2in", "--spacing", "2mm", "--size", "10cm"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto report = nlohmann::json::parse(run.out);
  EXPECT_NEAR(report["size_mm"].get<double>(), 100, 1e-9);
}

TEST(CliMake, OutOfRangeLengthsAreRefusedWithReadableBoundsBeforeAnyWork) {
  // Each of these took gigabytes or ended in "internal error" (issue 10): --size 1e9mm was killed at
  // 24 GB, 100000mm took 3.4 GB before its refusal, 1e300mm and a 1e9 mm paper overflowed the packer.
  const fs::path dir = test::temp_dir("make-range");
  const std::string mesh = test::example_mesh("spot_128.obj").string();
  const std::string out = (dir / "x.pdf").string();
  struct Case {
    std::vector<std::string> args;
    std::string says;
  };
  const std::vector<Case> cases = {
      {{"--size", "1e9mm"}, "--size: '1e9mm': must be between 1 mm and 10000 mm"},
      {{"--size", "100000mm"}, "must be between 1 mm and 10000 mm"},
      {{"--size", "1e300mm"}, "must be between 1 mm and 10000 mm"},
      {{"--size", "1e9mm", "--no-split"}, "must be between 1 mm and 10000 mm"},
      {{"--paper", "1e9x1e9mm"}, "--paper: '1e9x1e9mm': each side must be between 10 mm and 3000 mm"},
      {{"--margin", "1e300mm"}, "--margin: '1e300mm': must be between 0 mm and 200 mm"},
      {{"--tab-width", "2in"}, "--tab-width: '2in': must be between 0.5 mm and 50 mm"},
      {{"--spacing", "-1cm"}, "must be between 0 mm and 50 mm"},
      {{"--regmark-arm", "1e300"}, "--regmark-arm: '1e300': must be between 1 mm and 100 mm"},
  };
  for (const Case& c : cases) {
    std::vector<std::string> args{"make", mesh, "-o", out};
    args.insert(args.end(), c.args.begin(), c.args.end());
    const auto run = test::run_foldkit(args);
    EXPECT_EQ(run.exit_code, 2) << c.args.front() << ": " << run.err;
    EXPECT_NE(run.err.find(c.says), std::string::npos) << run.err;
    EXPECT_EQ(count_lines(run.err), 1u) << run.err;
    EXPECT_LT(run.err.size(), 200u) << "no 309-digit numbers: " << run.err;
  }
  EXPECT_FALSE(fs::exists(out));
}

TEST(CliMake, APngTooLargeForMemoryIsRefusedBeforeThePipelineRuns) {
  // --dpi 2400 on A3 is 28063x39685 pixels (4.5 GB): it was refused only after 63 s of work.
  const fs::path dir = test::temp_dir("make-dpi");
  const auto run = test::run_foldkit({"make", test::example_mesh("spot_128.obj").string(), "-o",
                                      (dir / "x.png").string(), "--paper", "A3", "--dpi", "2400"});
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_NE(run.err.find("--dpi 2400: a 297x420 mm sheet is 28063x39685 pixels"), std::string::npos)
      << run.err;
  EXPECT_NE(run.err.find("--dpi 880 at most"), std::string::npos) << run.err;
  EXPECT_EQ(run.err.find("loading"), std::string::npos) << "refused before loading the mesh: " << run.err;
  EXPECT_FALSE(fs::exists(dir / "x.png"));
}

TEST(CliMake, ASizeNeedingHundredsOfSheetsIsRefusedBeforeUnfolding) {
  const fs::path dir = test::temp_dir("make-budget");
  const auto run = test::run_foldkit({"make", test::example_mesh("spot_128.obj").string(), "-o",
                                      (dir / "x.pdf").string(), "--size", "9000mm", "-q"});
  EXPECT_EQ(run.exit_code, 5) << run.err;
  EXPECT_NE(run.err.find("over the limit of 500; the largest --size that fits 500 sheets is"),
            std::string::npos)
      << run.err;
  EXPECT_EQ(count_lines(run.err), 1u) << run.err;
}

TEST(CliMake, ALayoutStoppedByTheTimeLimitNamesTheFileAndTheLimitAndWritesNothing) {
  const fs::path dir = test::temp_dir("make-time-limit");
  const std::string mesh = test::example_mesh("spot_128.obj").string();
  const fs::path out = dir / "x.pdf";
  // 10 ms: the unfolding stops early with a valid result, the layout cannot.
  auto run =
      test::run_foldkit({"make", mesh, "--size", "250mm", "-o", out.string(), "-q", "--time-limit", "0.01"});
  EXPECT_EQ(run.exit_code, 5) << run.err;
  EXPECT_EQ(run.err.rfind("foldkit: " + mesh + ": stopped at the time limit", 0), 0u) << run.err;
  EXPECT_NE(run.err.find("(--time-limit 0.01 s bounds the whole command"), std::string::npos) << run.err;
  EXPECT_EQ(count_lines(run.err), 1u) << run.err;
  EXPECT_FALSE(fs::exists(out));
}
