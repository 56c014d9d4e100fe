// The assembly guide: every part drawn in its colour and marked with its letter.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "../devices/src/render_internal.hpp"
#include "foldkit/devices/render.hpp"
#include "foldkit/layout/guide.hpp"
#include "foldkit/layout/piece_letters.hpp"
#include "foldkit/unfold/mesh_io.hpp"
#include "foldkit/unfold/unfold.hpp"
#include "layout_fixtures.hpp"
#include "test_images.hpp"
#include "test_paths.hpp"

using namespace foldkit;
using namespace foldkit::layout;

namespace {

struct Guided {
  unfold::PartsResult split;
  LayoutResult layout;
  Sheet guide;
};

// The parts `split_to_fit` cuts from examples/<name> at `options`, laid out, and their guide.
Guided guided(const std::string& name, const LayoutOptions& options) {
  const auto& ex = test::unfolded_example(name);
  Guided out;
  out.split = test::split_to_fit(ex.mesh, ex.unfolding, options);
  out.layout = layout_sheets(out.split.unfolding, options);
  out.guide = guide_sheet(ex.mesh, out.split.unfolding, out.layout, GuideOptions{});
  return out;
}

const Guided& spot_guide() {
  static const Guided g = [] {
    LayoutOptions o;
    o.size_mm = 150;
    o.hints = true;
    return guided("spot_350.obj", o);
  }();
  return g;
}

// Fish at 300 mm: 20-odd parts, several of them small and side by side in the views; seen from the front
// (head on) it is much narrower than long.
const Guided& fish_guide() {
  static const Guided g = [] {
    LayoutOptions o;
    o.size_mm = 300;
    return guided("fish_350.obj", o);
  }();
  return g;
}

}  // namespace

TEST(Guide, EveryPartIsFilledInItsLettersColourAndMarkedWithItsLetter) {
  const Guided& g = spot_guide();
  const int parts = g.split.unfolding.piece_count;
  ASSERT_GT(parts, 2);
  std::set<int> tints;
  for (const Path& p : g.guide.paths)
    if (p.role == PathRole::Piece && p.filled) tints.insert(p.tint);
  std::set<std::string> letters;
  for (const Text& t : g.guide.texts)
    if (t.role == PathRole::Piece) letters.insert(t.text);
  for (int p = 0; p < parts; ++p) {
    const std::string& letter = g.layout.piece_letters[p];
    EXPECT_TRUE(tints.count(letter_rank(letter))) << letter;
    EXPECT_TRUE(letters.count(letter)) << "part " << letter << " shows in no view";
  }
}

TEST(Guide, TheRenderedGuideShowsEveryPartsColour) {
  const Guided& g = spot_guide();
  const std::filesystem::path png = test::temp_dir("guide") / "guide.png";
  devices::RenderOptions options;
  options.png_dpi = 100;
  devices::render_sheets({g.guide}, png, options);
  const test::RgbImage image = test::read_image(png);
  ASSERT_GT(image.w, 0);
  const int w = image.w, h = image.h;
  const unsigned char* pixels = image.rgb.data();
  // The palette has twelve colours; parts beyond repeat them (their letters tell them apart).
  const int parts = std::min(g.split.unfolding.piece_count, 12);
  std::vector<int> seen(parts, 0);
  for (int p = 0; p < parts; ++p) {
    Path probe;
    probe.tint = p;
    const devices::Rgb base = devices::detail::shaded_fill(probe);
    const double norm2 = base.r * base.r + base.g * base.g + base.b * base.b;
    for (int i = 0; i < w * h; ++i) {
      const double r = pixels[3 * i] / 255.0, gr = pixels[3 * i + 1] / 255.0, b = pixels[3 * i + 2] / 255.0;
      // A lit face: the part's colour times a shade.
      const double s = (r * base.r + gr * base.g + b * base.b) / norm2;
      if (s < 0.5 || s > 1.02) continue;
      const double err = std::hypot(r - s * base.r, gr - s * base.g, b - s * base.b);
      seen[p] += err < 0.02;
    }
  }
  for (int p = 0; p < parts; ++p)
    EXPECT_GT(seen[p], 50) << "colour of tint " << p;
}

TEST(Guide, NoTwoLettersOfAViewOverlap) {
  const Sheet& guide = fish_guide().guide;
  // A letter's box as drawn: from its baseline up by its height, as wide as the print font sets it.
  std::vector<Box2> boxes;
  std::vector<std::string> names;
  for (const Text& t : guide.texts)
    if (t.role == PathRole::Piece) {
      Box2 b;
      b.add(t.at_mm);
      b.add(t.at_mm + Vec2{letter_width_mm(t.text, t.height_mm, PieceLetterOptions{}), -t.height_mm});
      boxes.push_back(b);
      names.push_back(t.text);
    }
  ASSERT_GT(boxes.size(), 20u);
  for (std::size_t i = 0; i < boxes.size(); ++i)
    for (std::size_t j = i + 1; j < boxes.size(); ++j)
      EXPECT_FALSE(boxes[i].overlaps(boxes[j])) << names[i] << " and " << names[j];
}

// Back faces and shaded sides are dark: a letter there reads only on its white halo (render tests).
TEST(Guide, EveryLetterIsDrawnOnAHaloOverTheFaces) {
  const Sheet& guide = fish_guide().guide;
  int letters = 0;
  for (const Text& t : guide.texts)
    if (t.role == PathRole::Piece) {
      ++letters;
      EXPECT_TRUE(t.halo_over_paths) << t.text;
    }
  EXPECT_GT(letters, 20);
}

TEST(Guide, AModelSeenEndOnStillFillsItsView) {
  const Sheet& guide = fish_guide().guide;
  // The front view is the one in the top left quarter of the page.
  const Vec2 middle = 0.5 * (guide.printable_mm.min + guide.printable_mm.max);
  Box2 front;
  for (const Path& p : guide.paths)
    if (p.role == PathRole::Piece && p.filled && p.points_mm[0].x < middle.x && p.points_mm[0].y < middle.y)
      for (Vec2 q : p.points_mm)
        front.add(q);
  ASSERT_FALSE(front.empty());
  // Its cell is a little under half the printable width; the sphere about the fish left it 0.23 of it.
  EXPECT_GT(front.width(), 0.4 * guide.printable_mm.width());
}

namespace {

unfold::Mesh low_poly(const std::string& file) {
  return unfold::load_mesh(test::source_dir() / "tests" / "data" / "lowpoly" / file).mesh;
}

// The mesh turned a quarter about X, so that what stood on Z stands on Y.
unfold::Mesh turned_to_y_up(unfold::Mesh mesh) {
  for (Vec3& v : mesh.vertices)
    v = {v.x, v.z, -v.y};
  return mesh;
}

}  // namespace

TEST(Guide, AModelStandingOnAFlatBaseAlongZIsShownStandingAndOthersStandOnY) {
  // barn.obj and drum.obj are drawn Z-up: seen Y-up, the barn lay on its side in every view.
  for (const char* name : {"barn.obj", "drum.obj", "l_block.obj"}) {
    const unfold::Mesh mesh = low_poly(name);
    EXPECT_EQ(upright_axis(mesh).z, 1) << name;
    EXPECT_EQ(upright_axis(turned_to_y_up(mesh)).y, 1) << name;
  }
  // Organic models have no base and follow the OBJ convention.
  EXPECT_EQ(upright_axis(test::unfolded_example("spot_128.obj").mesh).y, 1);
  EXPECT_EQ(upright_axis(test::unfolded_example("fish_350.obj").mesh).y, 1);
}

namespace {

// The corners of the faces painted in the guide's front view (its top left quarter).
std::vector<Vec2> front_view_of_barn(UpAxis up) {
  const unfold::Mesh mesh = low_poly("barn.obj");
  unfold::UnfoldOptions uo;
  uo.threads = 1;
  const unfold::Unfolding u = unfold::unfold_mesh(mesh, uo).unfolding;
  LayoutOptions o;
  o.size_mm = 150;
  const unfold::PartsResult parts = test::split_to_fit(mesh, u, o);
  const LayoutResult r = layout_sheets(parts.unfolding, o);
  GuideOptions g;
  g.up = up;
  const Sheet guide = guide_sheet(mesh, parts.unfolding, r, g);
  const Vec2 middle = 0.5 * (guide.printable_mm.min + guide.printable_mm.max);
  std::vector<Vec2> corners;
  for (const Path& p : guide.paths)
    if (p.role == PathRole::Piece && p.filled && p.points_mm[0].x < middle.x && p.points_mm[0].y < middle.y)
      corners.insert(corners.end(), p.points_mm.begin(), p.points_mm.end());
  return corners;
}

Box2 box_of(const std::vector<Vec2>& points) {
  Box2 box;
  for (Vec2 q : points)
    box.add(q);
  return box;
}

}  // namespace

TEST(Guide, TheFrontViewOfAZUpBarnShowsItsGableWithTheRidgeOnTop) {
  const std::vector<Vec2> corners = front_view_of_barn(UpAxis::Auto);
  const Box2 front = box_of(corners);
  ASSERT_FALSE(front.empty());
  // The gable end: a pentagon 4 wide and 5 high whose top is the ridge, one point in the middle. Seen
  // from above (Y up) it was the roof, a 4 x 6 rectangle with two top corners.
  EXPECT_NEAR(front.height() / front.width(), 5.0 / 4.0, 0.05);
  Box2 top;
  for (Vec2 q : corners)
    if (q.y < front.min.y + 0.02 * front.height()) top.add(q);
  EXPECT_LT(top.width(), 0.05 * front.width()) << "the ridge, not a flat top edge";
  EXPECT_NEAR(0.5 * (top.min.x + top.max.x), 0.5 * (front.min.x + front.max.x), 0.02 * front.width());
}

TEST(Guide, AnUpAxisAskedForOverridesTheOneFound) {
  // Y up, the barn lies on its side: the front view looks down on its roof, 4 wide and 6 long.
  const Box2 roof = box_of(front_view_of_barn(UpAxis::Y));
  ASSERT_FALSE(roof.empty());
  EXPECT_NEAR(roof.height() / roof.width(), 6.0 / 4.0, 0.05);
  const Box2 gable = box_of(front_view_of_barn(UpAxis::Z));
  EXPECT_NEAR(gable.height() / gable.width(), 5.0 / 4.0, 0.05);
}
