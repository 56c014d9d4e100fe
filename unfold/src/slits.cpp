// Closing slits by tree moves. A move adds fold edge e at the slit vertex to the cuts and folds a cut
// edge a on the cycle this makes in the cut graph: in the dual, the side of e is cut off and glued back
// along a. Only the four end vertices of e and a change their cut count, so the change in slits is
// known before the (costly) overlap test, and only moves that lower it are tested.
#include "foldkit/unfold/slits.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <optional>

#include "foldkit/unfold/curvature.hpp"

namespace foldkit::unfold {
namespace {

bool slit_at(const CutTree& tree, const std::vector<double>& defect, int v, int cuts, double limit) {
  return cuts == 1 && tree.context().required_cuts[v] >= 1 && defect[v] < limit;
}

struct Move {
  int gain = 0;  // slits closed (positive is better)
  int cut = -1, fold = -1;
};

// Slits the move (cut `e`, fold `a`) closes, or nothing when it breaks the curvature rule.
std::optional<int> move_gain(const CutTree& tree, const std::vector<double>& defect, int e, int a,
                             double limit) {
  const Mesh& m = tree.mesh();
  std::array<int, 4> vs{m.edges[e].v[0], m.edges[e].v[1], m.edges[a].v[0], m.edges[a].v[1]};
  int gain = 0;
  for (int i = 0; i < 4; ++i) {
    const int v = vs[i];
    if (std::find(vs.begin(), vs.begin() + i, v) != vs.begin() + i) continue;
    const int before = tree.cut_count(v);
    const int after = before + (v == vs[0] || v == vs[1]) - (v == vs[2] || v == vs[3]);
    if (after < tree.context().required_cuts[v]) return std::nullopt;
    gain += slit_at(tree, defect, v, before, limit) - slit_at(tree, defect, v, after, limit);
  }
  return gain;
}

}  // namespace

bool is_slit(const CutTree& tree, const std::vector<double>& defect_rad, int v, double min_leaf_defect_rad) {
  return slit_at(tree, defect_rad, v, tree.cut_count(v), min_leaf_defect_rad);
}

int count_slits(const CutTree& tree, const std::vector<double>& defect_rad, double min_leaf_defect_rad) {
  int n = 0;
  for (int v = 0; v < tree.mesh().num_vertices(); ++v)
    n += is_slit(tree, defect_rad, v, min_leaf_defect_rad);
  return n;
}

SlitResult close_slits(CutTree& tree, const EdgeConstraints& cons, const SlitOptions& options) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  auto out_of_time = [&] {
    return std::chrono::duration<double>(Clock::now() - start).count() >= options.time_limit_s;
  };
  const Mesh& m = tree.mesh();
  const double limit = options.min_leaf_defect_rad;
  const std::vector<double> defect = angle_defects(m);
  std::vector<std::vector<int>> edges_at(m.num_vertices());
  for (int e = 0; e < m.num_edges(); ++e)
    for (int v : m.edges[e].v)
      edges_at[v].push_back(e);

  SlitResult result;
  result.slits_before = count_slits(tree, defect, limit);
  std::vector<int> side;
  std::vector<Move> candidates;
  bool stopped = false;
  for (int pass = 0; pass < options.max_passes && !stopped; ++pass) {
    int moves_this_pass = 0;
    for (int v = 0; v < m.num_vertices() && !stopped; ++v) {
      if (!is_slit(tree, defect, v, limit)) continue;
      // The best move over every fold edge at v: the largest gain, then the first found.
      Move best;
      for (int e : edges_at[v]) {
        if (!tree.folded(e) || cons.fold(e)) continue;
        tree.smaller_side(e, side);
        candidates.clear();
        for (int x : side)
          for (int a : m.face_edges[x]) {
            if (a == e || tree.folded(a) || m.edges[a].boundary() || cons.cut(a)) continue;
            const int y = tree.across(a, x);
            if (tree.in_side(y) || tree.piece(y) != tree.piece(x)) continue;
            const std::optional<int> gain = move_gain(tree, defect, e, a, limit);
            if (gain && *gain > best.gain) candidates.push_back({*gain, e, a});
          }
        std::stable_sort(candidates.begin(), candidates.end(),
                         [](const Move& p, const Move& q) { return p.gain > q.gain; });
        for (const Move& c : candidates) {
          if (c.gain <= best.gain) break;
          if (out_of_time()) {
            stopped = true;
            break;
          }
          if (tree.reattach_cost(side, c.fold, 0) == 0) {
            best = c;
            break;
          }
        }
        if (stopped) break;
      }
      if (best.cut < 0) continue;
      tree.smaller_side(best.cut, side);
      tree.reattach(side, best.cut, best.fold);
      ++result.moves;
      ++moves_this_pass;
    }
    if (moves_this_pass == 0) break;
  }
  result.slits_after = count_slits(tree, defect, limit);
  return result;
}

}  // namespace foldkit::unfold
