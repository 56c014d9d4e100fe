#include "foldkit/unfold/decompose.hpp"

#include <algorithm>
#include <numeric>

#include "foldkit/error.hpp"

namespace foldkit::unfold {

EdgeStates initial_patches(const UnfoldContext& ctx, double disconnected_share,
                           const EdgeConstraints& constraints) {
  const Mesh& m = *ctx.mesh;
  int interior = 0;
  for (const auto& e : m.edges)
    interior += e.boundary() ? 0 : 1;
  const int target_folds = static_cast<int>(std::lround((1.0 - disconnected_share) * interior));
  // Kruskal skips edges that close cycles, so the share of folds is not a simple quantile of the
  // weights: search the threshold over the ranks of the sorted weights instead (monotone in the rank).
  std::vector<int> order(m.num_edges());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return ctx.weight[a] < ctx.weight[b]; });
  std::vector<double> rank(m.num_edges());
  for (int i = 0; i < m.num_edges(); ++i)
    rank[order[i]] = i;
  auto folds_below = [&](int k) { return spanning_forest(m, rank, constraints, k); };
  auto count = [](const EdgeStates& state) {
    return static_cast<int>(std::count(state.begin(), state.end(), EdgeState::Fold));
  };
  int lo = 0, hi = m.num_edges();
  while (lo < hi) {
    int mid = lo + (hi - lo) / 2;
    if (count(folds_below(mid)) >= target_folds)
      hi = mid;
    else
      lo = mid + 1;
  }
  return folds_below(lo);
}

void cut_overlaps(CutTree& tree, const EdgeConstraints& constraints) {
  const auto& w = tree.context().weight;
  while (tree.overlap_count() > 0) {
    int f = tree.overlapping_faces().front();
    int g = tree.overlap_partners(f).front();
    EdgeId best;
    for (EdgeId e : tree.path(FaceId(f), FaceId(g)))
      if (!constraints.fold(e) && (!best.valid() || w[e.index()] > w[best.index()])) best = e;
    if (!best.valid())
      throw Error("the edges to keep folded make a piece overlap itself: keep fewer edges", ExitCode::Usage);
    tree.cut(best);
  }
}

}  // namespace foldkit::unfold
