// Closing slits: fewer cut-tree leaves at nearly flat vertices, the unfolding still one valid piece,
// forced seams and the curvature rule kept, the same result every time.
#include <gtest/gtest.h>

#include <cmath>

#include "foldkit/unfold/curvature.hpp"
#include "foldkit/unfold/dual_graph.hpp"
#include "foldkit/unfold/mesh_io.hpp"
#include "foldkit/unfold/search.hpp"
#include "foldkit/unfold/slits.hpp"
#include "foldkit/unfold/unfold.hpp"
#include "foldkit/unfold/unfolding.hpp"
#include "test_paths.hpp"

using namespace foldkit;
using namespace foldkit::unfold;

namespace {

Mesh load(const std::string& name) {
  return load_mesh(test::example_mesh(name)).mesh;
}

// The search's one overlap-free piece of `mesh`, as a CutTree.
CutTree solved_tree(const UnfoldContext& ctx, const EdgeConstraints& constraints = {}) {
  SearchOptions opt;
  opt.constraints = constraints;
  const SearchResult r = search_unfold(ctx, spanning_forest(*ctx.mesh, ctx.weight, constraints), opt);
  EXPECT_TRUE(r.solved);
  return CutTree(ctx, r.edges);
}

}  // namespace

class SlitsOnExamples : public ::testing::TestWithParam<const char*> {};

TEST_P(SlitsOnExamples, MostSlitsCloseAndTheUnfoldingStaysOneValidPiece) {
  const Mesh mesh = load(GetParam());
  const UnfoldContext ctx = make_context(mesh);
  CutTree tree = solved_tree(ctx);
  const SlitOptions opt;
  const int before = count_slits(tree, opt.min_gap_per_length);
  const SlitResult r = close_slits(tree, {}, opt);
  EXPECT_EQ(r.slits_before, before);
  EXPECT_EQ(r.slits_after, count_slits(tree, opt.min_gap_per_length));
  EXPECT_GT(before, 10);
  EXPECT_LE(3 * r.slits_after, before) << "closed only " << before - r.slits_after << " of " << before;
  EXPECT_EQ(tree.overlap_count(), 0);
  EXPECT_EQ(tree.piece_count(), 1);
  for (int v = 0; v < mesh.num_vertices(); ++v)
    EXPECT_GE(tree.cut_count(VertexId(v)), ctx.required_cuts[v]) << "vertex " << v;
  const Unfolding u = flatten(mesh, tree.states());
  EXPECT_EQ(u.piece_count, 1);
  EXPECT_EQ(check_unfolding(mesh, u), std::vector<std::string>{});
}

INSTANTIATE_TEST_SUITE_P(Examples, SlitsOnExamples, ::testing::Values("spot_350.obj", "bob_350.obj"));

TEST(Slits, ALeafAtAFlatVertexIsASlitAndOneAtAConePointIsNot) {
  const Mesh mesh = load("spot_350.obj");
  const UnfoldContext ctx = make_context(mesh);
  const CutTree tree = solved_tree(ctx);
  const std::vector<double> defect = angle_defects(mesh);
  int flat = 0, cones = 0;
  for (EdgeId e : all_ids<EdgeId>(mesh.num_edges())) {
    if (tree.folded(e)) {
      EXPECT_TRUE(std::isinf(seam_gap_per_length(tree, e)));
      continue;
    }
    for (int v : mesh.edge(e).v) {
      if (tree.cut_count(VertexId(v)) != 1) continue;
      // The far ends of a leaf's two sides are 2 sin(defect / 2) of its length apart.
      EXPECT_NEAR(seam_gap_per_length(tree, e), 2 * std::sin(0.5 * defect[v]), 1e-9);
      (defect[v] < 0.2 ? flat : cones) += 1;
      if (defect[v] < 0.2) {
        EXPECT_LT(seam_gap_per_length(tree, e), SlitOptions{}.min_gap_per_length);
      } else if (defect[v] > 0.85) {
        EXPECT_GT(seam_gap_per_length(tree, e), SlitOptions{}.min_gap_per_length);
      }
    }
  }
  EXPECT_GT(flat, 0);
  EXPECT_GT(cones, 0);  // spot's ears, horns and hooves
  EXPECT_EQ(count_slits(tree, 0.0), 0);
}

TEST(Slits, ForcedCutsAndFoldsAreKept) {
  const Mesh mesh = load("bob_350.obj");
  const UnfoldContext ctx = make_context(mesh);
  // Forbid cutting, and force, every tenth edge of a first solution's folds and cuts.
  const CutTree first = solved_tree(ctx);
  EdgeConstraints c;
  c.rule.assign(mesh.num_edges(), EdgeRule::Free);
  for (int e = 0; e < mesh.num_edges(); e += 10)
    c.rule[EdgeId(e)] = first.folded(EdgeId(e)) ? EdgeRule::MustFold : EdgeRule::MustCut;
  CutTree tree = solved_tree(ctx, c);
  for (EdgeId e : all_ids<EdgeId>(mesh.num_edges())) {
    if (c.fold(e)) {
      ASSERT_TRUE(tree.folded(e));
    }
    if (c.cut(e)) {
      ASSERT_FALSE(tree.folded(e));
    }
  }
  const SlitResult r = close_slits(tree, c, {});
  EXPECT_GT(r.moves, 0);
  for (EdgeId e : all_ids<EdgeId>(mesh.num_edges())) {
    if (c.fold(e)) {
      EXPECT_TRUE(tree.folded(e)) << "edge " << e.index();
    }
    if (c.cut(e)) {
      EXPECT_FALSE(tree.folded(e)) << "edge " << e.index();
    }
  }
  EXPECT_EQ(tree.overlap_count(), 0);
}

TEST(Slits, TheSameTreeGivesTheSameCuts) {
  const Mesh mesh = load("spot_350.obj");
  const UnfoldContext ctx = make_context(mesh);
  CutTree a = solved_tree(ctx);
  CutTree b = a;
  close_slits(a, {}, {});
  close_slits(b, {}, {});
  EXPECT_TRUE(a.states() == b.states());
}

TEST(Slits, TheUnfoldingStageClosesThemUnlessAskedNotTo) {
  const Mesh mesh = load("bob_350.obj");
  UnfoldOptions with, without;
  without.close_slits = false;
  const UnfoldResult a = unfold_mesh(mesh, with), b = unfold_mesh(mesh, without);
  const UnfoldContext ctx = make_context(mesh);
  auto slits = [&](const Unfolding& u) {
    return count_slits(CutTree(ctx, edge_states(u)), SlitOptions{}.min_gap_per_length);
  };
  EXPECT_EQ(a.unfolding.piece_count, 1);
  EXPECT_LT(2 * slits(a.unfolding), slits(b.unfolding));
  EXPECT_EQ(check_unfolding(mesh, a.unfolding), std::vector<std::string>{});
}

TEST(Slits, ProgressIsReportedPerSlitTriedWithCountsThatNeverFall) {
  const Mesh mesh = load("spot_350.obj");
  const UnfoldContext ctx = make_context(mesh);
  CutTree tree = solved_tree(ctx);
  SlitOptions opt;
  std::vector<std::pair<long, long>> seen;
  opt.progress = [&seen](long done, long total) { seen.emplace_back(done, total); };
  const SlitResult r = close_slits(tree, {}, opt);
  ASSERT_GE(static_cast<int>(seen.size()), r.slits_before) << "every slit is tried once in the first pass";
  // One total for the whole run (a bar that does not rescale), never reached before the run ends.
  for (std::size_t k = 0; k < seen.size(); ++k) {
    EXPECT_EQ(seen[k].second, seen.front().second) << "report " << k << " changed the total";
    EXPECT_LT(seen[k].first, seen[k].second);
    if (k > 0) {
      EXPECT_GT(seen[k].first, seen[k - 1].first) << "report " << k << " went back";
    }
  }
}
