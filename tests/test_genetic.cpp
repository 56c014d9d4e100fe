// The seed's method: initial patches (§4), fitness (§5.3), crossover (§5.4), rearrangement (§6) and
// the whole GA, on the bundled meshes with fixed seeds.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

#include "foldkit/unfold/decompose.hpp"
#include "foldkit/unfold/fitness.hpp"
#include "foldkit/unfold/genetic.hpp"
#include "foldkit/unfold/mesh_io.hpp"
#include "foldkit/unfold/rearrange.hpp"
#include "foldkit/unfold/unfolding.hpp"
#include "test_paths.hpp"

using namespace foldkit;
using namespace foldkit::unfold;

namespace {

Mesh load(const std::string& name) {
  return load_mesh(test::example_mesh(name)).mesh;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string s;
  for (const auto& l : lines)
    s += l + "\n";
  return s;
}

}  // namespace

TEST(InitialPatches, CutAboutTheAskedShareOfTheDualEdgesAndOverlapNowhereOnceResolved) {
  const Mesh mesh = load("bob_350.obj");
  const UnfoldContext ctx = make_context(mesh);
  int interior = 0;
  for (const auto& e : mesh.edges)
    interior += e.boundary() ? 0 : 1;
  for (double share : {0.65, 0.70, 0.75}) {
    const EdgeStates patches = initial_patches(ctx, share, {});
    const double cut_share =
        1.0 - static_cast<double>(std::count(patches.begin(), patches.end(), EdgeState::Fold)) / interior;
    EXPECT_NEAR(cut_share, share, 0.02);
    CutTree tree(ctx, patches);
    cut_overlaps(tree, {});
    EXPECT_EQ(tree.overlap_count(), 0);
    EXPECT_GT(tree.piece_count(), mesh.num_faces() / 4) << "patches are small";
    EXPECT_EQ(check_unfolding(mesh, flatten(mesh, tree.states())), std::vector<std::string>{});
  }
}

TEST(Fitness, TermsStayInRangeAndOnePieceHasNoFacesOutsideTheLargest) {
  const Mesh mesh = load("spot_350.obj");
  const UnfoldContext ctx = make_context(mesh);
  CutTree patches(ctx, initial_patches(ctx, 0.7, {}));
  FitnessTerms t = fitness_terms(patches);
  EXPECT_EQ(t.pieces, patches.piece_count());
  for (double r : {t.rl, t.rm, t.rb}) {
    EXPECT_GE(r, 0.0);
    EXPECT_LE(r, 1.0);
  }
  EXPECT_GT(t.rl, 0.5);
  CutTree tree(ctx, spanning_forest(mesh, ctx.weight));
  FitnessTerms one = fitness_terms(tree);
  EXPECT_EQ(one.pieces, 1);
  EXPECT_EQ(one.rl, 0.0);
  EXPECT_GT(one.rb, 0.0);
  EXPECT_LT(one.rb, 0.5);
  EXPECT_LT(fitness(one, {}), fitness(t, {}));
}

TEST(Crossover, KeepsSharedSuccessesAndFailuresInPlaceAndYieldsAPermutation) {
  std::mt19937_64 rng(5);
  for (int round = 0; round < 200; ++round) {
    const int n = 2 + round % 40;
    std::vector<int> p(n), q(n);
    std::iota(p.begin(), p.end(), 0);
    std::iota(q.begin(), q.end(), 0);
    std::shuffle(p.begin(), p.end(), rng);
    std::shuffle(q.begin(), q.end(), rng);
    const int sp = std::uniform_int_distribution<int>(0, n)(rng),
              sq = std::uniform_int_distribution<int>(0, n)(rng);
    const std::vector<int> c = crossover(p, sp, q, sq, rng());
    std::vector<int> sorted = c;
    std::sort(sorted.begin(), sorted.end());
    std::vector<int> ids(n);
    std::iota(ids.begin(), ids.end(), 0);
    ASSERT_EQ(sorted, ids);
    auto success_in = [](const std::vector<int>& v, int s, int x) {
      return std::find(v.begin(), v.begin() + s, x) != v.begin() + s;
    };
    for (int i = 0; i < n; ++i) {
      const int x = p[i];
      const bool shared = success_in(p, sp, x) == success_in(q, sq, x);
      if (shared) {
        EXPECT_EQ(c[i], x) << "edge " << x << " is a shared "
                           << (success_in(p, sp, x) ? "success" : "failure");
      }
    }
  }
}

TEST(Rearrange, LeavesAnOverlapFreeStateWithConsistentCurvatureCounts) {
  const Mesh mesh = load("fish_350.obj");
  const UnfoldContext ctx = make_context(mesh);
  CutTree tree(ctx, initial_patches(ctx, 0.65, {}));
  cut_overlaps(tree, {});
  rearrange_pieces(tree, 1, {}, 4 * mesh.num_faces());
  EXPECT_EQ(tree.overlap_count(), 0);
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    int cuts = 0;
    for (int e = 0; e < mesh.num_edges(); ++e)
      if (!tree.folded(EdgeId(e)) && (mesh.edges[e].v[0] == v || mesh.edges[e].v[1] == v)) ++cuts;
    ASSERT_EQ(tree.cut_count(VertexId(v)), cuts) << "vertex " << v;
  }
  EXPECT_EQ(check_unfolding(mesh, flatten(mesh, tree.states())), std::vector<std::string>{});
}

class GaOnExamples : public ::testing::TestWithParam<const char*> {};

TEST_P(GaOnExamples, ReachesOneValidPieceWithAFixedSeed) {
  const Mesh mesh = load(GetParam());
  const UnfoldContext ctx = make_context(mesh);
  GaOptions opt;
  opt.seed = 2;
  opt.time_limit_s = 60;
  const GaResult r = genetic_unfold(ctx, opt);
  const Unfolding u = flatten(mesh, r.edges);
  EXPECT_EQ(u.piece_count, 1) << r.method;
  EXPECT_EQ(r.pieces, 1);
  EXPECT_EQ(check_unfolding(mesh, u), std::vector<std::string>{}) << joined(check_unfolding(mesh, u));
}

INSTANTIATE_TEST_SUITE_P(Examples, GaOnExamples,
                         ::testing::Values("spot_350.obj", "fish_350.obj", "bob_350.obj", "penguin_500.obj"));

TEST(Ga, OneAndTwoThreadsGiveTheSameUnfolding) {
  const Mesh mesh = load("spot_350.obj");
  const UnfoldContext ctx = make_context(mesh);
  GaOptions opt;
  opt.seed = 9;
  opt.threads = 1;
  const GaResult one = genetic_unfold(ctx, opt);
  opt.threads = 2;
  const GaResult two = genetic_unfold(ctx, opt);
  EXPECT_TRUE(one.edges == two.edges);
  EXPECT_EQ(one.method, two.method);
  EXPECT_EQ(one.score, two.score);
}

TEST(Ga, ForcedCutsStayCutAndKeptEdgesStayFolded) {
  const Mesh mesh = load("bob_350.obj");
  const UnfoldContext ctx = make_context(mesh);
  GaOptions opt;
  opt.constraints.rule.assign(mesh.num_edges(), EdgeRule::Free);
  for (int e : mesh.face_edges[10])
    opt.constraints.rule[EdgeId(e)] = EdgeRule::MustCut;
  for (int e : mesh.face_edges[200])
    opt.constraints.rule[EdgeId(e)] = EdgeRule::MustFold;
  const GaResult r = genetic_unfold(ctx, opt);
  for (int e = 0; e < mesh.num_edges(); ++e) {
    if (opt.constraints.cut(EdgeId(e))) {
      EXPECT_EQ(r.edges[EdgeId(e)], EdgeState::Cut) << "edge " << e;
    }
    if (opt.constraints.fold(EdgeId(e))) {
      EXPECT_EQ(r.edges[EdgeId(e)], EdgeState::Fold) << "edge " << e;
    }
  }
  EXPECT_EQ(check_unfolding(mesh, flatten(mesh, r.edges)), std::vector<std::string>{});
}

TEST(Ga, ACancelledGaStopsBeforeItsFirstGenerationAndStillReturnsAValidUnfolding) {
  const Mesh mesh = load("fish_350.obj");
  const UnfoldContext ctx = make_context(mesh);
  GaOptions opt;
  opt.seed = 2;
  std::vector<std::string> stages;
  const GaResult r = genetic_unfold(ctx, opt, [&](const UnfoldProgress& p) {
    stages.push_back(p.stage);
    return false;
  });
  EXPECT_EQ(r.generations, 0) << "stopped before the first generation";
  ASSERT_FALSE(stages.empty());
  EXPECT_EQ(stages.front(), "ga");
  EXPECT_EQ(std::count(stages.begin(), stages.end(), "ga"), 1) << "never asked again after answering stop";
  const Unfolding u = flatten(mesh, r.edges);
  EXPECT_EQ(check_unfolding(mesh, u), std::vector<std::string>{}) << joined(check_unfolding(mesh, u));
}
