#include "foldkit/unfold/decompose.hpp"

#include <algorithm>
#include <numeric>

#include "foldkit/error.hpp"

namespace foldkit::unfold {

std::vector<char> initial_patch_folds(const UnfoldContext& ctx, double disconnected_share,
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
  auto folds_below = [&](int k) {
    std::vector<char> fold = folds_from_cuts(spanning_forest_cuts(m, rank, constraints, k));
    return fold;
  };
  auto count = [](const std::vector<char>& fold) {
    return static_cast<int>(std::count(fold.begin(), fold.end(), 1));
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
    int best = -1;
    for (int e : tree.path(f, g))
      if (!constraints.fold(e) && (best < 0 || w[e] > w[best])) best = e;
    if (best < 0)
      throw Error("the edges to keep folded make a piece overlap itself: keep fewer edges", ExitCode::Usage);
    tree.cut(best);
  }
}

}  // namespace foldkit::unfold
