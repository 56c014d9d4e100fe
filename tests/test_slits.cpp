// Slits: a leaf's two sides meet at its vertex's angle defect, a seam is a slit below the gap limit.
#include <gtest/gtest.h>

#include <cmath>

#include "foldkit/unfold/curvature.hpp"
#include "foldkit/unfold/dual_graph.hpp"
#include "foldkit/unfold/mesh_io.hpp"
#include "foldkit/unfold/search.hpp"
#include "foldkit/unfold/slits.hpp"
#include "test_paths.hpp"

using namespace foldkit;
using namespace foldkit::unfold;

namespace {

// The search's one overlap-free piece of `mesh`, as a CutTree.
CutTree solved_tree(const UnfoldContext& ctx) {
  const SearchResult r = search_unfold(ctx, spanning_forest(*ctx.mesh, ctx.weight, {}), SearchOptions{});
  EXPECT_TRUE(r.solved);
  return CutTree(ctx, r.edges);
}

}  // namespace

TEST(Slits, ALeafAtAFlatVertexIsASlitAndOneAtAConePointIsNot) {
  const Mesh mesh = load_mesh(test::example_mesh("spot_350.obj")).mesh;
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
        EXPECT_LT(seam_gap_per_length(tree, e), kSlitGapPerLength);
      } else if (defect[v] > 0.85) {
        EXPECT_GT(seam_gap_per_length(tree, e), kSlitGapPerLength);
      }
    }
  }
  EXPECT_GT(flat, 0);
  EXPECT_GT(cones, 0);  // spot's ears, horns and hooves
  EXPECT_EQ(count_slits(tree, 0.0), 0);
}
