// Packing: nothing overlaps, nothing leaves the area or enters a keep-out zone, items turn to fit,
// spill onto new sheets, and an item too large for any sheet is reported rather than lost.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "foldkit/layout/outline.hpp"
#include "foldkit/layout/pack.hpp"
#include "layout_fixtures.hpp"

using namespace foldkit;
using namespace foldkit::layout;

namespace {

PackItem rect(double w, double h) {
  return PackItem{{{{0, 0}, {w, 0}, {w, h}, {0, h}}}, {}};
}

std::vector<Polygon> placed(const PackItem& item, const PackPlacement& p) {
  std::vector<Polygon> out = item.shape_mm;
  for (Polygon& poly : out)
    for (Vec2& v : poly)
      v = p.transform.apply(v);
  return out;
}

// Every placed item inside the area, and items on one sheet at least `gap` apart.
void expect_valid(const std::vector<PackItem>& items, const PackResult& r, const PackOptions& o) {
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (r.placements[i].sheet < 0) continue;
    const auto a = placed(items[i], r.placements[i]);
    for (const Polygon& poly : a)
      for (Vec2 v : poly) {
        ASSERT_GE(v.x, o.area_mm.min.x - 1e-9);
        ASSERT_LE(v.x, o.area_mm.max.x + 1e-9);
        ASSERT_GE(v.y, o.area_mm.min.y - 1e-9);
        ASSERT_LE(v.y, o.area_mm.max.y + 1e-9);
      }
    const auto grown = polygon_offset(a, 0.5 * o.spacing_mm - 0.01);
    for (std::size_t j = i + 1; j < items.size(); ++j) {
      if (r.placements[j].sheet != r.placements[i].sheet) continue;
      const auto b = polygon_offset(placed(items[j], r.placements[j]), 0.5 * o.spacing_mm - 0.01);
      ASSERT_LT(intersection_area(grown, b), 1e-6)
          << "items " << i << " and " << j << " closer than the spacing";
    }
  }
}

// The pieces of the penguin_500 example's unfolding with the model `size_mm` large, one item each.
std::vector<PackItem> penguin_pieces(double size_mm) {
  const auto& ex = test::unfolded_example("penguin_500.obj");
  std::vector<PackItem> items;
  for (const ScaledPiece& p : scaled_pieces(ex.unfolding, size_mm / ex.unfolding.model_extent)) {
    std::vector<Polygon> tris;
    for (const Triangle2& t : p.triangles_mm)
      tris.push_back({t[0], t[1], t[2]});
    items.push_back({polygon_union(tris), {}});
  }
  return items;
}

}  // namespace

TEST(Pack, RectanglesFillASheetThenSpillOntoTheNext) {
  std::vector<PackItem> items;
  for (int i = 0; i < 14; ++i)
    items.push_back(rect(40 + i % 3 * 5, 30));
  PackOptions o;
  o.area_mm = {{0, 0}, {100, 100}};
  const PackResult r = pack_items(items, o);
  EXPECT_TRUE(r.unplaced.empty());
  EXPECT_GE(r.sheet_count, 2);
  EXPECT_LE(r.sheet_count, 3);
  expect_valid(items, r, o);
}

TEST(Pack, ASheetThatFirstFitLeavesIsSavedByPackingTheItemsOfTwoSheetsAgain) {
  // Strips most of the sheet's height, about 5, 4, 3, 3, 3 and 2 tenths of its width: largest first, 5 and 4
  // share a sheet, the threes the next, and the 2 fits neither (three sheets); {5, 3, 2} and {4, 3, 3}
  // fill two.
  std::vector<PackItem> items;
  for (double w : {47.0, 37.0, 27.0, 27.0, 27.0, 17.0}) {
    items.push_back(rect(w, 8));
    items.back().rotate = false;
  }
  PackOptions o;
  o.area_mm = {{0, 0}, {100, 14}};  // too low for two strips one above the other
  o.spacing_mm = 0.5;
  o.shaken_orders = 0;
  o.sheet_search_orders = 0;
  EXPECT_EQ(pack_items(items, o).sheet_count, 3) << "first fit alone";
  o.sheet_search_orders = 200;
  const PackResult r = pack_items(items, o);
  EXPECT_TRUE(r.unplaced.empty());
  EXPECT_EQ(r.sheet_count, 2);
  expect_valid(items, r, o);
}

TEST(Pack, ALongItemIsTurnedToFit) {
  std::vector<PackItem> items = {rect(140, 10)};
  PackOptions o;
  o.area_mm = {{0, 0}, {60, 150}};
  const PackResult r = pack_items(items, o);
  ASSERT_TRUE(r.unplaced.empty());
  // Along the 60 mm width its 140 mm stick out: it is turned until they span less than 60 mm across
  // (cos < 60/140), not necessarily upright: 24 rotations may find a tilt that lies lower.
  EXPECT_GT(std::fabs(std::sin(r.placements[0].transform.angle_rad)), std::sqrt(1 - std::pow(60.0 / 140, 2)));
  expect_valid(items, r, o);
}

TEST(Pack, AnItemIsTurnedToLayItsLongestEdgeAlongTheSheet) {
  // An acute triangle, base 60 and height 40, given tilted by 97 degrees. Only with its base along
  // the sheet's side does it fit 62.5 x 42.5 mm: along either other side it spans 50 x 48 mm, the
  // nearest of the 24 even rotations leaves it 7 degrees tilted and 47 mm tall, and the smallest
  // bounding box ties on all three sides (its area is twice the triangle's), so that turn may lay
  // any of them flat.
  const Rotation tilt(97 * std::numbers::pi / 180);
  PackItem triangle{{{tilt(Vec2{0, 0}), tilt(Vec2{60, 0}), tilt(Vec2{30, 40})}}, {}};
  const std::vector<PackItem> items = {triangle};
  PackOptions o;
  o.area_mm = {{0, 0}, {62.5, 42.5}};
  o.aligned_hull_edges = 0;
  EXPECT_EQ(pack_items(items, o).unplaced.size(), 1u) << "it fits nowhere else";
  o.aligned_hull_edges = 1;
  const PackResult r = pack_items(items, o);
  ASSERT_TRUE(r.unplaced.empty());
  expect_valid(items, r, o);
  const Vec2 base =
      r.placements[0].transform.apply(tilt(Vec2{60, 0})) - r.placements[0].transform.apply(tilt(Vec2{0, 0}));
  EXPECT_NEAR(std::fabs(base.y), 0, 1e-9) << "the base lies along the sheet's side";
}

TEST(Pack, ASmallItemNestsInTheBayOfAConcaveOne) {
  // A cup 60 wide, 40 tall, walls 10 thick, and a 20 x 20 square that only fits inside the cup:
  // bounding boxes alone would need two sheets.
  PackItem cup{{{{0, 0}, {60, 0}, {60, 40}, {50, 40}, {50, 10}, {10, 10}, {10, 40}, {0, 40}}}, {}};
  std::vector<PackItem> items = {cup, rect(20, 20)};
  PackOptions o;
  o.area_mm = {{0, 0}, {62, 42}};
  o.spacing_mm = 1;
  const PackResult r = pack_items(items, o);
  EXPECT_TRUE(r.unplaced.empty());
  EXPECT_EQ(r.sheet_count, 1);
  expect_valid(items, r, o);
}

TEST(Pack, KeepOutZonesStayEmptyAndTooLargeItemsAreReported) {
  std::vector<PackItem> items = {rect(30, 30), rect(30, 30), rect(500, 10)};
  PackOptions o;
  o.area_mm = {{0, 0}, {100, 100}};
  o.keep_out_mm = {Box2{{0, 60}, {40, 100}}};
  const PackResult r = pack_items(items, o);
  EXPECT_EQ(r.unplaced, std::vector<int>{2});
  EXPECT_EQ(r.placements[2].sheet, -1);
  for (int i = 0; i < 2; ++i) {
    const auto shape = placed(items[i], r.placements[i]);
    for (Vec2 v : shape[0])
      EXPECT_FALSE(v.x < 40 + o.spacing_mm - 1e-9 && v.y > 60 - o.spacing_mm + 1e-9)
          << "inside the keep-out zone";
  }
}

TEST(Pack, AtMostTheAllowedNumberOfSheetsIsOpened) {
  std::vector<PackItem> items(6, rect(45, 45));
  PackOptions o;
  o.area_mm = {{0, 0}, {100, 100}};
  o.max_sheets = 1;
  const PackResult r = pack_items(items, o);
  EXPECT_EQ(r.sheet_count, 1);
  EXPECT_EQ(r.unplaced.size(), 2u);
}

TEST(Pack, RealPiecesPackWithoutOverlapAtHighCoverage) {
  const auto& ex = test::unfolded_example("penguin_500.obj");
  const auto pieces = scaled_pieces(ex.unfolding, 150 / ex.unfolding.model_extent);
  std::vector<PackItem> items;
  double area = 0;
  for (const ScaledPiece& p : pieces) {
    std::vector<Polygon> tris;
    for (const Triangle2& t : p.triangles_mm)
      tris.push_back({t[0], t[1], t[2]});
    items.push_back({polygon_union(tris), {}});
    area += p.area_mm2;
  }
  PackOptions o;
  o.area_mm = {{10, 10}, {200, 287}};
  const PackResult r = pack_items(items, o);
  ASSERT_TRUE(r.unplaced.empty());
  expect_valid(items, r, o);
  EXPECT_GT(area / (r.sheet_count * 190.0 * 277.0), 0.3);
}

TEST(Pack, TheLibnest2dEngineKeepsItemsApartAndInsideTheArea) {
  std::vector<PackItem> items;
  for (int i = 0; i < 10; ++i)
    items.push_back(rect(40 + i % 3 * 5, 30));
  PackOptions o;
  o.area_mm = {{10, 10}, {110, 110}};
  o.engine = PackEngine::Nest2d;
  const PackResult r = pack_items(items, o);
  ASSERT_TRUE(r.unplaced.empty());
  EXPECT_GE(r.sheet_count, 2);
  expect_valid(items, r, o);
}

TEST(Pack, ProgressCountsEveryPlacementAndEndsAtItsTotal) {
  std::vector<PackItem> items;
  for (int i = 0; i < 14; ++i)
    items.push_back(rect(40 + i % 3 * 5, 30));
  PackOptions o;
  o.area_mm = {{0, 0}, {100, 100}};
  std::vector<std::pair<long, long>> seen;
  o.progress = [&seen](long done, long total) { seen.emplace_back(done, total); };
  pack_items(items, o);
  ASSERT_GT(seen.size(), items.size()) << "a report per placement (of the calling thread), and the last";
  for (std::size_t k = 0; k < seen.size(); ++k) {
    EXPECT_EQ(seen[k].second, seen.front().second) << "the total stays";
    EXPECT_LE(seen[k].first, seen[k].second);
    if (k > 0) {
      EXPECT_GT(seen[k].first, seen[k - 1].first) << "every report counts a placement more";
    }
  }
  EXPECT_EQ(seen.back().first, seen.back().second);
  EXPECT_EQ(seen.back().second % static_cast<long>(items.size()), 0) << "items times orders";
}

// Orders are packed on several threads and judged in their own order: the threads never change where
// anything goes, also when the shaken orders stop early.
TEST(Pack, TheThreadsNeverChangeThePacking) {
  std::vector<PackItem> items = penguin_pieces(60);
  // Two of these go to a sheet (57% of it), so the plain orders leave more sheets than the cells need
  // and the shaken orders are tried.
  for (int i = 0; i < 7; ++i)
    items.push_back(rect(100, 150));
  PackOptions o;
  o.area_mm = {{10, 10}, {200, 287}};
  std::size_t reports_one = 0;  // one thread: one per placement in every order tried, and the last
  o.threads = 1;
  o.progress = [&](long, long) { ++reports_one; };
  const PackResult one = pack_items(items, o);
  ASSERT_TRUE(one.unplaced.empty());
  for (int threads : {2, 3}) {
    o.threads = threads;
    o.progress = nullptr;
    const PackResult many = pack_items(items, o);
    ASSERT_EQ(many.sheet_count, one.sheet_count) << threads << " threads";
    for (std::size_t i = 0; i < items.size(); ++i) {
      EXPECT_EQ(many.placements[i].sheet, one.placements[i].sheet) << "item " << i << ", " << threads;
      EXPECT_EQ(many.placements[i].transform.apply(Vec2{1, 2}), one.placements[i].transform.apply(Vec2{1, 2}))
          << "item " << i << ", " << threads << " threads";
    }
  }
  EXPECT_GT(reports_one, 3 * items.size() + 1) << "shaken orders were tried";
}

namespace {
Polygon square(double side) {
  return {{0, 0}, {side, 0}, {side, side}, {0, side}};
}
}  // namespace

TEST(PackBound, SixSquaresTooWideToShareASheetNeedSixSheets) {
  // 150 mm squares on 190 x 277 mm: by area three sheets, but each one covers the centre wherever it lies.
  const std::vector<Polygon> cores(6, square(150));
  EXPECT_EQ(shape_sheet_bound(cores, Box2{{0, 0}, {190, 277}}), 6);
}

TEST(PackBound, SquaresTooWideToGoSideBySideGoTwoToASheet) {
  // 120 mm squares on 190 x 277 mm: two fit one above the other, never three (area: 12 x 14,400 mm² fits
  // in 4 sheets).
  const std::vector<Polygon> cores(12, square(120));
  EXPECT_EQ(shape_sheet_bound(cores, Box2{{0, 0}, {190, 277}}), 6);
}

TEST(PackBound, SquaresAThirdOfTheSheetTallGoTwoToASheetAsTheRhombicuboctahedronsDo) {
  // The rhombicuboctahedron at 250 mm: eighteen 103.6 mm squares on 190 x 277 mm. By area they fill four
  // sheets, and a lattice spaced after their width proves six; every placement covers one of the two
  // points at a third and two thirds of the height on the centre line, so no sheet takes three: nine.
  const std::vector<Polygon> cores(18, square(103.6));
  EXPECT_EQ(shape_sheet_bound(cores, Box2{{10, 10}, {200, 287}}), 9);
}

TEST(PackBound, NeverAboveTheSheetsThePackerUses) {
  // The packer's count is one packing, so no lower bound may exceed it: squares, hexagons and triangles
  // of many sizes, each packed without spacing, each set also turned by an odd angle.
  auto regular = [](int corners, double radius, double turn) {
    Polygon p;
    for (int k = 0; k < corners; ++k) {
      const double a = turn + 2 * std::numbers::pi * k / corners;
      p.push_back({radius * std::cos(a), radius * std::sin(a)});
    }
    return p;
  };
  const Box2 area{{0, 0}, {190, 277}};
  PackOptions o;
  o.area_mm = area;
  o.spacing_mm = 0;
  o.shaken_orders = 0;
  long beyond_area = 0;
  for (int corners : {3, 4, 6})
    for (double radius = 40; radius <= 125; radius += 7.5) {
      std::vector<Polygon> cores;
      std::vector<PackItem> items;
      for (int i = 0; i < 7; ++i) {
        cores.push_back(regular(corners, radius, 0.3 * i));
        items.push_back(PackItem{{cores.back()}, {}});
      }
      const long bound = shape_sheet_bound(cores, area);
      const PackResult packed = pack_items(items, o);
      if (!packed.unplaced.empty()) continue;  // larger than the sheet
      EXPECT_LE(bound, packed.sheet_count) << corners << " corners, radius " << radius;
      const double area_sheets = std::ceil(total_area(cores) / (area.width() * area.height()));
      beyond_area += bound > area_sheets;
    }
  EXPECT_GT(beyond_area, 5) << "the shapes should often say more than the area";
}

TEST(PackBound, SmallOrConcaveShapesCountNothingAndNothingIsZero) {
  EXPECT_EQ(shape_sheet_bound({}, Box2{{0, 0}, {190, 277}}), 0);
  const std::vector<Polygon> small(40, square(10));
  EXPECT_EQ(shape_sheet_bound(small, Box2{{0, 0}, {190, 277}}), 0);
  const std::vector<Polygon> concave(6, Polygon{{0, 0}, {150, 0}, {150, 150}, {75, 20}, {0, 150}});
  EXPECT_EQ(shape_sheet_bound(concave, Box2{{0, 0}, {190, 277}}), 0) << "a concave core is refused";
}

// The packer's grids and scans are tuned for speed (rows tried in a spread order, rotations by how
// high their rows' widths let them lie, free runs counted by length); none of it may move a piece.
// These are the placements the plain scan found (main at a8e32f0), to a micrometre and a microradian.
TEST(Pack, TheFasterScansPlaceEveryPieceWhereThePlainScanDid) {
  std::vector<PackItem> items = penguin_pieces(150);
  for (int i = 0; i < 5; ++i)
    items.push_back(rect(60 + 20 * i, 45 + 15 * i));
  PackOptions o;
  o.area_mm = {{10, 10}, {200, 287}};
  o.keep_out_mm = {{{150, 240}, {200, 287}}};
  o.aligned_hull_edges = 0;  // the rotations the plain scan was recorded at
  const PackResult r = pack_items(items, o);
  std::string got;
  for (const PackPlacement& p : r.placements) {
    const Vec2 origin = p.transform.apply(Vec2{0, 0}), unit = p.transform.apply(Vec2{1, 0}) - origin;
    char line[96];
    std::snprintf(line, sizeof line, "%d %.3f %.3f %.6f\n", p.sheet, origin.x, origin.y,
                  std::atan2(unit.y, unit.x));
    got += line;
  }
  const std::string plain_scan =
      "1 168.422 33.907 2.094395\n"
      "1 43.692 146.156 2.617994\n"
      "0 37.705 36.251 -1.047198\n"
      "1 101.282 143.998 2.879793\n"
      "0 26.071 48.860 2.135877\n"
      "2 28.734 265.991 -1.675126\n"
      "1 86.504 108.843 -2.729308\n"
      "1 60.886 168.579 0.000000\n"
      "1 10.362 202.660 -1.138989\n"
      "0 117.873 278.734 -0.523599\n"
      "0 93.501 37.942 -1.570796\n"
      "1 100.704 51.793 1.047198\n"
      "0 117.870 256.265 -0.739662\n"
      "1 143.376 285.853 -2.525259\n"
      "1 50.300 23.365 0.523599\n"
      "1 172.162 93.661 0.000000\n"
      "0 159.134 163.938 2.356194\n"
      "1 70.033 50.098 0.523599\n"
      "0 57.864 142.287 -1.047198\n"
      "0 138.173 28.956 -1.132917\n"
      "1 154.873 63.235 -1.047198\n"
      "1 85.697 37.352 -1.308997\n"
      "0 197.769 163.942 2.901896\n"
      "0 55.374 83.374 1.570796\n"
      "0 117.874 177.874 0.000000\n"
      "1 10.374 210.874 0.000000\n"
      "0 83.165 41.371 0.261799\n"
      "0 115.374 145.874 1.570796\n";
  EXPECT_EQ(got, plain_scan);
}
