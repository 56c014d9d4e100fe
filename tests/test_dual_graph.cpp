// Minimum-perimeter weights and spanning forests of the dual graph.
#include <gtest/gtest.h>

#include <algorithm>

#include "foldkit/unfold/dual_graph.hpp"
#include "foldkit/unfold/mesh_io.hpp"
#include "test_paths.hpp"

using namespace foldkit;
using namespace foldkit::unfold;

namespace {
int folds(const EdgeStates& state) {
  return static_cast<int>(std::count(state.begin(), state.end(), EdgeState::Fold));
}
bool is_cut(const EdgeStates& s, int e) {
  return s[EdgeId(e)] == EdgeState::Cut;
}

}  // namespace

TEST(DualGraph, MinimumPerimeterWeightsRunFromZeroAtTheLongestEdgeToOneAtTheShortest) {
  Mesh mesh = load_mesh(test::example_mesh("spot_350.obj")).mesh;
  auto w = min_perimeter_weights(mesh);
  int longest = 0, shortest = 0;
  for (int e = 0; e < mesh.num_edges(); ++e) {
    if (edge_length(mesh, e) > edge_length(mesh, longest)) longest = e;
    if (edge_length(mesh, e) < edge_length(mesh, shortest)) shortest = e;
  }
  EXPECT_DOUBLE_EQ(w[longest], 0.0);
  EXPECT_DOUBLE_EQ(w[shortest], 1.0);
  for (double x : w) {
    EXPECT_GE(x, 0.0);
    EXPECT_LE(x, 1.0);
  }
}

TEST(DualGraph, TheSpanningForestFoldsOneEdgeFewerThanFacesPerComponent) {
  Mesh mesh = load_mesh(test::example_mesh("bob_350.obj")).mesh;
  auto cut = spanning_forest(mesh, min_perimeter_weights(mesh));
  EXPECT_EQ(count_components(mesh), 1);
  EXPECT_EQ(folds(cut), mesh.num_faces() - 1);
}

TEST(DualGraph, TheSpanningTreeHasMinimumWeight) {
  Mesh mesh = load_mesh(test::example_mesh("spot_128.obj")).mesh;
  auto w = min_perimeter_weights(mesh);
  auto cut = spanning_forest(mesh, w);
  double tree = 0;
  for (int e = 0; e < mesh.num_edges(); ++e)
    if (!is_cut(cut, e)) tree += w[e];
  // Swapping any cut edge in for the heaviest fold on its cycle never lowers the weight (cut property),
  // checked cheaply by forcing one light cut edge to fold: the result cannot be lighter.
  for (int e = 0; e < mesh.num_edges(); e += 7) {
    if (!is_cut(cut, e)) continue;
    EdgeConstraints c;
    c.rule.assign(mesh.num_edges(), EdgeRule::Free);
    c.rule[EdgeId(e)] = EdgeRule::MustFold;
    auto other = spanning_forest(mesh, w, c);
    double sum = 0;
    for (int k = 0; k < mesh.num_edges(); ++k)
      if (!is_cut(other, k)) sum += w[k];
    EXPECT_GE(sum, tree - 1e-12);
  }
}

TEST(DualGraph, ForcedCutsAndFoldsAreHonoured) {
  Mesh mesh = load_mesh(test::example_mesh("spot_128.obj")).mesh;
  auto w = min_perimeter_weights(mesh);
  EdgeConstraints c;
  c.rule.assign(mesh.num_edges(), EdgeRule::Free);
  for (int e = 0; e < 20; ++e)
    c.rule[EdgeId(e)] = EdgeRule::MustCut;
  for (int e = 20; e < 30; ++e)
    c.rule[EdgeId(e)] = EdgeRule::MustFold;
  auto cut = spanning_forest(mesh, w, c);
  for (int e = 0; e < 20; ++e)
    EXPECT_TRUE(is_cut(cut, e));
  for (int e = 20; e < 30; ++e)
    EXPECT_FALSE(is_cut(cut, e));
}

TEST(DualGraph, AThresholdLeavesSpanningSubtrees) {
  Mesh mesh = load_mesh(test::example_mesh("fish_350.obj")).mesh;
  auto w = min_perimeter_weights(mesh);
  std::vector<double> sorted = w;
  std::sort(sorted.begin(), sorted.end());
  double threshold = sorted[sorted.size() * 3 / 10];  // keep the lightest 30% of dual edges at most
  auto cut = spanning_forest(mesh, w, {}, threshold);
  EXPECT_LT(folds(cut), mesh.num_faces() - 1);
  for (int e = 0; e < mesh.num_edges(); ++e)
    if (!is_cut(cut, e)) {
      EXPECT_LT(w[e], threshold);
    }
}

namespace {

// The height of face f above its edge e.
double height_above(const Mesh& mesh, int e, int f) {
  return 2 * face_area(mesh, f) / edge_length(mesh, e);
}

// The face with the least height over its longest edge: the thinnest sliver.
int thinnest_face(const Mesh& mesh) {
  int best = 0;
  double best_ratio = 1e300;
  for (int f = 0; f < mesh.num_faces(); ++f) {
    double longest = 0;
    for (int e : mesh.face_edges[f])
      longest = std::max(longest, edge_length(mesh, e));
    const double ratio = 2 * face_area(mesh, f) / (longest * longest);
    if (ratio < best_ratio) {
      best_ratio = ratio;
      best = f;
    }
  }
  return best;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

TEST(DualGraph, RoomySeamWeightsRunFromZeroToOneAndGrowWithLengthAndHeight) {
  Mesh mesh = load_mesh(test::example_mesh("spot_350.obj")).mesh;
  auto w = roomy_seam_weights(mesh, 3);
  double lo = 1, hi = 0;
  for (double x : w) {
    lo = std::min(lo, x);
    hi = std::max(hi, x);
  }
  EXPECT_DOUBLE_EQ(lo, 0.0);
  EXPECT_DOUBLE_EQ(hi, 1.0);
  // An edge that is both longer and has taller faces on both sides than another weighs more.
  int checked = 0;
  for (int a = 0; a < mesh.num_edges(); a += 5)
    for (int b = 1; b < mesh.num_edges(); b += 11) {
      const auto& ea = mesh.edges[a];
      const auto& eb = mesh.edges[b];
      const double ha = std::min(height_above(mesh, a, ea.face[0]), height_above(mesh, a, ea.face[1]));
      const double hb = std::min(height_above(mesh, b, eb.face[0]), height_above(mesh, b, eb.face[1]));
      if (edge_length(mesh, a) > edge_length(mesh, b) && ha > hb) {
        EXPECT_GE(w[a], w[b]) << a << " " << b;
        ++checked;
      }
    }
  EXPECT_GT(checked, 100);
}

TEST(DualGraph, TheEdgesOfASliverWeighLessThanTheMedianRoomyWeight) {
  Mesh mesh = load_mesh(test::example_mesh("bob_350.obj")).mesh;
  auto w = roomy_seam_weights(mesh, 3);
  const double mid = median(w);
  const int sliver = thinnest_face(mesh);
  for (int e : mesh.face_edges[sliver])
    EXPECT_LT(w[e], mid) << "edge " << e << " of face " << sliver;
  // Its longest edge is long, and still light: the sliver beside it leaves no room.
  int longest = mesh.face_edges[sliver][0];
  for (int e : mesh.face_edges[sliver])
    if (edge_length(mesh, e) > edge_length(mesh, longest)) longest = e;
  auto by_length = min_perimeter_weights(mesh);
  EXPECT_LT(w[longest], 1 - by_length[longest]);
}

TEST(DualGraph, TheRoomyTreeCutsLongerEdgesWithMoreRoomThanTheMinimumPerimeterTree) {
  Mesh mesh = load_mesh(test::example_mesh("fish_350.obj")).mesh;
  auto mean_cut = [&](const EdgeStates& s, auto measure) {
    double sum = 0;
    int n = 0;
    for (int e = 0; e < mesh.num_edges(); ++e)
      if (is_cut(s, e)) {
        sum += measure(e);
        ++n;
      }
    return sum / n;
  };
  auto length = [&](int e) { return edge_length(mesh, e); };
  // The side of a square label that fits beside the edge on both sides (aspect 1): the lower height,
  // capped by the length.
  auto room = [&](int e) {
    const double l = edge_length(mesh, e);
    double least = l;
    for (int f : mesh.edges[e].face) {
      const double h = height_above(mesh, e, f);
      least = std::min(least, l * h / (l + h));
    }
    return least;
  };
  const EdgeStates roomy = spanning_forest(mesh, cut_weights(mesh, {SeamPreference::Roomy, 1, 1}));
  const EdgeStates shortest = spanning_forest(mesh, cut_weights(mesh, {SeamPreference::Short, 1, 1}));
  EXPECT_EQ(folds(roomy), mesh.num_faces() - 1);
  EXPECT_GT(mean_cut(roomy, length), 1.3 * mean_cut(shortest, length));
  EXPECT_GT(mean_cut(roomy, room), 1.3 * mean_cut(shortest, room));
}

TEST(DualGraph, CutWeightsGiveTheWeightsTheirPreferenceNames) {
  Mesh mesh = load_mesh(test::example_mesh("spot_128.obj")).mesh;
  EXPECT_EQ(cut_weights(mesh, {SeamPreference::Short, 3, 1}), min_perimeter_weights(mesh));
  EXPECT_EQ(cut_weights(mesh, {SeamPreference::Roomy, 2, 1}), roomy_seam_weights(mesh, 2));
  EXPECT_NE(roomy_seam_weights(mesh, 2), roomy_seam_weights(mesh, 6));
}

TEST(DualGraph, BalancedWeightsKeepTheMinimumPerimeterOrderAndLightenOnlyTheTightEdges) {
  Mesh mesh = load_mesh(test::example_mesh("bob_350.obj")).mesh;
  const CutOptions balanced{SeamPreference::Balanced, 3, 1};
  auto w = cut_weights(mesh, balanced);
  auto by_length = min_perimeter_weights(mesh);
  auto roomy = roomy_seam_weights(mesh, 3);  // monotone in the room: the median room is its median
  const double median_roomy = median(roomy);
  int tight = 0, lightened = 0;
  for (int e = 0; e < mesh.num_edges(); ++e) {
    EXPECT_LE(w[e], by_length[e] + 1e-12);
    if (roomy[e] >= median_roomy) {
      EXPECT_DOUBLE_EQ(w[e], by_length[e]) << "edge " << e << " has room and keeps its weight";
    } else {
      ++tight;
      lightened += w[e] < by_length[e] ? 1 : 0;
    }
  }
  EXPECT_GT(tight, mesh.num_edges() / 3);
  EXPECT_GT(lightened, tight * 9 / 10);
  // The sliver's edges are tight: lighter than their length alone would make them.
  for (int e : mesh.face_edges[thinnest_face(mesh)])
    EXPECT_LT(w[e], by_length[e]) << "edge " << e;
}

TEST(DualGraph, EdgesWithoutRoomForTheSmallestLabelAreFoldedBeforeEveryEdgeWithRoom) {
  Mesh mesh = load_mesh(test::example_mesh("bob_350.obj")).mesh;
  const std::vector<double> room = edge_label_room(mesh, 3);
  CutOptions cuts;
  cuts.label_room = median(room);
  const std::vector<LabelFit> tight = tight_edges(mesh, cuts);
  const std::vector<double> w = cut_weights(mesh, cuts), by_length = min_perimeter_weights(mesh);
  double heaviest_tight = -1e9, lightest_roomy = 1e9;
  int tight_count = 0;
  for (int e = 0; e < mesh.num_edges(); ++e) {
    // Without tabs (label_tab_length 0) an edge is tight, 2, when either side lacks room.
    EXPECT_EQ(tight[e],
              !mesh.edges[e].boundary() && room[e] < cuts.label_room ? LabelFit::Tight : LabelFit::BothSides)
        << "edge " << e;
    if (tight[e] != LabelFit::BothSides) {
      ++tight_count;
      heaviest_tight = std::max(heaviest_tight, w[e]);
    } else {
      lightest_roomy = std::min(lightest_roomy, w[e]);
      EXPECT_DOUBLE_EQ(w[e], by_length[e]) << "edge " << e << " has room: the seam stays short";
    }
  }
  EXPECT_GT(tight_count, mesh.num_edges() / 3);
  EXPECT_LE(heaviest_tight + 1, lightest_roomy);  // a whole weight range apart
  // The spanning tree cuts fewer tight edges than the minimum-perimeter tree.
  auto tight_cuts = [&](const EdgeStates& s) {
    int n = 0;
    for (int e = 0; e < mesh.num_edges(); ++e)
      n += tight[e] != LabelFit::BothSides && is_cut(s, e) ? 1 : 0;
    return n;
  };
  const EdgeStates with_room = spanning_forest(mesh, w), shortest = spanning_forest(mesh, by_length);
  EXPECT_EQ(folds(with_room), mesh.num_faces() - 1);
  EXPECT_LT(tight_cuts(with_room), tight_cuts(shortest) / 2);
}

TEST(DualGraph, WithoutALabelRoomOrAtALargePrintNoEdgeIsTightAndTheWeightsStay) {
  Mesh mesh = load_mesh(test::example_mesh("bob_350.obj")).mesh;
  const std::vector<double> room = edge_label_room(mesh, 3);
  double least = 1e9;
  for (int e = 0; e < mesh.num_edges(); ++e)
    if (!mesh.edges[e].boundary()) least = std::min(least, room[e]);
  ASSERT_GT(least, 0);
  for (double label_room : {0.0, 0.5 * least}) {
    CutOptions cuts;
    cuts.label_room = label_room;
    const std::vector<LabelFit> tight = tight_edges(mesh, cuts);
    EXPECT_EQ(std::count(tight.begin(), tight.end(), LabelFit::BothSides), mesh.num_edges())
        << "label room " << label_room;
    EXPECT_EQ(cut_weights(mesh, cuts), min_perimeter_weights(mesh)) << "label room " << label_room;
  }
}

TEST(DualGraph, AnEdgeLongEnoughForATabLabelIsLessTightWhenOneSideHasRoom) {
  Mesh mesh = load_mesh(test::example_mesh("bob_350.obj")).mesh;
  CutOptions no_tabs;
  no_tabs.label_room = median(edge_label_room(mesh, 3));
  CutOptions tabs = no_tabs;
  tabs.label_tab_length = 1e-9;  // every edge takes a tab label
  const std::vector<LabelFit> without = tight_edges(mesh, no_tabs), with = tight_edges(mesh, tabs);
  const std::vector<double> w = cut_weights(mesh, tabs);
  int one_side = 0;
  for (int e = 0; e < mesh.num_edges(); ++e) {
    EXPECT_LE(with[e], without[e]) << "edge " << e;
    if (with[e] == LabelFit::OnTab) {
      ++one_side;
      EXPECT_EQ(without[e], LabelFit::Tight);
      EXPECT_LT(w[e], 0);   // below every edge with room on both sides
      EXPECT_GE(w[e], -1);  // above every edge where no label fits
    }
  }
  EXPECT_GT(one_side, mesh.num_edges() / 10);
}
