// Printed colour (layout/fills and the renderers' fills), read back from rendered PNGs: every face shows
// its own region of its texture, the right way round, on Spot decimated to 500 faces and on a cube of
// asymmetric glyphs; the bleed reaches past every cut line; tabs take their partner face's colour.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <random>

#include "foldkit/devices/render.hpp"
#include "foldkit/layout/fills.hpp"
#include "foldkit/layout/layout.hpp"
#include "foldkit/unfold/decimate.hpp"
#include "foldkit/unfold/mesh_io.hpp"
#include "foldkit/unfold/unfold.hpp"
#include "layout_fixtures.hpp"
#include "test_images.hpp"
#include "test_paths.hpp"

using namespace foldkit;
namespace fs = std::filesystem;

namespace {

using test::read_image;
using Image = test::RgbImage;

/// Bilinear between texel centres, as a printer's (and Cairo's) magnification sees the texture.
std::array<double, 3> at_uv(const Image& texture, Vec2 uv) {
  const double x = uv.x * texture.w - 0.5, y = (1 - uv.y) * texture.h - 0.5;
  const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
  const double fx = x - x0, fy = y - y0;
  std::array<double, 3> out{};
  for (int ch = 0; ch < 3; ++ch)
    out[ch] = (1 - fx) * (1 - fy) * texture.at(x0, y0)[ch] + fx * (1 - fy) * texture.at(x0 + 1, y0)[ch] +
              (1 - fx) * fy * texture.at(x0, y0 + 1)[ch] + fx * fy * texture.at(x0 + 1, y0 + 1)[ch];
  return out;
}

struct Printed {
  unfold::Mesh mesh;
  unfold::Unfolding unfolding;
  layout::LayoutResult layout;
  std::vector<Image> pages;
  double dpi = 0;
};

// Unfolds, lays out (no numbers: nothing but the fills and the cut lines on the faces), adds fills and
// renders PNGs without fold lines.
Printed print(unfold::Mesh mesh, double size_mm, double dpi, const layout::FillOptions& fill = {}) {
  Printed out;
  out.mesh = std::move(mesh);
  out.dpi = dpi;
  unfold::UnfoldOptions uo;
  uo.threads = 1;
  out.unfolding = unfold::unfold_mesh(out.mesh, uo).unfolding;
  layout::LayoutOptions lo;
  lo.size_mm = size_mm;
  lo.numbers = false;
  // The part letter is printed over the texture on purpose; here only the texture is compared.
  lo.piece_letters = false;
  lo.pack.spacing_mm = layout::fill_spacing_mm(fill);
  out.unfolding = test::split_to_fit(out.mesh, out.unfolding, lo).unfolding;
  out.layout = layout::layout_sheets(out.unfolding, lo);
  layout::add_fills(out.layout, out.mesh, out.unfolding, fill);
  devices::RenderOptions ro;
  ro.png_dpi = dpi;
  ro.fold_lines = devices::FoldLines::None;
  const fs::path dir = test::temp_dir("fills");
  for (const fs::path& f : devices::render_sheets(out.layout.sheets, dir / "sheet.png", ro))
    out.pages.push_back(read_image(f));
  fs::remove_all(dir);
  return out;
}

struct SampleScore {
  int samples = 0, matching = 0;
};

// Points inside each face (at least `inset_mm` from its edges): the texture's colour at their texture
// coordinates against the printed colour at the same point of the sheet.
SampleScore sample_faces(const Printed& p, const Image& texture, double inset_mm, double tolerance,
                         int per_face) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0, 1);
  SampleScore score;
  const double px_per_mm = p.dpi / 25.4;
  for (int f = 0; f < p.mesh.num_faces(); ++f) {
    // Faces in a flat colour have no texture region to compare.
    if (!p.mesh.materials[p.mesh.face_material[f]].texture_found) continue;
    const int piece = p.unfolding.piece_of_face[f];
    const int sheet = p.layout.placements[piece].sheet;
    std::array<Vec2, 3> c;
    for (int i = 0; i < 3; ++i)
      c[i] = p.layout.to_sheet(piece, p.unfolding.flat[f][i]);
    const double area = std::abs(cross(c[1] - c[0], c[2] - c[0]));
    for (int k = 0; k < per_face; ++k) {
      double a = unit(rng), b = unit(rng);
      if (a + b > 1) a = 1 - a, b = 1 - b;
      const double w[3] = {1 - a - b, a, b};
      const Vec2 at = c[0] * w[0] + c[1] * w[1] + c[2] * w[2];
      // Distance to each edge = 2 * area * barycentric / edge length.
      bool inside = true;
      for (int i = 0; i < 3; ++i) {
        const double edge = norm(c[(i + 2) % 3] - c[(i + 1) % 3]);
        inside = inside && area * w[i] / edge >= inset_mm;
      }
      if (!inside) continue;
      const Vec2 uv = p.mesh.face_uv[f][0] * w[0] + p.mesh.face_uv[f][1] * w[1] + p.mesh.face_uv[f][2] * w[2];
      const auto want = at_uv(texture, uv);
      const auto got =
          p.pages[sheet].at(static_cast<int>(at.x * px_per_mm), static_cast<int>(at.y * px_per_mm));
      double diff = 0;
      for (int ch = 0; ch < 3; ++ch)
        diff = std::max(diff, std::abs(want[ch] - got[ch]));
      ++score.samples;
      score.matching += diff <= tolerance;
      if (diff > tolerance && std::getenv("FOLDKIT_FILLS_DEBUG"))
        std::fprintf(stderr,
                     "face %d at (%.2f, %.2f) mm uv (%.3f, %.3f): want %.2f %.2f %.2f got %.2f %.2f %.2f\n",
                     f, at.x, at.y, uv.x, uv.y, want[0], want[1], want[2], got[0], got[1], got[2]);
    }
  }
  return score;
}

fs::path spot_textured() {
  return test::example_mesh("spot_textured/spot_triangulated.obj");
}

fs::path cube(const std::string& name) {
  return test::source_dir() / "tests/data/colour" / name;
}

}  // namespace

TEST(Fills, SpotAt500FacesPrintsEachFacesTextureRegionFor99PercentOfSamples) {
  ASSERT_TRUE(fs::exists(spot_textured())) << spot_textured();
  const unfold::Mesh mesh = unfold::decimate(unfold::load_mesh(spot_textured()).mesh, 500);
  ASSERT_LE(mesh.num_faces(), 500);
  ASSERT_EQ(mesh.face_uv.size(), mesh.faces.size());
  const Printed p = print(mesh, 200, 200);
  const Image texture = read_image(spot_textured().parent_path() / "spot_texture.png");
  ASSERT_GT(texture.w, 0);
  const SampleScore s = sample_faces(p, texture, 0.3, 0.15, 8);
  ASSERT_GT(s.samples, 1000);
  std::printf("spot at %d faces: %d of %d samples match their texture\n", mesh.num_faces(), s.matching,
              s.samples);
  EXPECT_GE(s.matching, 0.99 * s.samples) << s.matching << " of " << s.samples << " samples match";
}

TEST(Fills, GlyphsPrintTheRightWayRoundOnEveryFace) {
  // A mirrored or turned face moves the glyph's bars: the samples on the bars and off them disagree.
  for (const char* file : {"cube.obj", "cube.glb"}) {
    const Printed p = print(unfold::load_mesh(cube(file)).mesh, 60, 300);
    const Image texture = read_image(cube("glyphs.png"));
    const SampleScore s = sample_faces(p, texture, 0.5, 0.12, 400);
    ASSERT_GT(s.samples, 2000);
    EXPECT_GE(s.matching, 0.99 * s.samples) << file << ": " << s.matching << " of " << s.samples;
  }
}

TEST(Fills, FlatColourFacesAreFilledWithTheirColour) {
  const Printed p = print(unfold::load_mesh(cube("cube.obj")).mesh, 60, 150);
  int red_faces = 0;
  for (int f = 0; f < p.mesh.num_faces(); ++f) {
    const unfold::Material& m = p.mesh.materials[p.mesh.face_material[f]];
    if (!m.texture.empty()) continue;
    const int piece = p.unfolding.piece_of_face[f];
    Vec2 centre{};
    for (int i = 0; i < 3; ++i)
      centre += p.layout.to_sheet(piece, p.unfolding.flat[f][i]) / 3.0;
    const auto got = p.pages[p.layout.placements[piece].sheet].at(static_cast<int>(centre.x * 150 / 25.4),
                                                                  static_cast<int>(centre.y * 150 / 25.4));
    EXPECT_NEAR(got[0], 0.8, 0.02);
    EXPECT_NEAR(got[1], 0.1, 0.02);
    ++red_faces;
  }
  EXPECT_EQ(red_faces, 2);
}

TEST(Fills, ColourReachesPastEveryCutLineByTheBleed) {
  layout::FillOptions fill;
  fill.bleed_mm = 1.5;
  fill.tab_fill = layout::TabFill::White;
  const Printed p = print(unfold::load_mesh(cube("cube.obj")).mesh, 60, 300, fill);
  int checked = 0, coloured = 0;
  for (int f = 0; f < p.mesh.num_faces(); ++f) {
    const int piece = p.unfolding.piece_of_face[f];
    for (int i = 0; i < 3; ++i) {
      const unfold::UnfoldEdge& e = p.unfolding.edges[p.unfolding.face_edges[f][i]];
      if (!e.cut) continue;
      const Vec2 a = p.layout.to_sheet(piece, p.unfolding.flat[f][i]);
      const Vec2 b = p.layout.to_sheet(piece, p.unfolding.flat[f][(i + 1) % 3]);
      const Vec2 c = p.layout.to_sheet(piece, p.unfolding.flat[f][(i + 2) % 3]);
      Vec2 out = normalized(perp_ccw(b - a));
      if (dot(out, c - a) > 0) out = -out;
      // Half way into the bleed beside the middle of the edge: not white, whether a tab is there or not.
      const Vec2 q = (a + b) * 0.5 + out * 0.75;
      const auto got = p.pages[p.layout.placements[piece].sheet].at(static_cast<int>(q.x * 300 / 25.4),
                                                                    static_cast<int>(q.y * 300 / 25.4));
      ++checked;
      coloured += got[0] + got[1] + got[2] < 2.9;
    }
  }
  EXPECT_GT(checked, 10);
  EXPECT_EQ(coloured, checked);
}

TEST(Fills, TabsTakeTheColourOfTheFaceTheyGlueUnder) {
  const Printed p = print(unfold::load_mesh(cube("cube.obj")).mesh, 60, 150);
  int tabs = 0, tab_fills = 0;
  for (const Sheet& s : p.layout.sheets) {
    for (const Path& path : s.paths)
      tabs += path.role == PathRole::Tab;
    tab_fills += static_cast<int>(s.fills.size());
  }
  ASSERT_GT(tabs, 0);
  EXPECT_EQ(tab_fills, p.mesh.num_faces() + tabs);
  layout::FillOptions white;
  white.tab_fill = layout::TabFill::White;
  const Printed q = print(unfold::load_mesh(cube("cube.obj")).mesh, 60, 150, white);
  int fills = 0;
  for (const Sheet& s : q.layout.sheets)
    fills += static_cast<int>(s.fills.size());
  EXPECT_EQ(fills, q.mesh.num_faces());
}

TEST(Fills, AMeshWithoutColoursGetsNoFills) {
  const Printed p = print(unfold::load_mesh(test::example_mesh("spot_128.obj")).mesh, 150, 50);
  for (const Sheet& s : p.layout.sheets) {
    EXPECT_TRUE(s.fills.empty());
    EXPECT_TRUE(s.images.empty());
  }
}

TEST(Fills, DecimationKeepsEveryFacesTextureTheRightWayRound) {
  const unfold::Mesh full = unfold::load_mesh(spot_textured()).mesh;
  const unfold::Mesh mesh = unfold::decimate(full, 500);
  auto ccw = [](const unfold::Mesh& m) {
    int n = 0;
    for (const auto& uv : m.face_uv)
      n += cross(uv[1] - uv[0], uv[2] - uv[0]) > 0;
    return n;
  };
  // Spot's file maps 97% of its faces counter-clockwise (the rest are a mirrored strip of the layout);
  // collapses never turn a face's texture over, so the share does not drop.
  const double before = static_cast<double>(ccw(full)) / full.num_faces();
  const double after = static_cast<double>(ccw(mesh)) / mesh.num_faces();
  EXPECT_GE(after, before - 0.01) << before << " -> " << after;
  ASSERT_EQ(mesh.face_material.size(), mesh.faces.size());
  EXPECT_EQ(mesh.materials.size(), full.materials.size());
}

TEST(Fills, SvgAndPdfEmbedTheFillsAsOneImagePerSheet) {
  const Printed p = print(unfold::load_mesh(cube("cube.glb")).mesh, 60, 50);
  const fs::path dir = test::temp_dir("fills_formats");
  devices::RenderOptions ro;
  const auto svg = devices::render_sheets(p.layout.sheets, dir / "cube.svg", ro);
  const std::string text = test::slurp(svg.front());
  EXPECT_NE(text.find("<g id=\"fill\""), std::string::npos);
  EXPECT_NE(text.find("data:image/jpeg;base64,"), std::string::npos);
  EXPECT_NE(text.find("clip-path=\"url(#fills)\""), std::string::npos);
  const auto pdf = devices::render_sheets(p.layout.sheets, dir / "cube.pdf", ro);
  const std::string bytes = test::slurp(pdf.front());
  EXPECT_NE(bytes.find("/DCTDecode"), std::string::npos);
  fs::remove_all(dir);
}
