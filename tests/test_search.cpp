// The repair search: one overlap-free piece on the bundled meshes, valid results whatever happens
// (time limit, forced seams), the same result for the same seed.
#include <gtest/gtest.h>

#include <algorithm>

#include "foldkit/unfold/dual_graph.hpp"
#include "foldkit/unfold/mesh_io.hpp"
#include "foldkit/unfold/search.hpp"
#include "foldkit/unfold/unfold.hpp"
#include "foldkit/unfold/unfolding.hpp"
#include "test_paths.hpp"

using namespace foldkit;
using namespace foldkit::unfold;

namespace {

Mesh load(const std::string& name) {
  return load_mesh(test::example_mesh(name)).mesh;
}

EdgeStates mst_folds(const UnfoldContext& ctx, const EdgeConstraints& c = {}) {
  return spanning_forest(*ctx.mesh, ctx.weight, c);
}

SearchResult search_on_threads(const UnfoldContext& ctx, SearchOptions opt, int threads) {
  opt.threads = threads;
  return search_unfold(ctx, mst_folds(ctx), opt);
}

std::string joined(const std::vector<std::string>& lines) {
  std::string s;
  for (const auto& l : lines)
    s += l + "\n";
  return s;
}

}  // namespace

class SearchOnExamples : public ::testing::TestWithParam<const char*> {};

TEST_P(SearchOnExamples, ReachesOneValidPieceWithAFixedSeed) {
  const Mesh mesh = load(GetParam());
  const UnfoldContext ctx = make_context(mesh);
  SearchOptions opt;
  opt.seed = 3;
  opt.time_limit_s = 30;
  const SearchResult r = search_unfold(ctx, mst_folds(ctx), opt);
  ASSERT_TRUE(r.solved);
  const Unfolding u = flatten(mesh, r.edges);
  EXPECT_EQ(u.piece_count, 1);
  EXPECT_EQ(check_unfolding(mesh, u), std::vector<std::string>{}) << joined(check_unfolding(mesh, u));
}

INSTANTIATE_TEST_SUITE_P(Examples, SearchOnExamples,
                         ::testing::Values("spot_350.obj", "fish_350.obj", "bob_350.obj", "penguin_500.obj"));

TEST(Search, TheSameSeedGivesTheSameCuts) {
  const Mesh mesh = load("penguin_500.obj");
  const UnfoldContext ctx = make_context(mesh);
  SearchOptions opt;
  opt.seed = 42;
  const SearchResult a = search_unfold(ctx, mst_folds(ctx), opt);
  const SearchResult b = search_unfold(ctx, mst_folds(ctx), opt);
  ASSERT_TRUE(a.solved);
  EXPECT_TRUE(a.edges == b.edges);
  EXPECT_EQ(a.steps, b.steps);
}

TEST(Search, ThePortfolioGivesTheSameCutsOnOneOrTwoThreads) {
  const Mesh mesh = load("bob_350.obj");
  const UnfoldContext ctx = make_context(mesh);
  SearchOptions opt;
  opt.seed = 7;
  opt.portfolio = 3;
  opt.round_steps = 64;  // many rounds, so that a timing-dependent winner would show
  const SearchResult one = search_on_threads(ctx, opt, 1);
  const SearchResult two = search_on_threads(ctx, opt, 2);
  const SearchResult three = search_on_threads(ctx, opt, 3);
  ASSERT_TRUE(one.solved);
  EXPECT_TRUE(one.edges == two.edges);
  EXPECT_EQ(one.steps, two.steps);
  EXPECT_TRUE(one.edges == three.edges);
  EXPECT_EQ(one.steps, three.steps);
}

TEST(Search, OutOfTimeTheBestTreeIsCutApartIntoAValidUnfolding) {
  const Mesh mesh = load("fish_350.obj");
  const UnfoldContext ctx = make_context(mesh);
  SearchOptions opt;
  opt.time_limit_s = 0;
  const SearchResult r = search_unfold(ctx, mst_folds(ctx), opt);
  EXPECT_FALSE(r.solved);
  EXPECT_GT(r.overlaps_left, 0);
  const Unfolding u = flatten(mesh, r.edges);
  EXPECT_GT(u.piece_count, 1);
  EXPECT_EQ(check_unfolding(mesh, u), std::vector<std::string>{}) << joined(check_unfolding(mesh, u));
}

TEST(Search, AStepBudgetStopsEveryWalkAtTheSameTreeWhateverTheThreads) {
  // fish_350's spanning tree overlaps and is not untangled in 3 steps: every walk stops at its budget,
  // and the best tree, cut apart, is the same on one thread as on two.
  const Mesh mesh = load("fish_350.obj");
  const UnfoldContext ctx = make_context(mesh);
  SearchOptions opt;
  opt.portfolio = 2;
  opt.max_steps = 3;
  const SearchResult one = search_on_threads(ctx, opt, 1);
  const SearchResult two = search_on_threads(ctx, opt, 2);
  EXPECT_FALSE(one.solved);
  EXPECT_EQ(one.steps, 2 * 3);
  EXPECT_TRUE(one.edges == two.edges);
  EXPECT_EQ(one.steps, two.steps);
  const Unfolding u = flatten(mesh, one.edges);
  EXPECT_EQ(check_unfolding(mesh, u), std::vector<std::string>{}) << joined(check_unfolding(mesh, u));
}

TEST(Search, ACancelledSearchStopsAtOnceAndStillReturnsAValidUnfolding) {
  // fish_350's spanning tree overlaps (see above): cancelled before its first step, the search is not solved.
  const Mesh mesh = load("fish_350.obj");
  const UnfoldContext ctx = make_context(mesh);
  int calls = 0;
  const SearchResult r = search_unfold(ctx, mst_folds(ctx), SearchOptions{}, [&](const UnfoldProgress& p) {
    ++calls;
    EXPECT_EQ(p.stage, "search");
    return false;
  });
  EXPECT_EQ(calls, 1) << "asked before the first step, and never again after answering stop";
  EXPECT_EQ(r.steps, 0);
  EXPECT_FALSE(r.solved);
  const Unfolding u = flatten(mesh, r.edges);
  EXPECT_GT(u.piece_count, 1);
  EXPECT_EQ(check_unfolding(mesh, u), std::vector<std::string>{}) << joined(check_unfolding(mesh, u));
}

TEST(Search, TheProgressCallbackIsAskedDuringARoundAndItsAnswerStopsTheSearch) {
  // A walk that can never move (no candidate moves, no restarts) and one round longer than the time
  // limit: only reports from inside the round can reach the callback, and only its answer ends the walk.
  const Mesh mesh = load("fish_350.obj");
  const UnfoldContext ctx = make_context(mesh);
  SearchOptions opt;
  opt.portfolio = 1;
  opt.candidates_per_move = 0;
  opt.restart_after = 1 << 30;
  opt.round_steps = 1 << 30;
  opt.time_limit_s = 20;
  std::vector<UnfoldProgress> reports;
  const SearchResult r = search_unfold(ctx, mst_folds(ctx), opt, [&](const UnfoldProgress& p) {
    reports.push_back(p);
    return reports.size() < 3;
  });
  ASSERT_EQ(reports.size(), 3u);
  for (std::size_t k = 1; k < reports.size(); ++k) {
    EXPECT_GT(reports[k].seconds, reports[k - 1].seconds);
    EXPECT_GT(reports[k].iteration, reports[k - 1].iteration) << "steps counted as the walk goes";
  }
  EXPECT_LT(reports.back().seconds, 10.0) << "stopped by the answer, not by the time limit";
  EXPECT_FALSE(r.solved);
  EXPECT_GE(r.steps, reports.back().iteration);
}

TEST(Search, ForcedCutsStayCutAndKeptEdgesStayFolded) {
  const Mesh mesh = load("spot_350.obj");
  const UnfoldContext ctx = make_context(mesh);
  EdgeConstraints c;
  c.rule.assign(mesh.num_edges(), EdgeRule::Free);
  // Cut a short chain of edges around face 0's first vertex; keep the edges of face 100 folded.
  for (int e : mesh.face_edges[0])
    c.rule[EdgeId(e)] = EdgeRule::MustCut;
  for (int e : mesh.face_edges[100])
    c.rule[EdgeId(e)] = EdgeRule::MustFold;
  SearchOptions opt;
  opt.constraints = c;
  const SearchResult r = search_unfold(ctx, mst_folds(ctx, c), opt);
  for (int e = 0; e < mesh.num_edges(); ++e) {
    if (c.cut(EdgeId(e))) {
      EXPECT_EQ(r.edges[EdgeId(e)], EdgeState::Cut) << "edge " << e << " must be cut";
    }
    if (c.fold(EdgeId(e))) {
      EXPECT_EQ(r.edges[EdgeId(e)], EdgeState::Fold) << "edge " << e << " must stay folded";
    }
  }
  const Unfolding u = flatten(mesh, r.edges);
  EXPECT_EQ(check_unfolding(mesh, u), std::vector<std::string>{});
  // Face 0 cut all round is a piece of its own; solved, the rest is the other piece.
  EXPECT_EQ(std::count(u.piece_of_face.begin(), u.piece_of_face.end(), u.piece_of_face[0]), 1);
  ASSERT_TRUE(r.solved);
  EXPECT_EQ(u.piece_count, 2);
}

TEST(Search, ItsOwnOptionsReachItThroughUnfoldMesh) {
  // A search that may not move (no candidate moves, no restarts) cannot join fish_350's overlapping
  // spanning tree: set through UnfoldOptions::search, that must show in the result.
  const Mesh mesh = load("fish_350.obj");
  UnfoldOptions options;
  options.method = Method::Search;
  options.time_limit_s = 0.5;
  options.search.candidates_per_move = 0;
  options.search.restart_after = 1 << 30;
  const UnfoldResult r = unfold_mesh(mesh, options);
  EXPECT_GT(r.unfolding.piece_count, 1);
  EXPECT_TRUE(std::any_of(r.notes.begin(), r.notes.end(), [](const std::string& n) {
    return n.find("search stopped") != std::string::npos;
  }));
  EXPECT_EQ(check_unfolding(mesh, r.unfolding), std::vector<std::string>{});
}

TEST(Search, TreesKeptForLabelRoomNeverCostAPiece) {
  // fish_350's first tree overlaps. With one step for the trees that fold edges too tight for labels, the
  // search falls back to the weights without label room and still reaches one piece.
  const Mesh mesh = load("fish_350.obj");
  UnfoldOptions options;
  options.method = Method::Search;
  options.time_limit_s = 20;
  std::vector<double> room = edge_label_room(mesh, 3);
  std::nth_element(room.begin(), room.begin() + room.size() / 2, room.end());
  options.cuts.label_room = room[room.size() / 2];
  options.label_room_most_steps = 1;
  const UnfoldResult r = unfold_mesh(mesh, options);
  EXPECT_EQ(r.unfolding.piece_count, 1);
  EXPECT_EQ(check_unfolding(mesh, r.unfolding), std::vector<std::string>{});
}

TEST(Search, TiesBetweenMovesGoToTheCutsTheWeightsPrefer) {
  // Same mesh, seed and start; the walk that breaks ties by weight ends with heavier cuts on average.
  const Mesh mesh = load("fish_350.obj");
  const UnfoldContext ctx = make_context(mesh, {SeamPreference::Roomy, 3, 1});
  auto mean_cut_weight = [&](const EdgeStates& s) {
    double sum = 0;
    int n = 0;
    for (EdgeId e : all_ids<EdgeId>(mesh.num_edges()))
      if (s[e] == EdgeState::Cut && !mesh.edge(e).boundary()) {
        sum += ctx.weight[e.index()];
        ++n;
      }
    return sum / n;
  };
  SearchOptions opt;
  opt.seed = 5;
  opt.prefer_weighted_ties = false;
  const SearchResult plain = search_unfold(ctx, mst_folds(ctx), opt);
  opt.prefer_weighted_ties = true;
  const SearchResult ties = search_unfold(ctx, mst_folds(ctx), opt);
  ASSERT_TRUE(plain.solved);
  ASSERT_TRUE(ties.solved);
  EXPECT_EQ(check_unfolding(mesh, flatten(mesh, ties.edges)), std::vector<std::string>{});
  EXPECT_GT(mean_cut_weight(ties.edges), mean_cut_weight(plain.edges));
}

// Printed at 150 mm, a cut edge too tight for its label leaves the label crossing a line. Drawing the
// heaviest of several path edges as each candidate cut (the tight ones are the lightest) leads the walk
// to cut fewer of them, still to one valid piece.
TEST(Search, DrawingTheHeaviestOfSeveralPathEdgesCutsFewerEdgesTooTightForALabel) {
  for (const char* name : {"fish_350.obj", "penguin_500.obj"}) {
    const Mesh mesh = load(name);
    const double extent = flatten(mesh, mst_folds(make_context(mesh))).model_extent;
    // A two-digit label at 2 mm (cli/print_cuts.cpp): 2.85 mm tall, 3.3 mm wide, at 150 mm.
    CutOptions cuts;
    cuts.label_aspect = 3.3 / 2.85;
    cuts.label_room = 2.85 * extent / 150;
    const UnfoldContext ctx = make_context(mesh, cuts);
    const std::vector<LabelFit> fit = tight_edges(mesh, cuts);
    const auto tight_cuts = [&](const EdgeStates& s) {
      int n = 0;
      for (EdgeId e : all_ids<EdgeId>(mesh.num_edges()))
        n += s[e] == EdgeState::Cut && !mesh.edge(e).boundary() && fit[e.index()] == LabelFit::Tight;
      return n;
    };
    int uniform = 0, drawn = 0;
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      SearchOptions opt;
      opt.seed = seed;
      const SearchResult plain = search_unfold(ctx, mst_folds(ctx), opt);
      opt.cut_draws = 6;
      const SearchResult heavier = search_unfold(ctx, mst_folds(ctx), opt);
      ASSERT_TRUE(plain.solved && heavier.solved) << name << " seed " << seed;
      EXPECT_EQ(check_unfolding(mesh, flatten(mesh, heavier.edges)), std::vector<std::string>{});
      uniform += tight_cuts(plain.edges);
      drawn += tight_cuts(heavier.edges);
    }
    // fish_350 63 -> 39, penguin_500 42 -> 17 when written.
    EXPECT_LT(drawn, uniform) << name;
  }
}
