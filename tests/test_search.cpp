// The repair search: one overlap-free piece on the bundled meshes, valid results whatever happens
// (time limit, forced seams), the same result for the same seed.
#include <gtest/gtest.h>

#include "foldkit/unfold/dual_graph.hpp"
#include "foldkit/unfold/mesh_io.hpp"
#include "foldkit/unfold/search.hpp"
#include "foldkit/unfold/unfolding.hpp"
#include "test_paths.hpp"

using namespace foldkit;
using namespace foldkit::unfold;

namespace {

Mesh load(const std::string& name) {
  return load_mesh(test::example_mesh(name)).mesh;
}

std::vector<char> mst_folds(const UnfoldContext& ctx, const EdgeConstraints& c = {}) {
  return folds_from_cuts(spanning_forest_cuts(*ctx.mesh, ctx.weight, c));
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
  const Unfolding u = flatten(mesh, r.cut);
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
  EXPECT_EQ(a.cut, b.cut);
  EXPECT_EQ(a.steps, b.steps);
}

TEST(Search, ThePortfolioGivesTheSameCutsOnOneOrTwoThreads) {
  const Mesh mesh = load("bob_350.obj");
  const UnfoldContext ctx = make_context(mesh);
  SearchOptions opt;
  opt.seed = 7;
  opt.portfolio = 3;
  opt.round_steps = 64;  // many rounds, so that a timing-dependent winner would show
  opt.threads = 1;
  const SearchResult one = search_unfold(ctx, mst_folds(ctx), opt);
  opt.threads = 2;
  const SearchResult two = search_unfold(ctx, mst_folds(ctx), opt);
  opt.threads = 3;
  const SearchResult three = search_unfold(ctx, mst_folds(ctx), opt);
  ASSERT_TRUE(one.solved);
  EXPECT_EQ(one.cut, two.cut);
  EXPECT_EQ(one.steps, two.steps);
  EXPECT_EQ(one.cut, three.cut);
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
  const Unfolding u = flatten(mesh, r.cut);
  EXPECT_GT(u.piece_count, 1);
  EXPECT_EQ(check_unfolding(mesh, u), std::vector<std::string>{}) << joined(check_unfolding(mesh, u));
}

TEST(Search, ACancelledSearchStillReturnsAValidUnfolding) {
  const Mesh mesh = load("bob_350.obj");
  const UnfoldContext ctx = make_context(mesh);
  int calls = 0;
  SearchOptions opt;
  // Restarting constantly keeps the search busy long enough for the callback to be asked.
  opt.restart_after = 1;
  opt.candidates_per_move = 1;
  const SearchResult r = search_unfold(ctx, mst_folds(ctx), opt, [&](const UnfoldProgress&) {
    ++calls;
    return false;
  });
  const Unfolding u = flatten(mesh, r.cut);
  EXPECT_EQ(check_unfolding(mesh, u), std::vector<std::string>{});
  if (calls > 0) {
    EXPECT_FALSE(r.solved);
  }
}

TEST(Search, ForcedCutsStayCutAndKeptEdgesStayFolded) {
  const Mesh mesh = load("spot_350.obj");
  const UnfoldContext ctx = make_context(mesh);
  EdgeConstraints c;
  c.force_cut.assign(mesh.num_edges(), 0);
  c.force_fold.assign(mesh.num_edges(), 0);
  // Cut a short chain of edges around face 0's first vertex; keep the edges of face 100 folded.
  for (int e : mesh.face_edges[0])
    c.force_cut[e] = 1;
  for (int e : mesh.face_edges[100])
    c.force_fold[e] = 1;
  SearchOptions opt;
  opt.constraints = c;
  const SearchResult r = search_unfold(ctx, mst_folds(ctx, c), opt);
  for (int e = 0; e < mesh.num_edges(); ++e) {
    if (c.force_cut[e]) {
      EXPECT_TRUE(r.cut[e]) << "edge " << e << " must be cut";
    }
    if (c.force_fold[e]) {
      EXPECT_FALSE(r.cut[e]) << "edge " << e << " must stay folded";
    }
  }
  const Unfolding u = flatten(mesh, r.cut);
  EXPECT_EQ(check_unfolding(mesh, u), std::vector<std::string>{});
  // Face 0 cut all round is a piece of its own.
  EXPECT_EQ(u.piece_count, r.solved ? 2 : u.piece_count);
}
