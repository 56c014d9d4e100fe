// The repair search. Each step picks an overlapping pair, tries a few (cut edge on their tree path,
// re-attach edge of the cut-off side) moves, and applies the one that lowers the overlap count most
// (or keeps it, to walk plateaus). Only the moved side is re-tested (CutTree::reattach_cost), which is
// what keeps steps cheap at thousands of faces. A short tabu list stops the walk from undoing itself;
// a restart from a perturbed minimum-perimeter tree leaves regions where it stalls.
#include "foldkit/unfold/search.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <memory>
#include <numeric>
#include <random>
#include <thread>

#include "foldkit/unfold/mst.hpp"
#include "parallel.hpp"

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

// Steps a walk takes between two looks at the clock and the stop flag (and, on the calling thread, the
// progress callback): rare enough to cost nothing, often enough to stop within a millisecond or so.
constexpr int kCheckpointSteps = 16;
// Least time between two progress reports.
constexpr double kReportInterval_s = 0.2;
// The overlap change a kick starts from: larger than any move can add, so the least bad candidate wins.
constexpr int kAnyDelta = 1 << 20;
// Largest noise added to a minimum-perimeter weight (weights lie in [0, 1]) for a fresh tree: reorders
// edges of similar length, keeps the long ones early.
constexpr double kRestartWeightNoise = 0.3;
// The first rounds are this fraction of `round_steps`, doubling up to it: small meshes finish at once.
constexpr int kFirstRoundDivisor = 8;
constexpr int kMinRoundSteps = 16;

int uniform(std::mt19937_64& rng, std::size_t n) {
  return static_cast<int>(std::uniform_int_distribution<std::size_t>(0, n - 1)(rng));
}

}  // namespace

namespace {

// One independent walk of the repair search. `run` advances it by a fixed number of steps, so that a
// portfolio of walks advanced in rounds reaches the same states whatever the thread timing.
class Walker {
 public:
  Walker(const UnfoldContext& ctx, const std::vector<char>& initial_fold, const SearchOptions& opt,
         std::uint64_t seed)
      : ctx_(ctx), m_(*ctx.mesh), opt_(opt), cons_(opt.constraints), rng_(seed), tree_(ctx, initial_fold) {
    join_all_pieces(tree_, cons_);
    best_ = run_best_ = tree_.overlap_count();
    best_fold_ = run_fold_ = tree_.fold_flags();
    tabu_until_.assign(m_.num_edges(), 0);
  }

  bool solved() const { return tree_.overlap_count() == 0; }
  int best() const { return best_; }
  int steps() const { return steps_; }
  int moves() const { return moves_; }
  int restarts() const { return restarts_; }
  const CutTree& tree() const { return tree_; }
  const std::vector<char>& best_fold() const { return best_fold_; }

  /// Steps, best overlap count and piece count as of the last checkpoint: safe to read from another
  /// thread while the walk runs (for progress reports).
  int shown_steps() const { return shown_steps_.load(std::memory_order_relaxed); }
  int shown_best() const { return shown_best_.load(std::memory_order_relaxed); }
  int shown_pieces() const { return shown_pieces_.load(std::memory_order_relaxed); }

  /// Runs up to `budget` steps; stops early when solved or when `should_stop()` says so (asked before
  /// the first step and every kCheckpointSteps steps). Returns false when stopped by `should_stop`.
  template <class ShouldStop>
  bool run(int budget, const ShouldStop& should_stop) {
    for (int i = 0; i < budget && !solved(); ++i) {
      if (i % kCheckpointSteps == 0) {
        publish();
        if (should_stop()) return false;
      }
      step();
    }
    publish();
    return true;
  }

 private:
  bool tabu(int e) const { return tabu_until_[e] > steps_; }

  void publish() {
    shown_steps_.store(steps_, std::memory_order_relaxed);
    shown_best_.store(best_, std::memory_order_relaxed);
    shown_pieces_.store(tree_.piece_count(), std::memory_order_relaxed);
  }

  void step() {
    ++steps_;
    const auto& hot = tree_.overlapping_faces();
    int f = hot[uniform(rng_, hot.size())];
    const auto& partners = tree_.overlap_partners(f);
    int g = partners[uniform(rng_, partners.size())];
    const std::vector<int> path = tree_.path(f, g);
    if (path.empty()) return;

    // During a kick any move is taken (the least bad of the candidates), to leave a local minimum.
    int best_delta = kick_ > 0 ? kAnyDelta : opt_.max_uphill + 1, best_cut = -1, best_attach = -1;
    if (kick_ > 0) --kick_;
    for (int k = 0; k < opt_.candidates_per_move; ++k) {
      int e = path[uniform(rng_, path.size())];
      if (tabu(e) || cons_.fold(e)) continue;
      tree_.smaller_side(e, side_);
      const int old = tree_.cross_overlaps(side_);
      const auto& ev = m_.edges[e].v;
      attach_.clear();
      for (int x : side_) {
        for (int a : m_.face_edges[x]) {
          const auto& edge = m_.edges[a];
          if (a == e || tree_.folded(a) || edge.boundary() || cons_.cut(a) || tabu(a)) continue;
          if (tree_.in_side(tree_.across(a, x))) continue;
          // Curvature rule as a pre-filter: after cutting e and folding a, both ends of a must keep
          // the cut edges their class needs, or the move creates a local overlap for certain.
          bool ok = true;
          for (int v : edge.v) {
            int after = tree_.cut_count(v) - 1 + ((v == ev[0] || v == ev[1]) ? 1 : 0);
            if (after < ctx_.required_cuts[v]) ok = false;
          }
          if (ok) attach_.push_back(a);
        }
      }
      if (attach_.empty()) continue;
      // Edges sharing a vertex with e turn the side about that vertex: a small motion, so few new
      // overlaps. These are tried first; a random edge anywhere on the side gives the long jumps.
      near_.clear();
      for (int a : attach_) {
        const auto& av = m_.edges[a].v;
        if (av[0] == ev[0] || av[0] == ev[1] || av[1] == ev[0] || av[1] == ev[1]) near_.push_back(a);
      }
      const int tries = std::min<int>(opt_.attach_tries, static_cast<int>(attach_.size()));
      for (int t = 0; t < tries; ++t) {
        int a = (t == 0 && opt_.near_first && !near_.empty()) ? near_[uniform(rng_, near_.size())]
                                                              : attach_[uniform(rng_, attach_.size())];
        const int limit = old + best_delta - 1;
        if (limit < 0) break;
        int cost = tree_.reattach_cost(side_, a, limit);
        if (cost <= limit) {
          best_delta = cost - old;
          best_cut = e;
          best_attach = a;
        }
      }
    }
    if (best_cut >= 0) {
      tree_.smaller_side(best_cut, side_);
      tree_.reattach(side_, best_cut, best_attach);
      tabu_until_[best_cut] = tabu_until_[best_attach] = steps_ + opt_.tabu_tenure;
      ++moves_;
    }
    if (tree_.overlap_count() < run_best_) {
      run_best_ = tree_.overlap_count();
      run_fold_ = tree_.fold_flags();
      stall_ = 0;
      if (opt_.episode_best) kicks_since_restart_ = 0;
      if (run_best_ < best_) {
        best_ = run_best_;
        best_fold_ = run_fold_;
      }
    } else if (++stall_ >= opt_.restart_after && opt_.kicks_per_restart > 0 &&
               kicks_since_restart_ < opt_.kicks_per_restart) {
      // Back to the best tree of this episode, then a few forced moves: stays near it (which a
      // fresh tree would throw away) while changing enough to escape its local minimum.
      tree_ = CutTree(ctx_, run_fold_);
      std::fill(tabu_until_.begin(), tabu_until_.end(), 0);
      kick_ = opt_.kick_moves;
      stall_ = 0;
      ++kicks_since_restart_;
      ++restarts_;
    } else if (stall_ >= opt_.restart_after) {
      kicks_since_restart_ = 0;
      // A fresh tree from perturbed minimum-perimeter weights: close to the good trees, but
      // different enough to leave a region the walk keeps returning to. It starts a new episode:
      // its descent is not cut short by kicks back to the old best tree.
      std::vector<double> w = ctx_.weight;
      std::uniform_real_distribution<double> noise(0.0, kRestartWeightNoise);
      for (double& x : w)
        x += noise(rng_);
      tree_ = CutTree(ctx_, folds_from_cuts(spanning_forest_cuts(m_, w, cons_)));
      std::fill(tabu_until_.begin(), tabu_until_.end(), 0);
      stall_ = 0;
      ++restarts_;
      if (opt_.episode_best) {
        run_best_ = tree_.overlap_count();
        run_fold_ = tree_.fold_flags();
      }
      if (tree_.overlap_count() < best_) {
        best_ = run_best_ = tree_.overlap_count();
        best_fold_ = run_fold_ = tree_.fold_flags();
      }
    }
  }

  const UnfoldContext& ctx_;
  const Mesh& m_;
  const SearchOptions& opt_;
  const EdgeConstraints& cons_;
  std::mt19937_64 rng_;
  CutTree tree_;
  // Fewest overlapping pairs overall and in this episode (since the last fresh tree), with their trees.
  int best_ = 0, run_best_ = 0;
  std::vector<char> best_fold_, run_fold_;
  std::vector<int> tabu_until_;
  std::vector<int> side_, attach_, near_;
  int steps_ = 0, moves_ = 0, restarts_ = 0;
  int stall_ = 0, kick_ = 0, kicks_since_restart_ = 0;
  std::atomic<int> shown_steps_{0}, shown_best_{0}, shown_pieces_{0};
};

}  // namespace

SearchResult search_unfold(const UnfoldContext& ctx, std::vector<char> initial_fold, const SearchOptions& opt,
                           const ProgressFn& progress) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
  const Mesh& m = *ctx.mesh;
  const int walkers_n = std::max(1, opt.portfolio);
  const int hw = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const int threads = std::min(walkers_n, opt.threads > 0 ? opt.threads : hw);

  // Walker k uses seed + k. Built in parallel: the initial overlap test is a full pass over the mesh.
  std::vector<std::unique_ptr<Walker>> walkers(walkers_n);
  std::atomic<bool> stop{
      false};  // set when `progress` answers false: every walk stops at its next checkpoint
  std::atomic<bool> timed_out{false};
  // `progress`, asked on the calling thread only, at most every kReportInterval_s: at the checkpoints of
  // the walks it runs (inside a round) and between rounds. The first report comes before any step.
  const std::thread::id caller = std::this_thread::get_id();
  double next_report_s = 0;
  auto report = [&] {
    if (!progress || stop.load(std::memory_order_relaxed)) return;
    const double t = elapsed();
    if (t < next_report_s) return;
    next_report_s = t + kReportInterval_s;
    int best = walkers[0]->shown_best(), steps = 0;
    for (const auto& w : walkers) {
      if (!w) continue;
      best = std::min(best, w->shown_best());
      steps += w->shown_steps();
    }
    if (!progress({opt.stage, steps, walkers[0]->shown_pieces(), static_cast<double>(best), t}))
      stop.store(true, std::memory_order_relaxed);
  };
  auto out_of_time = [&] {
    if (std::this_thread::get_id() == caller) report();
    if (stop.load(std::memory_order_relaxed)) return true;
    if (elapsed() >= opt.time_limit_s) {
      timed_out.store(true, std::memory_order_relaxed);
      return true;
    }
    return false;
  };
  // Runs job(k) for every walker k on `threads` threads (the calling one included).
  auto for_each_walker = [&](const auto& job) { run_parallel(walkers_n, threads, job); };
  // Walk 0 first runs alone for one full round, on the calling thread: most meshes of up to ~1,000
  // faces are solved within it, before any other walk is built or any thread started.
  walkers[0] = std::make_unique<Walker>(ctx, initial_fold, opt, opt.seed);
  walkers[0]->run(opt.round_steps, out_of_time);
  if (!walkers[0]->solved())
    for_each_walker([&](int k) {
      if (k > 0) walkers[k] = std::make_unique<Walker>(ctx, initial_fold, opt, opt.seed + k);
    });

  // Rounds of a fixed number of steps per walker; after each round the lowest-numbered solved walker
  // wins, so the result depends on the seed only (unless the time limit or a cancel stops it).
  int winner = -1;
  int round_steps = std::max(kMinRoundSteps, opt.round_steps / kFirstRoundDivisor);
  for (int round = 0;; ++round) {
    for (int k = 0; k < walkers_n && winner < 0; ++k)
      if (walkers[k]->solved()) winner = k;
    if (winner >= 0 || timed_out.load() || stop.load()) break;
    if (elapsed() >= opt.time_limit_s) break;
    report();
    if (stop.load()) break;
    const int budget = round_steps;
    round_steps = std::min(opt.round_steps, round_steps * 2);
    for_each_walker([&](int k) { walkers[k]->run(budget, out_of_time); });
  }

  SearchResult res;
  for (const auto& w : walkers) {
    if (!w) continue;
    res.steps += w->steps();
    res.moves += w->moves();
    res.restarts += w->restarts();
  }
  if (winner >= 0) {
    const CutTree& tree = walkers[winner]->tree();
    res.cut = tree.cut_flags();
    res.solved = true;
    res.best_fold = tree.fold_flags();
    return res;
  }
  // Out of time: the best tree (fewest overlapping pairs, lowest walker on ties), cut apart where it
  // still overlaps, so the result is always valid.
  int pick = 0;
  for (int k = 1; k < walkers_n; ++k)
    if (walkers[k]->best() < walkers[pick]->best()) pick = k;
  res.overlaps_left = walkers[pick]->best();
  res.best_fold = walkers[pick]->best_fold();
  res.cut = folds_from_cuts(res.best_fold);
  cut_until_no_overlap(m, res.cut, ctx.weight, opt.constraints);
  return res;
}

}  // namespace foldkit::unfold
