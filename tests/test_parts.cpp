// Parts that fit the sheet: cut from the unfolding along folds, whole flat faces at a time.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "foldkit/error.hpp"
#include "foldkit/geom/hull.hpp"
#include "foldkit/layout/layout.hpp"
#include "foldkit/unfold/cut_tree.hpp"
#include "foldkit/unfold/flat_faces.hpp"
#include "foldkit/unfold/parts.hpp"
#include "foldkit/unfold/slits.hpp"
#include "layout_fixtures.hpp"

using namespace foldkit;
using namespace foldkit::unfold;

namespace {

PartOptions room_at(const Unfolding& u, double size_mm, double fraction = 1.0,
                    PartGrowth growth = PartGrowth::Fewest) {
  layout::LayoutOptions o;
  PartOptions p;
  p.room_mm = layout::piece_room_mm(o);
  p.mm_per_unit = size_mm / u.model_extent;
  p.room_fraction = fraction;
  p.growth = growth;
  return p;
}

// The best fit over fit_in_rect's angles and every hundredth of a degree: the split may have seen a part
// fit at an angle fit_in_rect does not try on the final hull (the edge of an earlier, smaller hull).
double best_fit_scale(const std::vector<Vec2>& points, Vec2 room) {
  double best = fit_in_rect(points, room).scale;
  for (int k = 0; k < 18000; ++k) {
    Box2 box;
    for (Vec2 q : points)
      box.add(rotated(q, k * std::numbers::pi / 18000));
    best = std::max(best, std::min(room.x / box.width(), room.y / box.height()));
  }
  return best;
}

void expect_parts_fit(const Unfolding& u, const PartOptions& p) {
  for (const auto& faces : u.piece_faces()) {
    std::vector<Vec2> points;
    for (int f : faces)
      points.insert(points.end(), u.flat[f].begin(), u.flat[f].end());
    EXPECT_GE(best_fit_scale(convex_hull(points), p.room_mm * p.room_fraction), p.mm_per_unit * (1 - 1e-9));
  }
}

test::UnfoldedExample lowpoly(const std::string& name) {
  test::UnfoldedExample ex;
  ex.mesh = load_mesh(test::source_dir() / "tests" / "data" / "lowpoly" / name).mesh;
  UnfoldOptions options;
  options.threads = 1;
  ex.unfolding = unfold_mesh(ex.mesh, options).unfolding;
  return ex;
}

}  // namespace

TEST(Parts, AOnePieceUnfoldingTooLargeForA4IsCutIntoPartsThatFit) {
  const auto& ex = test::unfolded_example("spot_350.obj", Method::Search);
  PartOptions p = room_at(ex.unfolding, 160);
  p.move_seams = false;  // so that every old cut stays one (seam moves: below)
  const PartsResult parts = split_into_parts(ex.mesh, ex.unfolding, p);
  ASSERT_GT(parts.split_pieces, 0) << "spot at 160 mm does not fit A4 in one piece";
  const Unfolding& u = parts.unfolding;
  EXPECT_TRUE(check_unfolding(ex.mesh, u).empty());
  EXPECT_GT(u.piece_count, ex.unfolding.piece_count);
  for (std::size_t e = 0; e < u.edges.size(); ++e)
    if (ex.unfolding.edges[e].cut) {
      EXPECT_TRUE(u.edges[e].cut) << "an old cut was glued back";
    }
  expect_parts_fit(u, p);
}

// Slits: cut-tree leaves at nearly flat vertices, where no glue tab fits (slits.hpp).
int slits_of(const Mesh& mesh, const Unfolding& u) {
  return count_slits(CutTree(make_context(mesh), edge_states(u)), kSlitGapPerLength);
}

TEST(Parts, SeamsMoveInsideThePartsClosingSlitsWhileEveryPartStillFitsItsRoom) {
  const auto& ex = test::unfolded_example("penguin_500.obj", Method::Search);
  int before = 0, after = 0;
  for (double fraction : {1.0, 0.85, 0.7, 0.5, 0.35}) {
    PartOptions p = room_at(ex.unfolding, 150, fraction, PartGrowth::Round);
    p.move_seams = false;
    const Unfolding still = split_into_parts(ex.mesh, ex.unfolding, p).unfolding;
    p.move_seams = true;
    const Unfolding moved = split_into_parts(ex.mesh, ex.unfolding, p).unfolding;
    EXPECT_EQ(check_unfolding(ex.mesh, moved), std::vector<std::string>{});
    EXPECT_EQ(moved.piece_count, still.piece_count) << "moves never add or remove a part";
    expect_parts_fit(moved, p);
    EXPECT_LE(slits_of(ex.mesh, moved), slits_of(ex.mesh, still)) << "at " << fraction << " of the room";
    before += slits_of(ex.mesh, still);
    after += slits_of(ex.mesh, moved);
  }
  EXPECT_LT(after, before);
}

TEST(Parts, SlitsAreClosedAcrossPartsWithAsManyPartsEachStillFittingTheSheet) {
  const auto& ex = test::unfolded_example("penguin_500.obj", Method::Search);
  int before = 0, after = 0;
  for (double fraction : {1.0, 0.7, 0.5}) {
    const PartOptions p = room_at(ex.unfolding, 150, fraction, PartGrowth::Round);
    const Unfolding parts = split_into_parts(ex.mesh, ex.unfolding, p).unfolding;
    const Unfolding closed = close_slits_across_parts(ex.mesh, parts, p);
    EXPECT_EQ(check_unfolding(ex.mesh, closed), std::vector<std::string>{});
    EXPECT_EQ(closed.piece_count, parts.piece_count);
    PartOptions sheet = p;
    sheet.room_fraction = 1;
    expect_parts_fit(closed, sheet);
    EXPECT_LE(slits_of(ex.mesh, closed), slits_of(ex.mesh, parts)) << "at " << fraction << " of the room";
    before += slits_of(ex.mesh, parts);
    after += slits_of(ex.mesh, closed);
    // Every edge forced as it is: nothing changes.
    PartOptions forced = p;
    forced.constraints.rule.assign(ex.mesh.num_edges(), EdgeRule::Free);
    for (int e = 0; e < ex.mesh.num_edges(); ++e)
      if (!parts.edges[e].boundary())
        forced.constraints.rule[EdgeId(e)] = parts.edges[e].cut ? EdgeRule::MustCut : EdgeRule::MustFold;
    const Unfolding kept = close_slits_across_parts(ex.mesh, parts, forced);
    for (int e = 0; e < ex.mesh.num_edges(); ++e)
      ASSERT_EQ(kept.edges[e].cut, parts.edges[e].cut) << "edge " << e;
  }
  EXPECT_LT(after, before);
}

using test::narrow_pairs_in_one_part;

TEST(Parts, WithASlitGapNoPartHoldsBothSidesOfASeamThatNarrowAndEveryPartStillFits) {
  const auto& ex = test::unfolded_example("penguin_500.obj", Method::Search);
  for (PartGrowth growth : {PartGrowth::Tree, PartGrowth::Round}) {
    PartOptions p = room_at(ex.unfolding, 150, 1.0, growth);
    const double gap_units = 2.5 / p.mm_per_unit;
    const Unfolding plain = split_into_parts(ex.mesh, ex.unfolding, p).unfolding;
    ASSERT_GT(narrow_pairs_in_one_part(ex.unfolding, plain, gap_units), 0) << "penguin's parts hold slits";
    p.slit_gap_mm = 2.5;
    const Unfolding opened = split_into_parts(ex.mesh, ex.unfolding, p).unfolding;
    EXPECT_EQ(check_unfolding(ex.mesh, opened), std::vector<std::string>{});
    EXPECT_EQ(narrow_pairs_in_one_part(ex.unfolding, opened, gap_units), 0);
    EXPECT_GT(opened.piece_count, plain.piece_count);
    expect_parts_fit(opened, p);
  }
}

TEST(Parts, ANarrowSeamsFacesArePartnersBothWaysAndTheirEdgesEndsLieWithinTheGap) {
  const auto& ex = test::unfolded_example("penguin_500.obj", Method::Search);
  const Unfolding& u = ex.unfolding;
  const double gap = 0.02 * u.model_extent;
  const std::vector<std::vector<int>> partners = narrow_seam_partners(u, gap);
  int pairs = 0;
  for (const UnfoldEdge& e : u.edges) {
    if (!e.glued_seam()) continue;
    const auto& a = partners[e.face[0]];
    const bool listed = std::find(a.begin(), a.end(), e.face[1]) != a.end();
    const auto& b = partners[e.face[1]];
    EXPECT_EQ(listed, std::find(b.begin(), b.end(), e.face[0]) != b.end());
    const Vec2 a0 = u.flat[e.face[0]][e.corner[0]], a1 = u.flat[e.face[0]][(e.corner[0] + 1) % 3];
    const Vec2 b0 = u.flat[e.face[1]][(e.corner[1] + 1) % 3], b1 = u.flat[e.face[1]][e.corner[1]];
    EXPECT_EQ(listed, norm(a0 - b0) < gap && norm(a1 - b1) < gap) << "seam of faces " << e.face[0];
    pairs += listed;
  }
  EXPECT_GT(pairs, 0);
  const std::vector<std::vector<int>> none = narrow_seam_partners(u, 0);
  EXPECT_TRUE(std::all_of(none.begin(), none.end(), [](const std::vector<int>& p) { return p.empty(); }))
      << "a gap of 0 makes no pairs";
}

TEST(Parts, SeamMovesInsideThePartsKeepTheForcedCutsAndFolds) {
  const auto& ex = test::unfolded_example("penguin_500.obj", Method::Search);
  PartOptions p = room_at(ex.unfolding, 150, 0.5, PartGrowth::Round);
  p.move_seams = false;
  const Unfolding still = split_into_parts(ex.mesh, ex.unfolding, p).unfolding;
  // Every edge of the unmoved parts forced as it is: no move is left.
  p.constraints.rule.assign(ex.mesh.num_edges(), EdgeRule::Free);
  for (int e = 0; e < ex.mesh.num_edges(); ++e)
    if (!still.edges[e].boundary())
      p.constraints.rule[EdgeId(e)] = still.edges[e].cut ? EdgeRule::MustCut : EdgeRule::MustFold;
  p.move_seams = true;
  const Unfolding moved = split_into_parts(ex.mesh, ex.unfolding, p).unfolding;
  for (int e = 0; e < ex.mesh.num_edges(); ++e)
    EXPECT_EQ(moved.edges[e].cut, still.edges[e].cut) << "edge " << e;
}

TEST(Parts, PiecesThatFitAreLeftAlone) {
  const auto& ex = test::unfolded_example("bob_350.obj");
  const PartsResult parts = split_into_parts(ex.mesh, ex.unfolding, room_at(ex.unfolding, 120));
  EXPECT_EQ(parts.split_pieces, 0);
  EXPECT_EQ(parts.unfolding.piece_count, ex.unfolding.piece_count);
}

TEST(Parts, EveryGrowthGivesPartsThatFitAtEveryRoomFraction) {
  const auto& ex = test::unfolded_example("fish_350.obj", Method::Search);
  for (PartGrowth growth : {PartGrowth::Tree, PartGrowth::Round, PartGrowth::Fewest})
    for (double fraction : {1.0, 0.7, 0.5}) {
      const PartOptions p = room_at(ex.unfolding, 200, fraction, growth);
      const PartsResult parts = split_into_parts(ex.mesh, ex.unfolding, p);
      EXPECT_TRUE(check_unfolding(ex.mesh, parts.unfolding).empty());
      EXPECT_EQ(parts.unfolding.piece_count,
                ex.unfolding.piece_count - parts.split_pieces + parts.new_pieces);
      expect_parts_fit(parts.unfolding, p);
    }
}

TEST(Parts, NoFlatFaceIsSeparatedAndNoneIsCutInside) {
  for (const char* name : {"barn.obj", "cylinder12.obj", "dodecahedron.obj", "football.obj", "l_block.obj"})
    for (double size : {150.0, 250.0, 400.0})
      for (PartGrowth growth : {PartGrowth::Tree, PartGrowth::Round}) {
        const auto ex = lowpoly(name);
        PartsResult parts;
        try {
          parts = split_into_parts(ex.mesh, ex.unfolding, room_at(ex.unfolding, size, 1.0, growth));
        } catch (const LayoutError&) {
          continue;  // a face larger than A4 at this size: refused, tested below
        }
        const Unfolding& u = parts.unfolding;
        EXPECT_TRUE(check_unfolding(ex.mesh, u).empty()) << name;
        const FlatFaces flat = find_flat_faces(ex.mesh);
        for (int e = 0; e < ex.mesh.num_edges(); ++e)
          if (flat.inside[e]) {
            EXPECT_FALSE(u.edges[e].cut) << name << " at " << size << " mm: edge " << e;
            EXPECT_TRUE(u.edges[e].inside_face);
          }
        for (int f = 0; f < ex.mesh.num_faces(); ++f)
          for (int g = 0; g < ex.mesh.num_faces(); ++g)
            if (ex.mesh.polygon_of(f) == ex.mesh.polygon_of(g)) {
              EXPECT_EQ(u.piece_of_face[f], u.piece_of_face[g]) << name << " at " << size << " mm";
            }
      }
}

TEST(Parts, AFlatFaceLargerThanTheSheetIsRefusedNamingTheLargestSizeThatFits) {
  // The barn's long wall (6 x 4 units) at 600 mm for the 6-unit barn is 600 x 400 mm: no A4 holds it.
  const auto ex = lowpoly("barn.obj");
  try {
    split_into_parts(ex.mesh, ex.unfolding, room_at(ex.unfolding, 600));
    FAIL() << "a wall larger than A4 was accepted";
  } catch (const PartTooLarge& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("flat face"), std::string::npos) << what;
    EXPECT_NE(what.find("the largest size that fits is"), std::string::npos) << what;
    EXPECT_EQ(what.find("--"), std::string::npos) << "the library names no command-line flag: " << what;
    EXPECT_NE(e.message("--size").find("the largest --size that fits is"), std::string::npos);
  }
}

TEST(Parts, APieceAskedForIsCutSmallerEvenThoughItFitsAndTheOthersStayWhole) {
  const auto& ex = test::unfolded_example("spot_350.obj", Method::Search);
  const PartsResult first = split_into_parts(ex.mesh, ex.unfolding, room_at(ex.unfolding, 160));
  ASSERT_GT(first.unfolding.piece_count, 1);
  PartOptions p = room_at(first.unfolding, 160, 0.5, PartGrowth::Round);
  p.also_split = {0};
  const PartsResult again = split_into_parts(ex.mesh, first.unfolding, p);
  EXPECT_TRUE(check_unfolding(ex.mesh, again.unfolding).empty());
  EXPECT_GT(again.unfolding.piece_count, first.unfolding.piece_count);
  // Only piece 0's faces were cut: every other piece keeps all of its faces together.
  const auto before = first.unfolding.piece_faces();
  for (std::size_t piece = 1; piece < before.size(); ++piece)
    for (int f : before[piece])
      EXPECT_EQ(again.unfolding.piece_of_face[f], again.unfolding.piece_of_face[before[piece].front()]);
  for (const auto& faces : again.unfolding.piece_faces())
    if (first.unfolding.piece_of_face[faces.front()] == 0) {
      std::vector<Vec2> points;
      for (int f : faces)
        points.insert(points.end(), again.unfolding.flat[f].begin(), again.unfolding.flat[f].end());
      EXPECT_GE(fit_in_rect(points, p.room_mm * 0.5).scale, p.mm_per_unit * (1 - 1e-9));
    }
}

TEST(Parts, PartsGrownIntoATileOfTheSheetFitTheTileAndPiecesThatFitTheSheetStayWhole) {
  const auto& ex = test::unfolded_example("spot_350.obj", Method::Search);
  PartOptions p = room_at(ex.unfolding, 250, 1.0, PartGrowth::Round);
  p.grow_room_mm = {p.room_mm.x, 0.45 * p.room_mm.y};  // about half a sheet
  const PartsResult tiled = split_into_parts(ex.mesh, ex.unfolding, p);
  ASSERT_GT(tiled.split_pieces, 0);
  EXPECT_TRUE(check_unfolding(ex.mesh, tiled.unfolding).empty());
  PartOptions tile = p;
  tile.room_mm = p.grow_room_mm;
  expect_parts_fit(tiled.unfolding, tile);
  const PartsResult whole =
      split_into_parts(ex.mesh, ex.unfolding, room_at(ex.unfolding, 250, 1.0, PartGrowth::Round));
  EXPECT_GT(tiled.unfolding.piece_count, whole.unfolding.piece_count)
      << "half-sheet parts are more than sheet-sized ones";
  // The tile only says how large parts grow; which pieces need a split is still the whole room's call.
  const auto& small = test::unfolded_example("bob_350.obj");
  PartOptions fits = room_at(small.unfolding, 120);
  fits.grow_room_mm = {10, 10};
  const PartsResult kept = split_into_parts(small.mesh, small.unfolding, fits);
  EXPECT_EQ(kept.split_pieces, 0);
  EXPECT_EQ(kept.unfolding.piece_count, small.unfolding.piece_count);
}

TEST(Parts, PartsAllowedToJoinAreJoinedIntoFewerPartsThatFitAddingNoCutAndNoSlit) {
  const auto& ex = test::unfolded_example("penguin_500.obj", Method::Search);
  const PartOptions small = room_at(ex.unfolding, 150, 0.35, PartGrowth::Round);
  const Unfolding parts = split_into_parts(ex.mesh, ex.unfolding, small).unfolding;
  ASSERT_GT(parts.piece_count, 6);
  // Two groups, as if parts lay on two sheets: even and odd part numbers.
  const auto group = [](int part) { return part % 2; };
  const PartOptions sheet = room_at(ex.unfolding, 150);
  const Unfolding joined =
      join_parts(ex.mesh, parts, sheet, [&](int a, int b) { return group(a) == group(b); });
  EXPECT_EQ(check_unfolding(ex.mesh, joined), std::vector<std::string>{});
  ASSERT_LE(joined.piece_count, parts.piece_count - 3);
  expect_parts_fit(joined, sheet);
  EXPECT_LE(slits_of(ex.mesh, joined), slits_of(ex.mesh, parts));
  for (int e = 0; e < ex.mesh.num_edges(); ++e)
    if (joined.edges[e].cut) {
      EXPECT_TRUE(parts.edges[e].cut) << "edge " << e << " was cut by a join";
    }
  // Each joined part holds parts of one group only.
  for (const std::vector<int>& faces : joined.piece_faces())
    for (int f : faces)
      EXPECT_EQ(group(parts.piece_of_face[f]), group(parts.piece_of_face[faces.front()])) << "face " << f;
  // Joins taken one at a time, smallest pairs first: a caller may stop where they cost a sheet.
  EXPECT_EQ(join_parts(
                ex.mesh, parts, sheet, [](int, int) { return true; }, 1)
                .piece_count,
            parts.piece_count - 1);
  EXPECT_EQ(join_parts(
                ex.mesh, parts, sheet, [](int, int) { return true; }, 3)
                .piece_count,
            parts.piece_count - 3);
  // Nothing may join, or every seam is forced: the parts stay as they were.
  EXPECT_EQ(join_parts(ex.mesh, parts, sheet, [](int, int) { return false; }).piece_count, parts.piece_count);
  PartOptions forced = sheet;
  forced.constraints.rule.assign(ex.mesh.num_edges(), EdgeRule::Free);
  for (int e = 0; e < ex.mesh.num_edges(); ++e)
    if (parts.edges[e].cut && !parts.edges[e].boundary())
      forced.constraints.rule[EdgeId(e)] = EdgeRule::MustCut;
  EXPECT_EQ(join_parts(ex.mesh, parts, forced, [](int, int) { return true; }).piece_count, parts.piece_count);
}

namespace {

// Of all faces, the share of the parts' convex hulls they cover: 1 for convex parts, small for spindly ones.
double hull_cover(const Unfolding& u) {
  double faces = 0, hulls = 0;
  for (const std::vector<int>& part : u.piece_faces()) {
    std::vector<Vec2> points;
    for (int f : part) {
      const Triangle2& t = u.flat[f];
      faces += 0.5 * std::fabs(cross(t[1] - t[0], t[2] - t[0]));
      points.insert(points.end(), t.begin(), t.end());
    }
    hulls += std::fabs(layout::signed_area(convex_hull(points)));
  }
  return faces / hulls;
}

}  // namespace

TEST(Parts, PatchesGrownOverTheSurfaceAreValidFitTheirRoomAndFillTheirHullsBetterThanPartsCutFromTheNet) {
  const auto& ex = test::unfolded_example("fish_350.obj", Method::Search);
  for (double fraction : {1.0, 0.5}) {
    const PartOptions p = room_at(ex.unfolding, 150, fraction, PartGrowth::Round);
    const std::optional<Unfolding> patches = patch_parts(ex.mesh, ex.unfolding, p);
    ASSERT_TRUE(patches.has_value());
    EXPECT_EQ(check_unfolding(ex.mesh, *patches), std::vector<std::string>{});
    expect_parts_fit(*patches, p);
    const Unfolding cut = split_into_parts(ex.mesh, ex.unfolding, p).unfolding;
    // fish_350 at 150 mm: 0.47 against 0.37 of the hulls in 12 patches against 5 parts, 0.61 against
    // 0.54 at half the room.
    EXPECT_GT(hull_cover(*patches), hull_cover(cut) + 0.05) << "at " << fraction << " of the room";
    // Patches grow as far as the room allows: no two neighbours could have joined into one that fits
    // unless it overlaps or adds a slit, so they are not confetti.
    EXPECT_LT(patches->piece_count, ex.mesh.num_faces() / 8) << "at " << fraction << " of the room";
  }
}

TEST(Parts, PatchesKeepEveryFlatFaceWholeAndTheForcedCutsAndFolds) {
  for (const char* name : {"barn.obj", "cylinder12.obj", "dodecahedron.obj", "football.obj"}) {
    const auto ex = lowpoly(name);
    PartOptions p = room_at(ex.unfolding, 150);
    // Forced: every third edge between two flat faces cut, and of the unfolding's folds every fifth kept.
    p.constraints.rule.assign(ex.mesh.num_edges(), EdgeRule::Free);
    for (int e = 0; e < ex.mesh.num_edges(); ++e) {
      const UnfoldEdge& edge = ex.unfolding.edges[e];
      if (edge.boundary() || edge.inside_face) continue;
      if (e % 3 == 0) p.constraints.rule[EdgeId(e)] = EdgeRule::MustCut;
      if (e % 5 == 1 && !edge.cut) p.constraints.rule[EdgeId(e)] = EdgeRule::MustFold;
    }
    const std::optional<Unfolding> patches = patch_parts(ex.mesh, ex.unfolding, p);
    ASSERT_TRUE(patches.has_value()) << name;
    EXPECT_EQ(check_unfolding(ex.mesh, *patches), std::vector<std::string>{}) << name;
    const FlatFaces flat = find_flat_faces(ex.mesh);
    for (int e = 0; e < ex.mesh.num_edges(); ++e) {
      if (flat.inside[e]) {
        EXPECT_FALSE(patches->edges[e].cut) << name << ": edge " << e << " inside a flat face";
        EXPECT_TRUE(patches->edges[e].inside_face);
      }
      if (p.constraints.cut(EdgeId(e))) {
        EXPECT_TRUE(patches->edges[e].cut) << name << ": forced cut " << e;
      }
      if (p.constraints.fold(EdgeId(e))) {
        EXPECT_FALSE(patches->edges[e].cut) << name << ": forced fold " << e;
      }
    }
  }
}

TEST(Parts, PatchSeamsMoveOffEdgesWithoutRoomForTheirLabels) {
  const auto& ex = test::unfolded_example("fish_350.obj", Method::Search);
  PartOptions p = room_at(ex.unfolding, 150);
  // The room of a 2 mm label at 150 mm (cli::cuts_for_print): about 2.6 mm beside the edge.
  p.cuts.label_room = 2.6 * ex.unfolding.model_extent / 150;
  const std::vector<LabelFit> fit = tight_edges(ex.mesh, p.cuts);
  const auto tight_seams = [&](const Unfolding& u) {
    int n = 0;
    for (std::size_t e = 0; e < u.edges.size(); ++e)
      n += u.edges[e].glued_seam() && fit[e] == LabelFit::Tight ? 1 : 0;
    return n;
  };
  // The patches as joined, before their seams move: every flat face apart, then join_parts.
  EdgeStates apart_state = edge_states(ex.unfolding);
  for (std::size_t e = 0; e < ex.unfolding.edges.size(); ++e)
    if (!ex.unfolding.edges[e].boundary() && !ex.unfolding.edges[e].inside_face)
      apart_state[EdgeId(static_cast<int>(e))] = EdgeState::Cut;
  Unfolding apart = flatten(ex.mesh, apart_state);
  for (std::size_t e = 0; e < apart.edges.size(); ++e)
    apart.edges[e].inside_face = ex.unfolding.edges[e].inside_face;
  const Unfolding joined = join_parts(ex.mesh, apart, p, [](int, int) { return true; });
  const std::optional<Unfolding> patches = patch_parts(ex.mesh, ex.unfolding, p);
  ASSERT_TRUE(patches.has_value());
  EXPECT_EQ(check_unfolding(ex.mesh, *patches), std::vector<std::string>{});
  expect_parts_fit(*patches, p);
  EXPECT_LT(tight_seams(*patches), tight_seams(joined));
  EXPECT_LE(slits_of(ex.mesh, *patches), slits_of(ex.mesh, joined));
  EXPECT_EQ(patches->piece_count, joined.piece_count) << "a move changes where parts meet, not how many";
}
