// Sheet furniture: number, name and scale check in a free corner, clear of parts and mark zones.
#include <gtest/gtest.h>

#include "foldkit/layout/furniture.hpp"
#include "foldkit/layout/label_text.hpp"
#include "foldkit/layout/polygon.hpp"

using namespace foldkit;
using namespace foldkit::layout;

namespace {

Sheet a4_with_part(std::vector<Vec2> outline) {
  Sheet s;
  s.size_mm = {210, 297};
  s.printable_mm = Box2{{10, 10}, {200, 287}};
  s.paths.push_back(Path{PathRole::Cut, std::move(outline), true, 0});
  return s;
}

std::vector<Vec2> furniture_points(const Sheet& s) {
  std::vector<Vec2> points;
  for (const Path& p : s.paths)
    if (p.role == PathRole::Sheet) points.insert(points.end(), p.points_mm.begin(), p.points_mm.end());
  for (const Text& t : s.texts)
    if (t.role == PathRole::Sheet) points.push_back(t.at_mm);
  return points;
}

}  // namespace

TEST(Furniture, EverySheetGetsItsNumberTheNameA50mmBarAnd1inSquareInAFreeCorner) {
  std::vector<Sheet> sheets{a4_with_part({{10, 10}, {150, 10}, {150, 200}, {10, 200}}),
                            a4_with_part({{20, 20}, {60, 20}, {60, 60}})};
  const auto crowded = add_sheet_furniture(sheets, {}, FurnitureOptions{"cow"});
  EXPECT_TRUE(crowded.empty());
  for (std::size_t k = 0; k < sheets.size(); ++k) {
    const Sheet& s = sheets[k];
    bool number = false, bar_label = false;
    for (const Text& t : s.texts) {
      number = number || t.text == std::to_string(k + 1) + "/2  cow";
      bar_label = bar_label || t.text == "50 mm";
    }
    EXPECT_TRUE(number && bar_label) << "sheet " << k + 1;
    bool bar = false, square = false;
    for (const Path& p : s.paths) {
      if (p.role != PathRole::Sheet) continue;
      if (p.points_mm.size() == 2 && std::abs(norm(p.points_mm[1] - p.points_mm[0]) - 50) < 1e-9) bar = true;
      if (p.closed && p.points_mm.size() == 4 &&
          std::abs(std::abs(signed_area(p.points_mm)) - 25.4 * 25.4) < 1e-6)
        square = true;
    }
    EXPECT_TRUE(bar && square) << "sheet " << k + 1;
    const Box2 block = bounds_of(furniture_points(s));
    EXPECT_FALSE(block.overlaps(bounds_of(s.paths.front().points_mm))) << "the block keeps clear of the part";
    EXPECT_TRUE(s.printable_mm.min.x <= block.min.x && block.max.x <= s.printable_mm.max.x);
    EXPECT_TRUE(s.printable_mm.min.y <= block.min.y && block.max.y <= s.printable_mm.max.y);
  }
  EXPECT_FALSE(sheets[0].legend_mm.empty()) << "the legend goes on sheet 1";
  EXPECT_TRUE(sheets[1].legend_mm.empty());
}

TEST(Furniture, KeepOutZonesAreRespected) {
  std::vector<Sheet> sheets{a4_with_part({{10, 10}, {50, 10}, {50, 50}})};
  // A zone over the bottom-right corner, as a mark would have.
  const std::vector<Box2> zones{Box2{{120, 220}, {210, 297}}};
  add_sheet_furniture(sheets, zones, FurnitureOptions{});
  EXPECT_FALSE(bounds_of(furniture_points(sheets[0])).overlaps(zones[0]));
}

TEST(Furniture, AFullSheetGetsNumberAndBarInTheMarginAndIsReported) {
  std::vector<Sheet> sheets{a4_with_part({{10, 10}, {200, 10}, {200, 287}, {10, 287}})};
  const auto crowded = add_sheet_furniture(sheets, {}, FurnitureOptions{"cow"});
  ASSERT_EQ(crowded, std::vector<int>{0});
  for (Vec2 p : furniture_points(sheets[0]))
    EXPECT_GT(p.y, 287) << "in the bottom margin";
  bool number = false;
  for (const Text& t : sheets[0].texts)
    number = number || t.text == "1/1  cow";
  EXPECT_TRUE(number);
}

namespace {
// An A4 sheet whose part fills the printable area but for a `gap` x `gap` mm notch at its bottom-right.
Sheet a4_full_but_a_corner(double gap) {
  return a4_with_part(
      {{10, 10}, {200, 10}, {200, 287 - gap}, {200 - gap, 287 - gap}, {200 - gap, 287}, {10, 287}});
}

bool has_square(const Sheet& s) {
  return std::any_of(s.paths.begin(), s.paths.end(), [](const Path& p) {
    return p.role == PathRole::Sheet && p.closed && p.points_mm.size() == 4 &&
           std::abs(std::abs(signed_area(p.points_mm)) - 25.4 * 25.4) < 1e-6;
  });
}
}  // namespace

TEST(Furniture, ASheetTooFullForTheBlockGetsTheSquareInASmallerGapAndItsHeadingInTheMargin) {
  std::vector<Sheet> sheets{a4_full_but_a_corner(32), a4_with_part({{10, 10}, {50, 10}, {50, 50}})};
  const auto crowded = add_sheet_furniture(sheets, {}, FurnitureOptions{"cow"});
  EXPECT_TRUE(crowded.empty()) << "both sheets have their square";
  ASSERT_TRUE(has_square(sheets[0]));
  for (const Path& p : sheets[0].paths) {
    if (p.role != PathRole::Sheet || !p.closed) continue;
    for (Vec2 v : p.points_mm)
      EXPECT_TRUE(v.x >= 168 - 1e-9 && v.y >= 255 - 1e-9) << "the square is in the notch";
  }
  bool heading_in_margin = false;
  for (const Text& t : sheets[0].texts)
    heading_in_margin = heading_in_margin || (t.text == "1/2  cow" && t.at_mm.y > 287);
  EXPECT_TRUE(heading_in_margin);
  // No room for the legend beside the square: one row in the top margin of the first sheet.
  EXPECT_TRUE(sheets[0].legend_in_row);
  EXPECT_LE(sheets[0].legend_mm.max.y, sheets[0].printable_mm.min.y);
  EXPECT_GE(sheets[0].legend_mm.min.y, 0);
  EXPECT_TRUE(sheets[1].legend_mm.empty()) << "one legend";
}

TEST(Furniture, ANotchTooSmallForTheSquareLeavesTheSheetReported) {
  std::vector<Sheet> sheets{a4_full_but_a_corner(20)};
  EXPECT_EQ(add_sheet_furniture(sheets, {}, FurnitureOptions{}), std::vector<int>{0});
  EXPECT_FALSE(has_square(sheets[0]));
}

TEST(Furniture, WithAMarginTooShallowForTheHeadingItStandsAboveTheSquare) {
  Sheet s = a4_full_but_a_corner(60);
  s.printable_mm = Box2{{3, 3}, {207, 294}};  // 3 mm margins: no room for a line of text below
  s.paths.front().points_mm = {{3, 3}, {207, 3}, {207, 234}, {147, 234}, {147, 294}, {3, 294}};
  std::vector<Sheet> sheets{s};
  EXPECT_TRUE(add_sheet_furniture(sheets, {}, FurnitureOptions{"cow"}).empty());
  bool heading = false;
  for (const Text& t : sheets[0].texts)
    heading = heading || (t.text == "1/1  cow" && t.at_mm.y < 294 && t.at_mm.x > 147);
  EXPECT_TRUE(heading) << "in the notch, with the square";
  EXPECT_TRUE(has_square(sheets[0]));
}

TEST(Furniture, AFullFirstSheetWhoseTopMarginIsTooShallowLeavesTheLegendToTheNextSheet) {
  Sheet full = a4_full_but_a_corner(32);
  full.printable_mm = Box2{{10, 4}, {200, 287}};  // 4 mm at the top: no room for a row of 4 mm text
  full.paths.front().points_mm = {{10, 4}, {200, 4}, {200, 255}, {168, 255}, {168, 287}, {10, 287}};
  std::vector<Sheet> sheets{full, a4_with_part({{10, 10}, {50, 10}, {50, 50}})};
  add_sheet_furniture(sheets, {}, FurnitureOptions{});
  EXPECT_TRUE(sheets[0].legend_mm.empty());
  EXPECT_FALSE(sheets[1].legend_mm.empty());
  EXPECT_FALSE(sheets[1].legend_in_row) << "stacked in the block of the next sheet";
}

TEST(Furniture, ALongPartsLineInTheMarginKeepsClearOfTheHeading) {
  Sheet full = a4_with_part({{10, 10}, {200, 10}, {200, 287}, {10, 287}});
  // Every other letter: thirteen parts that no range shortens.
  for (int rank = 0; rank < 26; rank += 2)
    full.texts.push_back(Text{piece_letter(rank), {100, 100}, 5, 0, PathRole::Piece, rank});
  std::vector<Sheet> sheets{full};
  add_sheet_furniture(sheets, {}, FurnitureOptions{"a model with a long name"});
  const Text* heading = nullptr;
  const Text* parts = nullptr;
  for (const Text& t : sheets[0].texts) {
    if (t.text.starts_with("1/1")) heading = &t;
    if (t.text.starts_with("parts A, C")) parts = &t;
  }
  ASSERT_NE(heading, nullptr);
  ASSERT_NE(parts, nullptr);
  EXPECT_GE(parts->height_mm, 2.0) << "never below the least legible size";
  // "1/1  a model with a long name" in DejaVu Sans at 3 mm cap height is about 61 mm long.
  const bool beside = parts->at_mm.y > 287 && parts->at_mm.x - heading->at_mm.x >= 60;
  const bool above = parts->at_mm.y < 10;
  EXPECT_TRUE(beside || above) << parts->at_mm.x << " " << parts->at_mm.y;
}
