// Glue tabs: trapezoids outside their edge, one per seam, never over their own piece or its other tabs.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "foldkit/layout/layout.hpp"
#include "foldkit/layout/polygon.hpp"
#include "foldkit/layout/tabs.hpp"
#include "foldkit/unfold/parts.hpp"
#include "layout_fixtures.hpp"
#include "zipper_fixture.hpp"

using namespace foldkit;
using namespace foldkit::layout;

TEST(Tabs, ATrapezoidLiesOutsideItsEdgeWithSlantedEnds) {
  const Polygon quad = tab_trapezoid({0, 0}, {10, 0}, 3, std::numbers::pi / 4, std::numbers::pi / 4);
  ASSERT_EQ(quad.size(), 4u);
  EXPECT_GT(signed_area(quad), 0) << "counter-clockwise";
  EXPECT_NEAR(quad[1].x, 3, 1e-9);
  EXPECT_NEAR(quad[1].y, -3, 1e-9) << "outside: to the right of a->b";
  EXPECT_NEAR(quad[2].x, 7, 1e-9);
  EXPECT_NEAR(signed_area(quad), 3 * (10 + 4) / 2.0, 1e-9);
}

TEST(Tabs, OnAShortEdgeTheTabNarrowsInsteadOfComingToAPoint) {
  const Polygon quad = tab_trapezoid({0, 0}, {4, 0}, 5, std::numbers::pi / 4, std::numbers::pi / 4);
  EXPECT_LT(std::fabs(quad[1].y), 2.0);
  EXPECT_GT(quad[2].x - quad[1].x, 0.3) << "the outer side keeps some length";
}

// The planner gives up on a stretch of edge when the narrowest tab of each slant meets something:
// that holds only because a narrower tab with the same slants lies inside a wider one.
TEST(Tabs, ANarrowerTabWithTheSameSlantsLiesInsideTheWiderOne) {
  const double slants[] = {0.3, std::numbers::pi / 4, std::numbers::pi / 3, 1.4};
  for (double length : {2.0, 6.0, 25.0})
    for (double slant_a : slants)
      for (double slant_b : slants) {
        const Polygon wide = tab_trapezoid({1, 2}, {1 + length * 0.6, 2 + length * 0.8}, 5, slant_a, slant_b);
        for (double w : {0.5, 1.0, 2.5, 4.0}) {
          const Polygon narrow =
              tab_trapezoid({1, 2}, {1 + length * 0.6, 2 + length * 0.8}, w, slant_a, slant_b);
          for (Vec2 p : narrow)
            EXPECT_TRUE(inside_convex(wide, p, -1e-9))
                << "length " << length << ", slants " << slant_a << " " << slant_b << ", width " << w;
        }
      }
}

TEST(Tabs, OnRealMeshesEachSeamHasAtMostOneTabAndNoneOverlapsItsPiece) {
  for (const char* name : {"spot_350.obj", "fish_350.obj", "penguin_500.obj"}) {
    const auto& ex = test::unfolded_example(name);
    const auto pieces = scaled_pieces(ex.unfolding, 160 / ex.unfolding.model_extent);
    const auto seams = find_seams(ex.unfolding, pieces);
    const TabPlan plan = plan_tabs(pieces, seams, TabOptions{});
    ASSERT_EQ(plan.tab_of_seam.size(), seams.size());
    std::vector<std::vector<Polygon>> body(pieces.size()), tabs(pieces.size());
    for (const ScaledPiece& p : pieces) {
      std::vector<Polygon> tris;
      for (const Triangle2& t : p.triangles_mm)
        tris.push_back({t[0], t[1], t[2]});
      body[p.index] = polygon_union(tris);
    }
    int placed = 0;
    for (std::size_t s = 0; s < seams.size(); ++s) {
      const auto& tab = plan.tab_of_seam[s];
      const bool dropped = std::find(plan.dropped.begin(), plan.dropped.end(), SeamId(static_cast<int>(s))) !=
                           plan.dropped.end();
      ASSERT_NE(tab.has_value(), dropped);
      if (!tab) continue;
      ++placed;
      EXPECT_EQ(tab->piece, seams[s].sides[tab->side].piece);
      EXPECT_GE(tab->width_mm, TabOptions{}.min_width_mm - 1e-9);
      EXPECT_LE(tab->width_mm, TabOptions{}.width_mm + 1e-9);
      const std::vector<Polygon> one = {tab->quad_mm};
      ASSERT_LT(intersection_area(one, body[tab->piece]), 1e-4)
          << name << ": tab of seam " << s << " covers its piece";
      for (const Polygon& other : tabs[tab->piece])
        ASSERT_LT(intersection_area(one, std::vector<Polygon>{other}), 1e-4) << name << ": tabs overlap";
      tabs[tab->piece].push_back(tab->quad_mm);
    }
    // Dropping is the last resort: a seam between two pieces always finds room on one side; only the
    // narrow notches and slits inside one piece (the MST baseline makes some) can lack it.
    for (SeamId s : plan.dropped)
      EXPECT_EQ(seams[s.index()].sides[0].piece, seams[s.index()].sides[1].piece)
          << name << ": seam " << s.index();
    EXPECT_GT(placed, 0.8 * seams.size()) << name;
  }
}

TEST(Tabs, NeighbouringSeamsAlongAnOutlineAlternateSides) {
  // The tetrahedron's outline pairs each seam with its neighbour: a b b^-1 c c^-1 a^-1 seen around the
  // big triangle. Every seam gets one tab, and no two tabs sit side by side on both halves of a zip.
  const auto ex = test::tetrahedron();
  const auto pieces = scaled_pieces(ex.unfolding, 30);
  const auto seams = find_seams(ex.unfolding, pieces);
  const TabPlan plan = plan_tabs(pieces, seams, TabOptions{});
  EXPECT_TRUE(plan.dropped.empty());
  ASSERT_EQ(pieces.size(), 1u);
  ASSERT_EQ(pieces[0].outline_mm.size(), 1u);
  const std::size_t n = pieces[0].outline_mm[0].size();
  ASSERT_EQ(n, 6u);
  std::vector<int> tabs_on_edge(n, 0);
  for (const auto& tab : plan.tab_of_seam) {
    ASSERT_TRUE(tab.has_value());
    tabs_on_edge[seams[tab->seam.index()].sides[tab->side].index] += 1;
  }
  // Walking round the outline, an edge with a tab is followed by one without: three of each, alternating.
  for (std::size_t i = 0; i < n; ++i)
    EXPECT_NE(tabs_on_edge[i], tabs_on_edge[(i + 1) % n]) << "outline edges " << i << " and " << (i + 1) % n;
}

using test::two_pieces_zipped_along_three_seams;
using test::Zipper;

TEST(Tabs, AlongAZipperBetweenTwoPiecesTheTabsChangeSidesFromSeamToSeam) {
  const Zipper z = two_pieces_zipped_along_three_seams();
  const TabPlan plan = plan_tabs(z.pieces, z.seams, TabOptions{});
  ASSERT_TRUE(plan.dropped.empty());
  std::vector<int> piece_of_tab;
  for (const auto& tab : plan.tab_of_seam) {
    ASSERT_TRUE(tab.has_value());
    EXPECT_NEAR(tab->width_mm, 4.5, 1e-9) << "room for a full tab (45% of 10 mm) on either side";
    piece_of_tab.push_back(tab->piece);
  }
  EXPECT_EQ(piece_of_tab, (std::vector<int>{0, 1, 0})) << "tab, no tab, tab along piece 0's edge";
}

namespace {

// A piece of one loop through `corners` (counter-clockwise), its outline edges numbered in order, made of
// the given triangles.
ScaledPiece piece_of(int index, const std::vector<Vec2>& corners, std::vector<Triangle2> triangles) {
  ScaledPiece p;
  p.index = index;
  OutlineLoop loop;
  for (std::size_t i = 0; i < corners.size(); ++i)
    loop.push_back({static_cast<int>(i), -1, -1, corners[i], corners[(i + 1) % corners.size()]});
  p.outline_mm = {loop};
  for (std::size_t k = 0; k < triangles.size(); ++k) {
    p.faces.push_back(static_cast<int>(k));
    p.area_mm2 += signed_area(triangles[k]);
  }
  p.triangles_mm = std::move(triangles);
  return p;
}

// A U of 30 x 30 mm open at the top (its bay 10 mm wide and 20 deep, outline edge 4 the bay's floor)
// and a 10 mm square, glued along the bay's floor and the square's bottom edge. sides[0] is the
// square's, so alternation alone would put the tab there, out past the square.
struct UAndSquare {
  std::vector<ScaledPiece> pieces;
  std::vector<Seam> seams;
};

UAndSquare u_and_square() {
  auto rect = [](double x0, double y0, double x1, double y1) {
    return std::vector<Triangle2>{Triangle2{Vec2{x0, y0}, Vec2{x1, y0}, Vec2{x1, y1}},
                                  Triangle2{Vec2{x0, y0}, Vec2{x1, y1}, Vec2{x0, y1}}};
  };
  std::vector<Triangle2> u = rect(0, 0, 30, 10);
  for (const std::vector<Triangle2>& arm : {rect(0, 10, 10, 30), rect(20, 10, 30, 30)})
    u.insert(u.end(), arm.begin(), arm.end());
  UAndSquare s;
  s.pieces.push_back(
      piece_of(0, {{0, 0}, {30, 0}, {30, 30}, {20, 30}, {20, 10}, {10, 10}, {10, 30}, {0, 30}}, u));
  s.pieces.push_back(piece_of(1, {{0, 0}, {10, 0}, {10, 10}, {0, 10}}, rect(0, 0, 10, 10)));
  Seam seam;
  seam.edge = 0;
  seam.sides = {SeamSide{1, 0, 0}, SeamSide{0, 0, 4}};
  s.seams.push_back(seam);
  return s;
}

}  // namespace

TEST(Tabs, BetweenTwoPiecesTheTabGoesIntoABayRatherThanOutPastTheOtherPiece) {
  const UAndSquare s = u_and_square();
  const TabPlan plan = plan_tabs(s.pieces, s.seams, TabOptions{});
  ASSERT_TRUE(plan.tab_of_seam[0].has_value());
  EXPECT_EQ(plan.tab_of_seam[0]->piece, 0) << "the tab on the U's bay floor";
  // The tab stays inside the bay, clear of the U's arms.
  for (Vec2 corner : plan.tab_of_seam[0]->quad_mm) {
    EXPECT_GE(corner.x, 10 - 1e-9);
    EXPECT_LE(corner.x, 20 + 1e-9);
    EXPECT_GE(corner.y, 10 - 1e-9);
  }
  TabOptions alternate_only;
  alternate_only.into_bays = false;
  const TabPlan alternated = plan_tabs(s.pieces, s.seams, alternate_only);
  ASSERT_TRUE(alternated.tab_of_seam[0].has_value());
  EXPECT_EQ(alternated.tab_of_seam[0]->piece, 1) << "without the rule the first side, out past the square";
}

TEST(Tabs, TheWidthsTriedNarrowFromTheEdgesShareDownToTheLeast) {
  const TabOptions o;
  const std::vector<double> on_long = tab_widths_to_try(100, o);
  ASSERT_FALSE(on_long.empty());
  EXPECT_DOUBLE_EQ(on_long.front(), o.width_mm);
  EXPECT_DOUBLE_EQ(on_long.back(), o.min_width_mm);
  for (std::size_t i = 1; i < on_long.size(); ++i)
    EXPECT_LT(on_long[i], on_long[i - 1]);
  EXPECT_DOUBLE_EQ(tab_widths_to_try(6, o).front(), o.width_per_length * 6) << "a short edge, a narrow tab";
  EXPECT_EQ(tab_widths_to_try(1, o), std::vector<double>{o.min_width_mm}) << "never below the least width";
}

TEST(Tabs, ATabWantedForItsLabelIsAsWideAsTheLabelWhereItsEdgeAloneWouldMakeItNarrower) {
  const auto& ex = test::unfolded_example("spot_350.obj");
  // Small: many edges shorter than a label-wide tab needs.
  const auto pieces = scaled_pieces(ex.unfolding, 90 / ex.unfolding.model_extent);
  const auto seams = find_seams(ex.unfolding, pieces);
  const std::vector<int> wanted(seams.size(), 0);
  TabOptions o;
  o.label_width_mm = 2.6;
  // Tabs on the wanted side of edges whose share (width_per_length) is less than the label needs.
  const auto label_wide_share = [&](const TabOptions& options) {
    const TabPlan plan = plan_tabs(pieces, seams, options, {}, wanted);
    int short_edges = 0, label_wide = 0;
    for (const auto& tab : plan.tab_of_seam) {
      if (!tab || tab->side != 0) continue;
      if (options.width_per_length * norm(tab->quad_mm[3] - tab->quad_mm[0]) >= o.label_width_mm) continue;
      ++short_edges;
      label_wide += tab->width_mm >= o.label_width_mm - 1e-9;
    }
    return std::pair(label_wide, short_edges);
  };
  const auto [wide, short_edges] = label_wide_share(o);
  ASSERT_GT(short_edges, 20);
  EXPECT_GT(wide, short_edges / 2) << wide << " of " << short_edges;
  TabOptions plain = o;
  plain.label_width_mm = 0;
  EXPECT_LT(label_wide_share(plain).first, short_edges / 10) << "without the floor they stay narrow";
}

namespace {

// One piece whose outline runs through `corners`, edge i from corner i to the next.
std::vector<ScaledPiece> piece_with_outline(const std::vector<Vec2>& corners) {
  ScaledPiece p;
  p.index = 0;
  OutlineLoop loop;
  for (std::size_t i = 0; i < corners.size(); ++i)
    loop.push_back({static_cast<int>(i), -1, -1, corners[i], corners[(i + 1) % corners.size()]});
  p.outline_mm = {loop};
  return {p};
}

}  // namespace

TEST(Tabs, ASeamWhoseSidesMeetAtANarrowMouthIsASlit) {
  // A notch cut into a piece's outline: edge 1 runs into the tip at (5, 10), edge 2 back out.
  auto notch = [](double mouth_mm) {
    return piece_with_outline(
        {{0, 0}, {5 - 0.5 * mouth_mm, 0}, {5, 10}, {5 + 0.5 * mouth_mm, 0}, {10, 0}, {10, 20}, {0, 20}});
  };
  Seam seam;
  seam.sides = {SeamSide{0, 0, 1}, SeamSide{0, 0, 2}};
  EXPECT_TRUE(is_narrow_slit(notch(1), seam, TabOptions{}));
  EXPECT_FALSE(is_narrow_slit(notch(6), seam, TabOptions{})) << "a wide notch takes a tab";
  seam.sides = {SeamSide{0, 0, 1}, SeamSide{0, 0, 4}};
  EXPECT_FALSE(is_narrow_slit(notch(1), seam, TabOptions{})) << "sides that are not neighbours";
}

TEST(Tabs, TwoSidesFacingEachOtherCloserThanATabAlongTheWholeEdgeAreASlitToo) {
  // A slot cut down into a piece from its top: edge 3 runs down its right side, edge 5 up its left.
  auto slot = [](double width_mm) {
    const double left = 5 - 0.5 * width_mm, right = 5 + 0.5 * width_mm;
    return piece_with_outline(
        {{0, 0}, {10, 0}, {10, 20}, {right, 20}, {right, 5}, {left, 5}, {left, 20}, {0, 20}});
  };
  Seam seam;
  seam.sides = {SeamSide{0, 0, 3}, SeamSide{0, 0, 5}};
  EXPECT_TRUE(is_narrow_slit(slot(1), seam, TabOptions{})) << "1 mm apart from end to end";
  EXPECT_FALSE(is_narrow_slit(slot(4), seam, TabOptions{})) << "a wide slot takes a tab";
}

// The default unfolding (one search piece, split to fit A4 at 150 mm) leaves few seams without a tab.
// Most of those left are slits: both sides meet at a vertex of small angular defect, and even at the
// slit's mouth the gap is narrower than the narrowest tab; no tab shape fits there.
TEST(Tabs, OnTheDefaultUnfoldingOfRealExamplesFewTabsAreDropped) {
  for (const char* name : {"spot_350.obj", "fish_350.obj", "penguin_500.obj"}) {
    const auto& ex = test::unfolded_example(name, unfold::Method::Search);
    LayoutOptions o;
    o.size_mm = 150;
    unfold::PartOptions parts;
    parts.room_mm = piece_room_mm(o);
    parts.mm_per_unit = 150 / ex.unfolding.model_extent;
    const unfold::PartsResult split = unfold::split_into_parts(ex.mesh, ex.unfolding, parts);
    const auto pieces = scaled_pieces(split.unfolding, 150 / split.unfolding.model_extent);
    const auto seams = find_seams(split.unfolding, pieces);
    const TabPlan plan = plan_tabs(pieces, seams, TabOptions{});
    int slits = 0;
    for (SeamId s : plan.dropped)
      slits += is_narrow_slit(pieces, seams[s.index()], TabOptions{});
    const double all = static_cast<double>(plan.dropped.size()) / seams.size();
    const double others = static_cast<double>(plan.dropped.size() - slits) / seams.size();
    std::printf("%s: %zu seams, %zu dropped (%.1f%%), %d of them slits; others %.1f%%\n", name, seams.size(),
                plan.dropped.size(), 100 * all, slits, 100 * others);
    EXPECT_LT(all, 0.25) << name;
    EXPECT_LT(others, 0.08) << name;
  }
}

TEST(Tabs, ASplitTabPutsOneLabelWideHalfOnEachSideAlongOppositeHalvesOfTheEdge) {
  const auto& ex = test::unfolded_example("spot_350.obj");
  const auto pieces = scaled_pieces(ex.unfolding, 160 / ex.unfolding.model_extent);
  const auto seams = find_seams(ex.unfolding, pieces);
  const std::vector<int> wanted(seams.size(), kSplitTab);
  TabOptions o;
  o.label_width_mm = 2.6;
  const TabPlan plan = plan_tabs(pieces, seams, o, {}, wanted);
  int split = 0;
  for (std::size_t s = 0; s < seams.size(); ++s) {
    if (!plan.is_split(s)) continue;
    ++split;
    const Tab* halves[2] = {plan.on_side(s, 0), plan.on_side(s, 1)};
    ASSERT_TRUE(halves[0] && halves[1]) << "seam " << s;
    int from_starts = 0;
    for (int k = 0; k < 2; ++k) {
      const SeamSide& at = seams[s].sides[k];
      const OutlineEdge& e = pieces[at.piece].outline_mm[at.loop][at.index];
      const Vec2 base_a = halves[k]->quad_mm[0], base_b = halves[k]->quad_mm[3];
      EXPECT_GE(halves[k]->width_mm, o.label_width_mm * 0.95 - 1e-9);
      // Each side's half starts at its edge's start or ends at its end.
      const bool from_start = norm(base_a - e.a) < 1e-9;
      EXPECT_TRUE(from_start || norm(base_b - e.b) < 1e-9) << "seam " << s;
      EXPECT_NEAR(norm(base_b - base_a), 0.5 * norm(e.b - e.a), 1e-6);
      from_starts += from_start ? 1 : 0;
    }
    // The sides run opposite ways: both from their starts (or both to their ends) is opposite halves.
    EXPECT_NE(from_starts, 1) << "seam " << s << ": the halves lie along opposite halves of the edge";
  }
  EXPECT_GT(split, static_cast<int>(seams.size()) / 2) << split << " of " << seams.size();
  // Every tab, halves included, stays clear of the others in its piece.
  const std::vector<const Tab*> all = plan.all();
  for (std::size_t i = 0; i < all.size(); ++i)
    for (std::size_t j = i + 1; j < all.size(); ++j) {
      if (all[i]->piece != all[j]->piece) continue;
      const std::vector<Polygon> a{all[i]->quad_mm}, b{all[j]->quad_mm};
      ASSERT_LT(intersection_area(a, b), 1e-4)
          << "seams " << all[i]->seam.index() << " and " << all[j]->seam.index();
    }
}
