// Tabs grown after packing: a seam takes the tabs wanted for its labels only where the packed sheet has
// room for all of them, never loses its tab, and keeps the packing's spacing from everything else.
#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "foldkit/layout/tabs.hpp"
#include "foldkit/layout/tabs_in_place.hpp"
#include "zipper_fixture.hpp"

using namespace foldkit;
using namespace foldkit::layout;

namespace {

// The zipper packed: piece 1 at the origin and piece 0 100 mm above it, both on sheet 0.
struct PackedZipper {
  std::vector<ScaledPiece> pieces;
  std::vector<Seam> seams;
  std::vector<std::vector<Polygon>> bodies;
  std::vector<PackPlacement> placements;
  TabPlan placed;  // the planner's own: on pieces 0, 1, 0
  TabPlan wanted;  // every seam's tab on the other side: on pieces 1, 0, 1
};

PackedZipper zipper_packed_apart() {
  test::Zipper zipper = test::two_pieces_zipped_along_three_seams();
  PackedZipper z;
  z.pieces = std::move(zipper.pieces);
  z.seams = std::move(zipper.seams);
  for (const ScaledPiece& p : z.pieces) {
    z.bodies.emplace_back();
    for (const Triangle2& t : p.triangles_mm)
      z.bodies.back().push_back({t[0], t[1], t[2]});
  }
  z.placements = {PackPlacement{0, Rigid2{0, {0, 100}}}, PackPlacement{0, Rigid2{0, {0, 0}}}};
  z.placed = plan_tabs(z.pieces, z.seams, TabOptions{});
  const std::vector<int> other_sides{1, 0, 1};
  z.wanted = plan_tabs(z.pieces, z.seams, TabOptions{}, {}, other_sides);
  return z;
}

PackedRoom room_of(const PackedZipper& z, std::span<const std::pair<int, Polygon>> others,
                   double spacing_mm) {
  return PackedRoom{z.placements, z.bodies, others, Box2{{-50, -50}, {200, 200}}, {}, spacing_mm};
}

// The piece carrying each seam's one tab.
std::vector<int> tab_pieces(const TabPlan& plan) {
  std::vector<int> pieces;
  for (const auto& tab : plan.tab_of_seam)
    pieces.push_back(tab ? tab->piece : -1);
  return pieces;
}

Polygon box(Vec2 lo, Vec2 hi) {
  return {lo, {hi.x, lo.y}, hi, {lo.x, hi.y}};
}

}  // namespace

TEST(TabsInPlace, WithRoomAroundThePiecesEverySeamTakesTheTabItWants) {
  const PackedZipper z = zipper_packed_apart();
  const TabPlan& placed = z.placed;
  const TabPlan& wanted = z.wanted;
  ASSERT_EQ(tab_pieces(placed), (std::vector<int>{0, 1, 0}));
  ASSERT_EQ(tab_pieces(wanted), (std::vector<int>{1, 0, 1}));
  const TabPlan mixed = tabs_in_place(z.seams, placed, wanted, room_of(z, {}, 2));
  EXPECT_EQ(tab_pieces(mixed), tab_pieces(wanted));
  for (std::size_t s = 0; s < z.seams.size(); ++s)
    EXPECT_EQ(mixed.tab_of_seam[s]->quad_mm, wanted.tab_of_seam[s]->quad_mm);
  EXPECT_TRUE(mixed.dropped.empty());
}

TEST(TabsInPlace, ASeamWhoseWantedTabWouldComeTooCloseToAnotherPartKeepsItsOwn) {
  const PackedZipper z = zipper_packed_apart();
  const TabPlan& placed = z.placed;
  const TabPlan& wanted = z.wanted;
  // Seam 1's wanted tab hangs 4.5 mm below piece 0 (bottom at y = 100), over x 10..20: another packed
  // shape ends 1.5 mm below the tab's outer side.
  const std::vector<std::pair<int, Polygon>> below{{0, box({12, 90}, {18, 94})}};
  const TabPlan roomy = tabs_in_place(z.seams, placed, wanted, room_of(z, below, 1));
  EXPECT_EQ(tab_pieces(roomy), (std::vector<int>{1, 0, 1})) << "1.5 mm is room enough at 1 mm spacing";
  const TabPlan tight = tabs_in_place(z.seams, placed, wanted, room_of(z, below, 2));
  EXPECT_EQ(tab_pieces(tight), (std::vector<int>{1, 1, 1})) << "at 2 mm seam 1 keeps its tab on piece 1";
  EXPECT_EQ(tight.tab_of_seam[1]->quad_mm, placed.tab_of_seam[1]->quad_mm);
  EXPECT_TRUE(tight.dropped.empty());
}

TEST(TabsInPlace, ATabStaysInsideTheAreaAndOutOfItsKeepOutZones) {
  const PackedZipper z = zipper_packed_apart();
  const TabPlan& placed = z.placed;
  const TabPlan& wanted = z.wanted;
  // Seams 0 and 2 want their tabs above piece 1 (top at y = 10): an area ending at y = 12 has no room.
  PackedRoom room = room_of(z, {}, 2);
  room.area_mm = Box2{{-50, -50}, {200, 12}};
  const std::vector<PackPlacement> placements{{0, Rigid2{0, {100, -40}}}, {0, Rigid2{0, {0, 0}}}};
  room.placements = placements;
  EXPECT_EQ(tab_pieces(tabs_in_place(z.seams, placed, wanted, room)), (std::vector<int>{0, 0, 0}));
  // The same room but for a keep-out zone over piece 0's underside: seam 1 cannot move there either.
  room.area_mm = Box2{{-50, -50}, {200, 200}};
  const std::vector<Box2> zone{Box2{{100, -50}, {130, -45}}};
  room.keep_out_mm = zone;
  EXPECT_EQ(tab_pieces(tabs_in_place(z.seams, placed, wanted, room)), (std::vector<int>{1, 1, 1}));
}

TEST(TabsInPlace, ASeamIsNeverLeftWithoutATabForOneWithout) {
  const PackedZipper z = zipper_packed_apart();
  const TabPlan& placed = z.placed;
  TabPlan wanted = placed;
  wanted.tab_of_seam[1].reset();
  wanted.dropped = {SeamId(1)};
  const TabPlan mixed = tabs_in_place(z.seams, placed, wanted, room_of(z, {}, 2));
  EXPECT_EQ(tab_pieces(mixed), tab_pieces(placed));
  EXPECT_TRUE(mixed.dropped.empty());
}

TEST(TabsInPlace, ALabelStickingOutOfItsPieceMustKeepClearOfTheOthers) {
  const PackedZipper z = zipper_packed_apart();
  const TabPlan& placed = z.placed;
  const PackedRoom room = room_of(z, {}, 2);
  // Piece 1's frame: a label box 3 mm above its top edge (y = 10) is far from piece 0 (y >= 100 - 4.5)
  // but one reaching y = 95 comes within the spacing of piece 0's tabs.
  const std::vector<std::pair<int, Polygon>> near{{1, box({22, 20}, {28, 23})}};
  EXPECT_TRUE(clear_in_place(near, z.seams, placed, room));
  const std::vector<std::pair<int, Polygon>> close{{1, box({2, 90}, {8, 94.5})}};
  EXPECT_FALSE(clear_in_place(close, z.seams, placed, room));
}
