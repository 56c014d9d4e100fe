// Edge numbers: unique per seam, on both sides, legible, clear of each other.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>

#include "foldkit/layout/edge_numbers.hpp"
#include "foldkit/layout/label_text.hpp"
#include "foldkit/layout/layout.hpp"
#include "layout_fixtures.hpp"

using namespace foldkit;
using namespace foldkit::layout;

namespace {

// Each piece's fold lines, which labels keep clear of.
std::vector<std::vector<FoldLine>> folds_of(const unfold::Unfolding& u,
                                            const std::vector<ScaledPiece>& pieces) {
  std::vector<std::vector<FoldLine>> folds;
  for (const ScaledPiece& p : pieces)
    folds.push_back(fold_lines(u, p));
  return folds;
}

// The label "12" of the one seam of `seams`, placed among `folds`, where it is the one label placed and
// found a spot clear of lines (beside its edge or on a leader); else none.
std::optional<Label> lone_clear_label(const std::vector<ScaledPiece>& pieces, const std::vector<Seam>& seams,
                                      const std::vector<std::vector<FoldLine>>& folds,
                                      const LabelOptions& o) {
  std::vector<Label> labels = place_labels(pieces, seams, std::vector<int>{12}, TabPlan{}, folds, {}, o);
  if (labels.size() != 1 || labels.front().crowded || labels.front().over_fold) return std::nullopt;
  return std::move(labels.front());
}

}  // namespace

TEST(EdgeNumbers, SeamsAreNumberedOneToNOnce) {
  const auto& ex = test::unfolded_example("fish_350.obj");
  const auto pieces = scaled_pieces(ex.unfolding, 1);
  const auto seams = find_seams(ex.unfolding, pieces);
  auto numbers = number_seams(pieces, seams);
  std::sort(numbers.begin(), numbers.end());
  for (std::size_t i = 0; i < numbers.size(); ++i)
    ASSERT_EQ(numbers[i], static_cast<int>(i) + 1);
}

TEST(EdgeNumbers, BothSidesOfEverySeamAreLabelledLegiblyAndLabelsDoNotOverlap) {
  for (const char* name : {"spot_350.obj", "bob_350.obj"}) {
    const auto& ex = test::unfolded_example(name);
    const auto pieces = scaled_pieces(ex.unfolding, 180 / ex.unfolding.model_extent);
    const auto seams = find_seams(ex.unfolding, pieces);
    const auto numbers = number_seams(pieces, seams);
    const TabPlan tabs = plan_tabs(pieces, seams, TabOptions{});
    const auto folds = folds_of(ex.unfolding, pieces);
    LabelOptions o;
    const auto labels = place_labels(pieces, seams, numbers, tabs, folds, {}, o);
    ASSERT_EQ(labels.size(), 2 * seams.size());
    std::vector<int> sides(seams.size(), 0);
    int on_tabs = 0, crowded = 0;
    for (const Label& l : labels) {
      EXPECT_EQ(l.text, number_text(numbers[l.seam.index()]));
      EXPECT_GE(l.height_mm, o.min_mm - 1e-9);
      EXPECT_LE(l.height_mm, o.max_mm + 1e-9);
      sides[l.seam.index()] |= 1 << l.side;
      const auto& tab = tabs.tab_of_seam[l.seam.index()];
      if (l.on_tab) {
        ++on_tabs;
        ASSERT_TRUE(tab && tab->side == l.side) << "a label on a tab only where that side has the tab";
      }
      crowded += l.crowded;
    }
    for (int s : sides)
      EXPECT_EQ(s, 3);
    EXPECT_GT(on_tabs, static_cast<int>(seams.size()) / 2) << name << ": most tabs carry their number";
    EXPECT_LT(crowded, static_cast<int>(labels.size()) / 20) << name;
    for (std::size_t i = 0; i < labels.size(); ++i)
      for (std::size_t j = i + 1; j < labels.size(); ++j) {
        if (labels[i].piece != labels[j].piece || labels[i].crowded || labels[j].crowded) continue;
        ASSERT_FALSE(convex_overlap(labels[i].box_mm, labels[j].box_mm, 1e-9))
            << name << ": labels " << labels[i].text << " and " << labels[j].text << " overlap";
      }
  }
}

TEST(EdgeNumbers, ALabelInsideAPieceReadsAlongItsEdgeWithItsFootTowardsIt) {
  const auto ex = test::tetrahedron();
  const auto pieces = scaled_pieces(ex.unfolding, 40);
  const auto seams = find_seams(ex.unfolding, pieces);
  const auto labels =
      place_labels(pieces, seams, number_seams(pieces, seams), TabPlan{}, {}, {}, LabelOptions{});
  ASSERT_EQ(labels.size(), 6u);
  for (const Label& l : labels) {
    const OutlineEdge& e = pieces[0].outline_mm[0][seams[l.seam.index()].sides[l.side].index];
    const Vec2 along = normalized(e.b - e.a);
    EXPECT_NEAR(dot(l.dir, along), 1, 1e-9);
    // The foot is a small gap inside the edge.
    const double foot = cross(along, l.at_mm - e.a);
    EXPECT_GT(foot, 0);
    EXPECT_LT(foot, 2.0);
    EXPECT_FALSE(l.crowded);
  }
}

namespace {
// One counter-clockwise triangle a, b, c as a piece whose base a-b is glued to another part.
struct OneTriangle {
  std::vector<ScaledPiece> pieces;
  std::vector<Seam> seams;
};
OneTriangle one_triangle_glued_at_its_base(Vec2 a, Vec2 b, Vec2 c) {
  ScaledPiece piece;
  piece.index = 0;
  piece.faces = {0};
  piece.triangles_mm = {Triangle2{a, b, c}};
  piece.outline_mm = {{OutlineEdge{0, 0, 0, a, b}, OutlineEdge{1, 0, 1, b, c}, OutlineEdge{2, 0, 2, c, a}}};
  piece.area_mm2 = std::fabs(signed_area(piece.triangles_mm[0]));
  Seam seam;
  seam.edge = 0;
  seam.sides = {SeamSide{0, 0, 0}, SeamSide{}};
  return {{piece}, {seam}};
}
}  // namespace

TEST(EdgeNumbers, ANeedleFaceTooNarrowAlongItsShortEdgeGetsItsLabelAcrossItClearOfEveryLine) {
  // One needle triangle, 3 mm at its glued base, 30 mm tall: "12" at 2 mm (2.8 mm wide) does not fit
  // along the base, 2.75 mm above it, where the face is 2.7 mm wide; across the base it does.
  const auto [pieces, seams] = one_triangle_glued_at_its_base({0, 0}, {3, 0}, {1.5, 30});
  const std::vector<int> numbers{12};
  LabelOptions o;
  o.min_mm = 2;
  const auto labels = place_labels(pieces, seams, numbers, TabPlan{}, {}, {}, o);
  ASSERT_EQ(labels.size(), 1u);
  const Label& l = labels.front();
  EXPECT_NEAR(dot(l.dir, Vec2{0, 1}), 1, 1e-9) << "reads away from the base, into the face";
  EXPECT_FALSE(l.crowded);
  EXPECT_FALSE(l.over_fold);
  EXPECT_DOUBLE_EQ(l.height_mm, 2);
  for (Vec2 corner : l.box_mm)
    EXPECT_TRUE(inside_convex(pieces[0].triangles_mm[0], corner, 0)) << corner.x << " " << corner.y;
}

TEST(EdgeNumbers, ANeedleFaceCrossedByAFoldStillGetsItsLabelAcrossItRatherThanOverItsOutline) {
  // The needle above with a fold line across it 2 mm above the base (as where the face meets the next
  // one): across the base the label crosses the fold, along the base it runs into the outline. Crossing
  // a fold is the lesser harm: the label reads across the face, not crowded against the cut line.
  const auto [pieces, seams] = one_triangle_glued_at_its_base({0, 0}, {3, 0}, {1.5, 30});
  const std::vector<std::vector<FoldLine>> folds{{FoldLine{PathRole::Valley, {0.1, 2}, {2.9, 2}, 7}}};
  LabelOptions o;
  o.min_mm = 2;
  o.leader_reach_mm = 0;  // with leaders it stands off beyond the fold (the test below)
  const auto labels = place_labels(pieces, seams, std::vector<int>{12}, TabPlan{}, folds, {}, o);
  ASSERT_EQ(labels.size(), 1u);
  const Label& l = labels.front();
  EXPECT_FALSE(l.crowded);
  EXPECT_TRUE(l.over_fold);
  EXPECT_NEAR(dot(l.dir, Vec2{0, 1}), 1, 1e-9) << "reads away from the base, into the face";
  for (Vec2 corner : l.box_mm)
    EXPECT_TRUE(inside_convex(pieces[0].triangles_mm[0], corner, 0)) << corner.x << " " << corner.y;
}

TEST(EdgeNumbers, ALabelOnALeaderReadsAcrossItsEdgeWhereOnlyThatWayFitsClear) {
  // The needle with the fold 2 mm above its base: no spot beside the base and none across the face below
  // the fold. Beyond the fold the needle is too narrow for "12" along the base, not across it.
  const auto [pieces, seams] = one_triangle_glued_at_its_base({0, 0}, {3, 0}, {1.5, 30});
  const std::array<Vec2, 2> fold{Vec2{0.1, 2}, Vec2{2.9, 2}};
  const std::vector<std::vector<FoldLine>> folds{{FoldLine{PathRole::Valley, fold[0], fold[1], 7}}};
  LabelOptions o;
  o.min_mm = 2;
  const auto labels = place_labels(pieces, seams, std::vector<int>{12}, TabPlan{}, folds, {}, o);
  ASSERT_EQ(labels.size(), 1u);
  const Label& l = labels.front();
  EXPECT_FALSE(l.crowded);
  EXPECT_FALSE(l.over_fold);
  ASSERT_EQ(l.leader_mm.size(), 2u) << "a leader and the bar along the base";
  EXPECT_NEAR(std::fabs(dot(l.dir, Vec2{0, 1})), 1, 1e-9) << "reads along the needle, across the base";
  EXPECT_FALSE(convex_overlap(l.box_mm, fold, -o.tight_clearance_mm));
  for (Vec2 corner : l.box_mm)
    EXPECT_TRUE(inside_convex(pieces[0].triangles_mm[0], corner, 0)) << corner.x << " " << corner.y;
  EXPECT_LE(norm(l.leader_mm[0][1] - l.leader_mm[0][0]), o.leader_reach_mm);
}

TEST(EdgeNumbers, ALabelOnALeaderReadsAlongASlantedGapWhereNeitherWayOfItsEdgeFits) {
  // A needle leaning 0.75 rad (43 degrees) off upright over a 5 mm base, a fold across it 2 mm up:
  // beyond the fold it is under 5 mm wide, too narrow for "12" along the base or across it, and 3.6 mm
  // square to its lean.
  const auto [pieces, seams] = one_triangle_glued_at_its_base({0, 0}, {5, 0}, {39.76, 40});
  const std::array<Vec2, 2> fold{Vec2{2.1, 2}, Vec2{6.75, 2}};
  const std::vector<std::vector<FoldLine>> folds{{FoldLine{PathRole::Valley, fold[0], fold[1], 7}}};
  const LabelOptions o;
  const std::optional<Label> placed = lone_clear_label(pieces, seams, folds, o);
  ASSERT_TRUE(placed.has_value()) << "one label, clear of lines";
  const Label& l = *placed;
  ASSERT_EQ(l.leader_mm.size(), 2u);
  const double along_base = std::fabs(dot(l.dir, Vec2{1, 0}));
  EXPECT_GT(along_base, 0.3) << "not across the base";
  EXPECT_LT(along_base, 0.95) << "not along the base";
  LabelOptions quick = o;
  quick.leader_search = LeaderSearch::Quick;
  EXPECT_FALSE(lone_clear_label(pieces, seams, folds, quick).has_value())
      << "the quick search reads along or across the base only";
  EXPECT_FALSE(convex_overlap(l.box_mm, fold, -o.tight_clearance_mm));
  for (Vec2 corner : l.box_mm)
    EXPECT_TRUE(inside_convex(pieces[0].triangles_mm[0], corner, 0)) << corner.x << " " << corner.y;
}

TEST(EdgeNumbers, ALabelWithNoSpotAtTheFullClearanceKeepsTheTightOneBeforeCrossingAFold) {
  // The needle above with a fold across it 0.18 mm above where "12" across the base ends (3.1 mm): too
  // close for the 0.25 mm clearance, clear of the tight 0.12 mm one. The label stays off the fold, the
  // line's ink (0.1 mm either side) not touching the text; asked for no tight spot, it crosses the fold.
  const auto [pieces, seams] = one_triangle_glued_at_its_base({0, 0}, {3, 0}, {1.5, 30});
  const std::array<Vec2, 2> fold{Vec2{0.1, 3.28}, Vec2{2.9, 3.28}};
  const std::vector<std::vector<FoldLine>> folds{{FoldLine{PathRole::Valley, fold[0], fold[1], 7}}};
  LabelOptions o;
  const auto labels = place_labels(pieces, seams, std::vector<int>{12}, TabPlan{}, folds, {}, o);
  ASSERT_EQ(labels.size(), 1u);
  const Label& l = labels.front();
  EXPECT_FALSE(l.crowded);
  EXPECT_FALSE(l.over_fold);
  EXPECT_FALSE(convex_overlap(l.box_mm, fold, -o.tight_clearance_mm)) << "the tight clearance is kept";
  EXPECT_TRUE(convex_overlap(l.box_mm, fold, -o.clearance_mm)) << "no spot keeps the full clearance";
  for (Vec2 corner : l.box_mm)
    EXPECT_TRUE(inside_convex(pieces[0].triangles_mm[0], corner, 0)) << corner.x << " " << corner.y;

  o.tight_clearance_mm = o.clearance_mm;
  const auto without_tight = place_labels(pieces, seams, std::vector<int>{12}, TabPlan{}, folds, {}, o);
  ASSERT_EQ(without_tight.size(), 1u);
  EXPECT_TRUE(without_tight.front().over_fold);
}

TEST(EdgeNumbers, ALabelWhoseOnlySpotANeighbourTookGetsItWhenTheNeighbourCanMove) {
  // A 10 mm square of two faces, glued along its right edge (seam 0, labelled first) and its bottom edge
  // (seam 1), with part letters covering all but the bottom-right corner and the right edge's two ends.
  // Seam 0's label takes the lower end of its edge first, next to the one spot seam 1's label has
  // (beside the bottom edge, right of the letters); seam 0's label moves to the upper end and both are
  // clear. Left where it was, seam 1's label would be crowded against it.
  ScaledPiece square;
  square.index = 0;
  square.faces = {0, 1};
  const Vec2 a{0, 0}, b{10, 0}, c{10, 10}, d{0, 10};
  square.triangles_mm = {Triangle2{a, b, c}, Triangle2{a, c, d}};
  square.outline_mm = {{OutlineEdge{1, 0, 0, a, b}, OutlineEdge{0, 0, 1, b, c}, OutlineEdge{2, 1, 1, c, d},
                        OutlineEdge{3, 1, 2, d, a}}};
  square.area_mm2 = 100;
  const std::vector<ScaledPiece> pieces{square};
  std::vector<Seam> seams(2);
  seams[0].edge = 0;
  seams[0].sides = {SeamSide{0, 0, 1}, SeamSide{}};
  seams[1].edge = 1;
  seams[1].sides = {SeamSide{0, 0, 0}, SeamSide{}};
  auto rect = [](double x0, double y0, double x1, double y1) {
    return Polygon{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  };
  const std::vector<std::vector<Polygon>> taken{
      {rect(0, 2.7, 7, 10), rect(0, 0, 7.3, 2.7), rect(7, 4.2, 10, 6.5)}};
  const LabelOptions o;
  const auto labels = place_labels(pieces, seams, std::vector<int>{1, 2}, TabPlan{}, {}, {}, o, {}, taken);
  ASSERT_EQ(labels.size(), 2u);
  for (const Label& l : labels) {
    EXPECT_FALSE(l.crowded) << l.text;
    EXPECT_FALSE(l.over_fold) << l.text;
    for (const Polygon& area : taken[0])
      EXPECT_FALSE(convex_overlap(l.box_mm, area, -o.tight_clearance_mm)) << l.text;
  }
  EXPECT_FALSE(convex_overlap(labels[0].box_mm, labels[1].box_mm, -o.tight_clearance_mm));
  EXPECT_GT(labels[0].at_mm.y, 6.5) << "seam 0's label is at the upper end of its edge";
}

TEST(EdgeNumbers, ALabelWithoutAClearSpotCoversAsFewTextsAsItCan) {
  // A 7 mm triangle with two part letters standing side by side over its base: "12" at 2 mm (2.8 mm
  // wide) covers one of them wherever it goes beside the base, and both in the base's middle.
  const auto [pieces, seams] = one_triangle_glued_at_its_base({0, 0}, {7, 0}, {3.5, 6.06});
  const std::vector<int> numbers{12};
  const Polygon left{{0.8, 0}, {3.4, 0}, {3.4, 10}, {0.8, 10}},
      right{{3.6, 0}, {6.2, 0}, {6.2, 10}, {3.6, 10}};
  const std::vector<std::vector<Polygon>> taken{{left, right}};
  const auto labels = place_labels(pieces, seams, numbers, TabPlan{}, {}, {}, LabelOptions{}, {}, taken);
  ASSERT_EQ(labels.size(), 1u);
  const Label& l = labels.front();
  EXPECT_TRUE(l.crowded);
  EXPECT_LE(convex_overlap(l.box_mm, left, 0) + convex_overlap(l.box_mm, right, 0), 1);
  const Vec2 middle = l.at_mm + l.dir * (0.5 * label_width_mm(l.text, l.height_mm, LabelOptions{})) +
                      perp_ccw(l.dir) * (0.5 * l.height_mm);
  EXPECT_TRUE(inside_convex(pieces[0].triangles_mm[0], middle, 0)) << "the label's middle is on its face";
}

namespace {
// A 2 mm glued base a-b under a tiny face (1.2 mm high) that opens into three large ones: a fan around
// c, its four inner edges fold lines. Beside the base no label fits clear of them.
struct TinyFaceInAFan {
  std::vector<ScaledPiece> pieces;
  std::vector<Seam> seams;
  std::vector<std::vector<FoldLine>> folds;
};
// The large face's top edge d-e runs at y = 12 from `d_x` to `e_x`.
TinyFaceInAFan tiny_face_in_a_fan(double d_x = 5, double e_x = -3) {
  const Vec2 a{0, 0}, b{2, 0}, c{1, 1.2}, d{d_x, 12}, e{e_x, 12};
  ScaledPiece piece;
  piece.index = 0;
  piece.faces = {0, 1, 2, 3};
  piece.triangles_mm = {Triangle2{a, b, c}, Triangle2{b, d, c}, Triangle2{c, d, e}, Triangle2{a, c, e}};
  piece.outline_mm = {{OutlineEdge{0, 0, 0, a, b}, OutlineEdge{1, 1, 0, b, d}, OutlineEdge{2, 2, 1, d, e},
                       OutlineEdge{3, 3, 2, e, a}}};
  for (const Triangle2& t : piece.triangles_mm)
    piece.area_mm2 += std::fabs(signed_area(t));
  Seam seam;
  seam.edge = 0;
  seam.sides = {SeamSide{0, 0, 0}, SeamSide{}};
  std::vector<FoldLine> folds{FoldLine{PathRole::Valley, b, c, 4}, FoldLine{PathRole::Valley, c, d, 5},
                              FoldLine{PathRole::Mountain, c, e, 6}, FoldLine{PathRole::Valley, a, c, 7}};
  return {{piece}, {seam}, {folds}};
}
}  // namespace

TEST(EdgeNumbers, ALabelWithNoRoomBesideItsEdgeStandsOffClearWithALeaderToTheEdgesMiddle) {
  const auto [pieces, seams, folds] = tiny_face_in_a_fan();
  const LabelOptions o;
  const std::optional<Label> placed = lone_clear_label(pieces, seams, folds, o);
  ASSERT_TRUE(placed.has_value()) << "one label, clear of lines";
  const Label& l = *placed;
  EXPECT_DOUBLE_EQ(l.height_mm, o.min_mm);
  for (const FoldLine& f : folds[0])
    EXPECT_FALSE(convex_overlap(l.box_mm, std::array<Vec2, 2>{f.a, f.b}, -o.tight_clearance_mm));
  const Vec2 middle = (l.box_mm[0] + l.box_mm[2]) * 0.5;
  EXPECT_TRUE(inside_convex(pieces[0].triangles_mm[2], middle, 0)) << "in the large face above the tiny one";
  ASSERT_EQ(l.leader_mm.size(), 2u) << "a leader and its bar along the edge";
  const std::array<Vec2, 2>& leader = l.leader_mm[0];
  EXPECT_NEAR(norm(leader[0] - Vec2{1, o.gap_mm}), 0, 1e-9) << "starts just inside the base's middle";
  double to_box = 1e300;
  for (std::size_t i = 0; i < l.box_mm.size(); ++i) {
    const Vec2 p = l.box_mm[i], q = l.box_mm[(i + 1) % l.box_mm.size()], d = q - p;
    to_box =
        std::min(to_box, norm(leader[1] - (p + d * std::clamp(dot(leader[1] - p, d) / dot(d, d), 0.0, 1.0))));
  }
  EXPECT_NEAR(to_box, o.clearance_mm, 1e-6) << "ends just short of the label";
  EXPECT_LE(norm(leader[1] - leader[0]), o.leader_reach_mm);
  const std::array<Vec2, 2>& bar = l.leader_mm[1];
  EXPECT_NEAR(bar[0].y, o.gap_mm, 1e-9) << "the bar runs along the base";
  EXPECT_NEAR(bar[1].y, o.gap_mm, 1e-9);
  EXPECT_FALSE(convex_overlap(l.box_mm, leader, 0)) << "the leader does not run into its text";
}

TEST(EdgeNumbers, WithoutLeadersALabelWithNoRoomBesideItsEdgeCrossesAFoldThere) {
  const auto [pieces, seams, folds] = tiny_face_in_a_fan();
  LabelOptions o;
  o.leader_reach_mm = 0;
  const auto labels = place_labels(pieces, seams, std::vector<int>{12}, TabPlan{}, folds, {}, o);
  ASSERT_EQ(labels.size(), 1u);
  EXPECT_TRUE(labels.front().over_fold);
  EXPECT_TRUE(labels.front().leader_mm.empty());
}

TEST(EdgeNumbers, ALabelWithNoClearSpotAnywhereStandsOffAcrossFoldsRatherThanOverAnotherText) {
  // The tiny base with two tall part letters over it, a narrow way up between them, and the large face
  // above ruled by folds 2 mm apart: no spot is clear of lines, and every spot beside the base covers a
  // letter. On a leader up the way, the label crosses folds only.
  auto [pieces, seams, folds] = tiny_face_in_a_fan();
  for (double y = 4; y < 12; y += 2)
    folds[0].push_back(FoldLine{PathRole::Valley, {-3 * y / 12 + 0.2, y}, {1 + 4 * y / 12 - 0.2, y}, 8});
  const Polygon left{{-1.5, 0.6}, {0.7, 0.6}, {0.7, 6}, {-1.5, 6}},
      right{{1.3, 0.6}, {3.5, 0.6}, {3.5, 6}, {1.3, 6}};
  const std::vector<std::vector<Polygon>> taken{{left, right}};
  const LabelOptions o;
  const auto labels = place_labels(pieces, seams, std::vector<int>{12}, TabPlan{}, folds, {}, o, {}, taken);
  ASSERT_EQ(labels.size(), 1u);
  const Label& l = labels.front();
  EXPECT_TRUE(l.over_fold);
  EXPECT_FALSE(l.crowded);
  ASSERT_EQ(l.leader_mm.size(), 2u);
  EXPECT_FALSE(convex_overlap(l.box_mm, left, 0));
  EXPECT_FALSE(convex_overlap(l.box_mm, right, 0));
  for (const OutlineEdge& edge : pieces[0].outline_mm[0])
    EXPECT_FALSE(convex_overlap(l.box_mm, std::array<Vec2, 2>{edge.a, edge.b}, 0));
}

TEST(EdgeNumbers, ALabelWhoseOnlyLeaderSpotANeighbourTookGetsItWhenTheNeighbourCanMove) {
  // The fan above with a 20 mm top edge d-e, glued (seam 1), and part letters over the large face's
  // lower part but for a way up from the tiny base 1.2 mm wide: a label on a leader from the base can
  // reach only the middle of the strip below the top edge, where the top edge's label stands (it takes
  // the middle first). That label has room all along its edge: it moves, both are clear. Left where it
  // was, the base's label would cross a line or cover a text.
  auto [pieces, seams, folds] = tiny_face_in_a_fan(11, -9);
  Seam top_edge;
  top_edge.edge = 2;
  top_edge.sides = {SeamSide{0, 0, 2}, SeamSide{}};
  seams.push_back(top_edge);
  const Polygon left{{-12, 1.5}, {0.4, 1.5}, {0.4, 8.5}, {-12, 8.5}},
      right{{1.6, 1.5}, {14, 1.5}, {14, 8.5}, {1.6, 8.5}};
  const std::vector<std::vector<Polygon>> taken{{left, right}};
  const LabelOptions o;
  const auto labels =
      place_labels(pieces, seams, std::vector<int>{12, 13}, TabPlan{}, folds, {}, o, {}, taken);
  ASSERT_EQ(labels.size(), 2u);
  const Label& base = labels[0];
  EXPECT_FALSE(base.crowded);
  EXPECT_FALSE(base.over_fold);
  ASSERT_EQ(base.leader_mm.size(), 2u) << "the base's label stands off on a leader";
  EXPECT_GT(base.at_mm.y, 8.5) << "in the strip below the top edge";
  const Label& top = labels[1];
  EXPECT_FALSE(top.crowded);
  EXPECT_FALSE(top.over_fold);
  EXPECT_GT(std::fabs((top.box_mm[0] + top.box_mm[2]).x * 0.5 - 1), 2) << "the top edge's label moved aside";
  EXPECT_FALSE(convex_overlap(base.box_mm, top.box_mm, -o.tight_clearance_mm));
  for (const Label& l : labels) {
    for (const Polygon& area : taken[0])
      EXPECT_FALSE(convex_overlap(l.box_mm, area, -o.tight_clearance_mm)) << l.text;
    for (const FoldLine& f : folds[0])
      EXPECT_FALSE(convex_overlap(l.box_mm, std::array<Vec2, 2>{f.a, f.b}, -o.tight_clearance_mm)) << l.text;
  }
}

TEST(EdgeNumbers, ALeaderKeepsOffOtherLabelsAndTheirLeadersAndNeverLeavesThePiece) {
  // Both sides of one seam on the tiny base, and a second seam on the large face's top edge d-e whose
  // label sits above the leader's way: every label and leader stays inside the piece, apart.
  auto [pieces, seams, folds] = tiny_face_in_a_fan();
  Seam top;
  top.edge = 2;
  top.sides = {SeamSide{0, 0, 2}, SeamSide{}};
  seams.push_back(top);
  const LabelOptions o;
  const auto labels = place_labels(pieces, seams, std::vector<int>{12, 13}, TabPlan{}, folds, {}, o);
  ASSERT_EQ(labels.size(), 2u);
  ASSERT_EQ(labels[0].leader_mm.size(), 2u) << "the base's label still stands off";
  std::vector<Polygon> shapes;
  for (const Label& l : labels) {
    EXPECT_FALSE(l.crowded) << l.text;
    shapes.push_back(l.box_mm);
    for (const std::array<Vec2, 2>& segment : l.leader_mm)
      shapes.push_back(Polygon(segment.begin(), segment.end()));
  }
  for (const Polygon& shape : shapes)
    for (const OutlineEdge& edge : pieces[0].outline_mm[0])
      EXPECT_FALSE(convex_overlap(shape, std::array<Vec2, 2>{edge.a, edge.b}, -o.tight_clearance_mm));
  const std::size_t first_of_second = 1 + labels[0].leader_mm.size();
  for (std::size_t i = 0; i < first_of_second; ++i)
    for (std::size_t j = first_of_second; j < shapes.size(); ++j)
      EXPECT_FALSE(convex_overlap(shapes[i], shapes[j], -o.tight_clearance_mm)) << i << " " << j;
}

namespace {
LayoutOptions spot_at_150() {
  LayoutOptions o;
  o.size_mm = 150;
  return o;
}
}  // namespace

TEST(EdgeNumbers, NumbersRestartInEachPartAndEachPairOfPartsInOutlineOrder) {
  const auto& ex = test::unfolded_example("spot_350.obj");
  const unfold::PartsResult split = test::split_to_fit(ex.mesh, ex.unfolding, spot_at_150());
  ASSERT_GT(split.unfolding.piece_count, 2);
  const auto pieces = scaled_pieces(split.unfolding, 150 / split.unfolding.model_extent);
  const auto seams = find_seams(split.unfolding, pieces);
  const auto outline = number_seams(pieces, seams);
  const auto printed = number_seams_by_part(seams, outline);
  // Per pair of parts (a part with itself for the seams inside it): 1..k, rising along the outlines.
  std::map<std::pair<int, int>, std::vector<std::pair<int, int>>> of_pair;
  for (std::size_t s = 0; s < seams.size(); ++s) {
    const int a = seams[s].sides[0].piece, b = seams[s].sides[1].piece;
    of_pair[{std::min(a, b), std::max(a, b)}].push_back({outline[s], printed[s]});
  }
  ASSERT_GT(of_pair.size(), 2u);
  int largest = 0;
  for (auto& [pair, numbers] : of_pair) {
    std::sort(numbers.begin(), numbers.end());
    for (std::size_t i = 0; i < numbers.size(); ++i)
      EXPECT_EQ(numbers[i].second, static_cast<int>(i) + 1) << "parts " << pair.first << "-" << pair.second;
    largest = std::max(largest, static_cast<int>(numbers.size()));
  }
  EXPECT_EQ(*std::max_element(printed.begin(), printed.end()), largest);
  EXPECT_LT(largest, static_cast<int>(seams.size()) / 2) << "numbers stay shorter than one count over all";
}

TEST(EdgeNumbers, TheTightestSeamsOfACountGetItsNarrowestNumbersStillInOutlineOrder) {
  const auto& ex = test::unfolded_example("spot_350.obj");
  const auto pieces = scaled_pieces(ex.unfolding, 150 / ex.unfolding.model_extent);
  const auto seams = find_seams(ex.unfolding, pieces);
  const auto outline = number_seams(pieces, seams);
  const auto room = seam_label_room_mm(pieces, seams, LabelOptions{});
  const auto printed = number_seams_by_part(seams, outline, room);
  struct Numbered {
    int printed, outline;
    double room_mm;
  };
  std::map<std::pair<int, int>, std::vector<Numbered>> of_pair;
  for (std::size_t s = 0; s < seams.size(); ++s) {
    const int a = seams[s].sides[0].piece, b = seams[s].sides[1].piece;
    of_pair[{std::min(a, b), std::max(a, b)}].push_back({printed[s], outline[s], room[s]});
  }
  const auto width = [](int n) { return label_width_mm(number_text(n), 1, LabelOptions{}); };
  ASSERT_LT(width(5), width(6)) << "a marked 6. prints wider than 5";
  ASSERT_LT(width(9), width(10)) << "and narrower than 10";
  std::size_t largest = 0;
  bool marked_one_digit_last = false;
  for (auto& [pair, numbers] : of_pair) {
    largest = std::max(largest, numbers.size());
    std::sort(numbers.begin(), numbers.end(),
              [](const Numbered& a, const Numbered& b) { return a.printed < b.printed; });
    for (std::size_t i = 0; i < numbers.size(); ++i) {
      EXPECT_EQ(numbers[i].printed, static_cast<int>(i) + 1);
      for (std::size_t j = 0; j < numbers.size(); ++j) {
        const double wi = width(numbers[i].printed), wj = width(numbers[j].printed);
        if (wi < wj - 1e-9) {
          EXPECT_LE(numbers[i].room_mm, numbers[j].room_mm) << "a roomier seam took a narrower number";
        } else if (std::fabs(wi - wj) < 1e-9 && numbers[i].printed < numbers[j].printed) {
          EXPECT_LT(numbers[i].outline, numbers[j].outline) << "numbers of one width follow the outline";
        }
      }
    }
    if (numbers.size() >= 9) {
      // The tightest seams take 1-5, 7, 8 before the marked 6. and 9.
      const double room_of_6 = numbers[5].room_mm, room_of_7 = numbers[6].room_mm;
      EXPECT_GE(room_of_6, room_of_7);
      marked_one_digit_last = marked_one_digit_last || room_of_6 > room_of_7;
    }
  }
  ASSERT_GT(largest, 20u) << "a count long enough for two-digit numbers";
  EXPECT_TRUE(marked_one_digit_last) << "somewhere 6. went to a roomier seam than 7";
  EXPECT_NE(printed, number_seams_by_part(seams, outline))
      << "the tightest seams are not the first along the outline";
}

TEST(EdgeNumbers, ASinglePartKeepsOneCountInOutlineOrder) {
  const auto ex = test::tetrahedron();
  ASSERT_EQ(ex.unfolding.piece_count, 1);
  const auto pieces = scaled_pieces(ex.unfolding, 40);
  const auto seams = find_seams(ex.unfolding, pieces);
  const auto outline = number_seams(pieces, seams);
  EXPECT_EQ(number_seams_by_part(seams, outline), outline);
}

// A seam whose one face has no room for its label and whose other face has: the tab goes on the side
// without room and carries that label, and the face with room takes the mate's.
TEST(EdgeNumbers, TabsOnTheSideWithoutRoomLeaveFewerLabelsWithoutAClearSpot) {
  const auto& ex = test::unfolded_example("spot_350.obj");
  const auto pieces = scaled_pieces(ex.unfolding, 110 / ex.unfolding.model_extent);
  const auto seams = find_seams(ex.unfolding, pieces);
  const auto numbers = number_seams(pieces, seams);
  const auto folds = folds_of(ex.unfolding, pieces);
  const LabelOptions o;
  std::vector<double> widths;
  for (int n : numbers)
    widths.push_back(label_width_mm(number_text(n), o.min_mm, o));
  const std::vector<int> wanted = tab_sides_for_labels(pieces, seams, widths, o);
  ASSERT_EQ(wanted.size(), seams.size());
  const auto decided = std::count_if(wanted.begin(), wanted.end(), [](int k) { return k >= 0; });
  EXPECT_GT(decided, 10) << "the faces decide the side of some seams";
  auto unclear = [&](const TabPlan& tabs, int& wanted_honoured) {
    int count = 0;
    for (const Label& l : place_labels(pieces, seams, numbers, tabs, folds, {}, o))
      count += l.crowded || l.over_fold;
    wanted_honoured = 0;
    for (std::size_t s = 0; s < seams.size(); ++s)
      wanted_honoured += wanted[s] >= 0 && tabs.tab_of_seam[s] && tabs.tab_of_seam[s]->side == wanted[s];
    return count;
  };
  int honoured_by_default = 0, honoured = 0;
  const int before = unclear(plan_tabs(pieces, seams, TabOptions{}), honoured_by_default);
  const int after = unclear(plan_tabs(pieces, seams, TabOptions{}, {}, wanted), honoured);
  EXPECT_GT(honoured, honoured_by_default);
  EXPECT_GE(honoured, 0.8 * static_cast<double>(decided)) << "the wanted side gets the tab where it fits";
  EXPECT_LT(after, before) << "labels without a clear spot";
}

// spot_350 cut into parts at 110 mm, its seams numbered and its tabs planned: the labels to place.
struct SpotInParts {
  std::vector<ScaledPiece> pieces;
  std::vector<Seam> seams;
  std::vector<int> numbers;
  TabPlan tabs;
  std::vector<std::vector<FoldLine>> folds;

  SpotInParts() {
    const auto& ex = test::unfolded_example("spot_350.obj");
    pieces = scaled_pieces(ex.unfolding, 110 / ex.unfolding.model_extent);
    seams = find_seams(ex.unfolding, pieces);
    numbers = number_seams(pieces, seams);
    tabs = plan_tabs(pieces, seams, TabOptions{});
    folds = folds_of(ex.unfolding, pieces);
  }
  std::vector<Label> labels(const LabelOptions& o, std::span<const int> only_pieces = {}) const {
    return place_labels(pieces, seams, numbers, tabs, folds, {}, o, {}, {}, only_pieces);
  }
};

// Pieces' labels are placed on several threads at once: the same labels, in the same order.
TEST(EdgeNumbers, LabelsPlacedOnSeveralThreadsAreThoseOfOneThreadInTheSameOrder) {
  const SpotInParts spot;
  ASSERT_GT(spot.pieces.size(), 4u);
  LabelOptions one;
  one.threads = 1;
  const std::vector<Label> alone = spot.labels(one);
  for (int threads : {2, 3, 8}) {
    LabelOptions many = one;
    many.threads = threads;
    const std::vector<Label> shared = spot.labels(many);
    ASSERT_EQ(shared.size(), alone.size()) << threads << " threads";
    for (std::size_t i = 0; i < alone.size(); ++i) {
      EXPECT_EQ(shared[i].seam, alone[i].seam) << "label " << i << ", " << threads << " threads";
      EXPECT_EQ(shared[i].side, alone[i].side);
      EXPECT_EQ(shared[i].text, alone[i].text);
      EXPECT_EQ(shared[i].at_mm, alone[i].at_mm);
      EXPECT_EQ(shared[i].dir, alone[i].dir);
      EXPECT_EQ(shared[i].height_mm, alone[i].height_mm);
      EXPECT_EQ(shared[i].box_mm, alone[i].box_mm);
      EXPECT_EQ(shared[i].leader_mm, alone[i].leader_mm);
      EXPECT_EQ(shared[i].crowded, alone[i].crowded);
    }
  }
}

// A caller that changed some pieces' tabs places only their labels again: they must come out exactly
// as in a placement of every piece, since a label keeps clear of its own piece only.
TEST(EdgeNumbers, LabelsPlacedForSomePiecesOnlyAreThoseOfAPlacementOfAll) {
  const SpotInParts spot;
  ASSERT_GT(spot.pieces.size(), 4u);
  const LabelOptions o;
  const std::vector<Label> all = spot.labels(o);
  std::vector<int> some;
  for (int p = 0; p < static_cast<int>(spot.pieces.size()); p += 3)
    some.push_back(p);
  const std::vector<Label> part = spot.labels(o, some);
  std::vector<Label> expected;
  for (const Label& l : all)
    if (l.piece % 3 == 0) expected.push_back(l);
  ASSERT_EQ(part.size(), expected.size());
  ASSERT_LT(part.size(), all.size());
  for (std::size_t i = 0; i < part.size(); ++i) {
    EXPECT_EQ(part[i].seam, expected[i].seam);
    EXPECT_EQ(part[i].side, expected[i].side);
    EXPECT_EQ(part[i].text, expected[i].text);
    EXPECT_EQ(part[i].box_mm, expected[i].box_mm) << "label of seam " << part[i].seam.index();
    EXPECT_EQ(part[i].crowded, expected[i].crowded);
    EXPECT_EQ(part[i].over_fold, expected[i].over_fold);
  }
}
