// The repair search. Each step picks an overlapping pair, tries a few (cut edge on their tree path,
// re-attach edge of the cut-off side) moves, and applies the one that lowers the overlap count most
// (or keeps it, to walk plateaus). Only the moved side is re-tested (CutTree::reattach_cost), which is
// what keeps steps cheap at thousands of faces. A short tabu list stops the walk from undoing itself;
// a restart from a perturbed minimum-perimeter tree leaves regions where it stalls.
#include "foldkit/unfold/search.hpp"

#include <algorithm>
#include <chrono>
#include <numeric>
#include <random>

#include "foldkit/unfold/mst.hpp"

namespace foldkit::unfold {

void join_all_pieces(CutTree& tree, const EdgeConstraints& constraints) {
  const Mesh& m = tree.mesh();
  const auto& w = tree.context().weight;
  std::vector<int> order;
  for (int e = 0; e < m.num_edges(); ++e) {
    const auto& edge = m.edges[e];
    if (edge.boundary() || tree.folded(e) || constraints.cut(e)) continue;
    if (tree.piece(edge.face[0]) != tree.piece(edge.face[1])) order.push_back(e);
  }
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return w[a] < w[b]; });
  for (int e : order) {
    const auto& edge = m.edges[e];
    if (tree.piece(edge.face[0]) != tree.piece(edge.face[1])) tree.stitch(e);
  }
}

namespace {

int uniform(std::mt19937_64& rng, std::size_t n) {
  return static_cast<int>(std::uniform_int_distribution<std::size_t>(0, n - 1)(rng));
}

}  // namespace

SearchResult search_unfold(const UnfoldContext& ctx, std::vector<char> initial_fold, const SearchOptions& opt,
                           const ProgressFn& progress) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
  const Mesh& m = *ctx.mesh;
  const auto& cons = opt.constraints;
  std::mt19937_64 rng(opt.seed);

  CutTree tree(ctx, std::move(initial_fold));
  join_all_pieces(tree, cons);
  SearchResult res;
  int best = tree.overlap_count();
  std::vector<char> best_fold = tree.fold_flags();
  std::vector<int> tabu_until(m.num_edges(), 0);
  std::vector<int> side, attach, near;
  int stall = 0, kick = 0, kicks_since_restart = 0;
  double next_report = 0.2;
  bool stopped = false;
  auto tabu = [&](int e) { return tabu_until[e] > res.steps; };

  while (tree.overlap_count() > 0) {
    if ((res.steps & 15) == 0) {
      double t = elapsed();
      if (t >= opt.time_limit_s) break;
      if (progress && t >= next_report) {
        next_report = t + 0.2;
        if (!progress({opt.stage, res.steps, tree.piece_count(), static_cast<double>(best), t})) {
          stopped = true;
          break;
        }
      }
    }
    ++res.steps;
    const auto& hot = tree.overlapping_faces();
    int f = hot[uniform(rng, hot.size())];
    const auto& partners = tree.overlap_partners(f);
    int g = partners[uniform(rng, partners.size())];
    const std::vector<int> path = tree.path(f, g);
    if (path.empty()) continue;

    // During a kick any move is taken (the least bad of the candidates), to leave a local minimum.
    int best_delta = kick > 0 ? (1 << 20) : opt.max_uphill + 1, best_cut = -1, best_attach = -1;
    if (kick > 0) --kick;
    for (int k = 0; k < opt.candidates_per_move; ++k) {
      int e = path[uniform(rng, path.size())];
      if (tabu(e) || cons.fold(e)) continue;
      tree.smaller_side(e, side);
      const int old = tree.cross_overlaps(side);
      const auto& ev = m.edges[e].v;
      attach.clear();
      for (int x : side) {
        for (int a : m.face_edges[x]) {
          const auto& edge = m.edges[a];
          if (a == e || tree.folded(a) || edge.boundary() || cons.cut(a) || tabu(a)) continue;
          if (tree.in_side(tree.across(a, x))) continue;
          // Curvature rule as a pre-filter: after cutting e and folding a, both ends of a must keep
          // the cut edges their class needs, or the move creates a local overlap for certain.
          bool ok = true;
          for (int v : edge.v) {
            int after = tree.cut_count(v) - 1 + ((v == ev[0] || v == ev[1]) ? 1 : 0);
            if (after < ctx.required_cuts[v]) ok = false;
          }
          if (ok) attach.push_back(a);
        }
      }
      if (attach.empty()) continue;
      // Edges sharing a vertex with e turn the side about that vertex: a small motion, so few new
      // overlaps. These are tried first; a random edge anywhere on the side gives the long jumps.
      near.clear();
      for (int a : attach) {
        const auto& av = m.edges[a].v;
        if (av[0] == ev[0] || av[0] == ev[1] || av[1] == ev[0] || av[1] == ev[1]) near.push_back(a);
      }
      const int tries = std::min<int>(opt.attach_tries, static_cast<int>(attach.size()));
      for (int t = 0; t < tries; ++t) {
        int a = (t == 0 && opt.near_first && !near.empty()) ? near[uniform(rng, near.size())]
                                                            : attach[uniform(rng, attach.size())];
        const int limit = old + best_delta - 1;
        if (limit < 0) break;
        int cost = tree.reattach_cost(side, a, limit);
        if (cost <= limit) {
          best_delta = cost - old;
          best_cut = e;
          best_attach = a;
        }
      }
    }
    if (best_cut >= 0) {
      tree.smaller_side(best_cut, side);
      tree.reattach(side, best_cut, best_attach);
      tabu_until[best_cut] = tabu_until[best_attach] = res.steps + opt.tabu_tenure;
      ++res.moves;
    }
    if (tree.overlap_count() < best) {
      best = tree.overlap_count();
      best_fold = tree.fold_flags();
      stall = 0;
    } else if (++stall >= opt.restart_after && opt.kicks_per_restart > 0 &&
               kicks_since_restart < opt.kicks_per_restart) {
      // Back to the best tree, then a few forced moves: stays near the best tree (which a fresh
      // tree would throw away) while changing enough to escape its local minimum.
      tree = CutTree(ctx, best_fold);
      std::fill(tabu_until.begin(), tabu_until.end(), 0);
      kick = opt.kick_moves;
      stall = 0;
      ++kicks_since_restart;
      ++res.restarts;
    } else if (stall >= opt.restart_after) {
      kicks_since_restart = 0;
      // A fresh tree from perturbed minimum-perimeter weights: close to the good trees, but
      // different enough to leave a region the walk keeps returning to.
      std::vector<double> w = ctx.weight;
      std::uniform_real_distribution<double> noise(0.0, 0.3);
      for (double& x : w)
        x += noise(rng);
      tree = CutTree(ctx, folds_from_cuts(spanning_forest_cuts(m, w, cons)));
      std::fill(tabu_until.begin(), tabu_until.end(), 0);
      stall = 0;
      ++res.restarts;
      if (tree.overlap_count() < best) {
        best = tree.overlap_count();
        best_fold = tree.fold_flags();
      }
    }
  }
  (void)stopped;
  if (tree.overlap_count() == 0) {
    res.cut = tree.cut_flags();
    res.solved = true;
    res.best_fold = tree.fold_flags();
    return res;
  }
  // Out of time: the best tree, cut apart where it still overlaps, so the result is always valid.
  res.overlaps_left = best;
  res.cut = folds_from_cuts(best_fold);
  res.best_fold = std::move(best_fold);
  cut_until_no_overlap(m, res.cut, ctx.weight, cons);
  return res;
}

}  // namespace foldkit::unfold
