// The repair search. Each step picks an overlapping pair, tries a few (cut edge on their tree path,
// re-attach edge of the cut-off side) moves, and applies the one that lowers the overlap count most
// (or keeps it, to walk plateaus). Only the moved side is re-tested (CutTree::reattach_cost), which is
// what keeps steps cheap at thousands of faces. A short tabu list stops the walk from undoing itself;
// a restart from a tree of perturbed cut weights leaves regions where it stalls.
#include "foldkit/unfold/search.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <memory>
#include <numeric>
#include <random>
#include <thread>

#include "foldkit/geom/parallel.hpp"
#include "foldkit/unfold/mst.hpp"

namespace foldkit::unfold {

void join_all_pieces(CutTree& tree, const EdgeConstraints& constraints) {
  const Mesh& m = tree.mesh();
  const auto& w = tree.context().weight;
  std::vector<EdgeId> order;
  for (EdgeId e : all_ids<EdgeId>(m.num_edges())) {
    const auto& edge = m.edge(e);
    if (edge.boundary() || tree.folded(e) || constraints.cut(e)) continue;
    if (tree.piece(edge.face_id(0)) != tree.piece(edge.face_id(1))) order.push_back(e);
  }
  std::stable_sort(order.begin(), order.end(),
                   [&](EdgeId a, EdgeId b) { return w[a.index()] < w[b.index()]; });
  for (EdgeId e : order) {
    const auto& edge = m.edge(e);
    if (tree.piece(edge.face_id(0)) != tree.piece(edge.face_id(1))) tree.stitch(e);
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
// Largest noise added to a cut weight (weights lie in [0, 1]) for a fresh tree: reorders
// edges of similar weight, keeps the order of the clearly lighter and heavier ones.
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
  Walker(const UnfoldContext& ctx, const EdgeStates& initial, const SearchOptions& opt, std::uint64_t seed)
      : ctx_(ctx), m_(*ctx.mesh), opt_(opt), cons_(opt.constraints), rng_(seed), tree_(ctx, initial) {
    join_all_pieces(tree_, cons_);
    best_ = run_best_ = tree_.overlap_count();
    best_tree_ = run_tree_ = tree_.states();
    tabu_until_.assign(m_.num_edges(), 0);
  }

  bool solved() const { return tree_.overlap_count() == 0; }
  int best() const { return best_; }
  int steps() const { return steps_; }
  int moves() const { return moves_; }
  int restarts() const { return restarts_; }
  const CutTree& tree() const { return tree_; }
  const EdgeStates& best_tree() const { return best_tree_; }

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
  bool tabu(EdgeId e) const { return tabu_until_[e] > steps_; }

  void publish() {
    shown_steps_.store(steps_, std::memory_order_relaxed);
    shown_best_.store(best_, std::memory_order_relaxed);
    shown_pieces_.store(tree_.piece_count(), std::memory_order_relaxed);
  }

  // A (cut edge, re-attach edge) move.
  struct Move {
    EdgeId cut, attach;
  };

  // One step: a random overlapping pair, a few candidate moves on the fold path between them, the best
  // applied; then the bookkeeping of bests, kicks and restarts.
  void step() {
    ++steps_;
    const std::vector<EdgeId> path = random_overlap_path();
    if (path.empty()) return;
    // During a kick any move is taken (the least bad of the candidates), to leave a local minimum.
    int best_delta = kick_ > 0 ? kAnyDelta : opt_.max_uphill + 1;
    if (kick_ > 0) --kick_;
    Move best;
    for (int k = 0; k < opt_.candidates_per_move; ++k)
      try_cut(drawn_cut(path), best_delta, best);
    if (best.cut.valid()) apply(best);
    if (tree_.overlap_count() < run_best_) {
      record_best();
    } else if (++stall_ >= opt_.restart_after && opt_.kicks_per_restart > 0 &&
               kicks_since_restart_ < opt_.kicks_per_restart) {
      kick_back();
    } else if (stall_ >= opt_.restart_after) {
      fresh_tree();
    }
  }

  // A candidate cut from `path`: the heaviest of cut_draws edges drawn at random (cut_weights: the
  // preferred cut), so that where the weights grade label room the walk cuts roomy edges more often.
  EdgeId drawn_cut(const std::vector<EdgeId>& path) {
    EdgeId e = path[uniform(rng_, path.size())];
    for (int d = 1; d < opt_.cut_draws; ++d) {
      const EdgeId o = path[uniform(rng_, path.size())];
      if (ctx_.weight[o.index()] > ctx_.weight[e.index()]) e = o;
    }
    return e;
  }

  // The fold path between a random overlapping face and a random partner of it.
  std::vector<EdgeId> random_overlap_path() {
    const auto& hot = tree_.overlapping_faces();
    int f = hot[uniform(rng_, hot.size())];
    const auto& partners = tree_.overlap_partners(f);
    int g = partners[uniform(rng_, partners.size())];
    return tree_.path(FaceId(f), FaceId(g));
  }

  // Moves cutting e: tries up to attach_tries re-attach edges of its smaller side; keeps in `best` the
  // first that changes the overlap count by less than `best_delta` (which it lowers) or, with
  // prefer_weighted_ties, by as much as `best` but trading a lighter cut for a heavier one.
  void try_cut(EdgeId e, int& best_delta, Move& best) {
    if (tabu(e) || cons_.fold(e)) return;
    tree_.smaller_side(e, side_);
    const int old = tree_.cross_overlaps(side_);
    collect_attach_edges(e);
    if (attach_.empty()) return;
    const int tries = std::min<int>(opt_.attach_tries, static_cast<int>(attach_.size()));
    for (int t = 0; t < tries; ++t) {
      const EdgeId a = (t == 0 && opt_.near_first && !near_.empty()) ? near_[uniform(rng_, near_.size())]
                                                                     : attach_[uniform(rng_, attach_.size())];
      const bool ties =
          opt_.prefer_weighted_ties && best.cut.valid() && gain(e, a) > gain(best.cut, best.attach);
      const int limit = old + best_delta - (ties ? 0 : 1);
      if (limit < 0) break;
      int cost = tree_.reattach_cost(side_, a, limit);
      if (cost <= limit) {
        best_delta = cost - old;
        best = {e, a};
      }
    }
  }

  // What a move gains in the weights' eyes: cutting e (heavy: a preferred cut) and folding a (light).
  double gain(EdgeId e, EdgeId a) const { return ctx_.weight[e.index()] - ctx_.weight[a.index()]; }

  // attach_: the cut edges from side_ (the smaller side of e) to the rest of its piece that may fold;
  // near_: those of them sharing a vertex with e.
  void collect_attach_edges(EdgeId e) {
    const auto& ev = m_.edge(e).v;
    attach_.clear();
    for (int x : side_) {
      for (EdgeId a : m_.edges_of(FaceId(x))) {
        const auto& edge = m_.edge(a);
        if (a == e || tree_.folded(a) || edge.boundary() || cons_.cut(a) || tabu(a)) continue;
        if (tree_.in_side(tree_.across(a, FaceId(x)))) continue;
        // Curvature rule as a pre-filter: a move that leaves an end of a short of the cut edges its
        // class needs creates a local overlap for certain.
        if (tree_.curvature_allows_move(e, a)) attach_.push_back(a);
      }
    }
    // Edges sharing a vertex with e turn the side about that vertex: a small motion, so few new
    // overlaps. These are tried first; a random edge anywhere on the side gives the long jumps.
    near_.clear();
    for (EdgeId a : attach_) {
      const auto& av = m_.edge(a).v;
      if (av[0] == ev[0] || av[0] == ev[1] || av[1] == ev[0] || av[1] == ev[1]) near_.push_back(a);
    }
  }

  void apply(const Move& move) {
    tree_.smaller_side(move.cut, side_);
    tree_.reattach(side_, move.cut, move.attach);
    tabu_until_[move.cut] = tabu_until_[move.attach] = steps_ + opt_.tabu_tenure;
    ++moves_;
  }

  void record_best() {
    run_best_ = tree_.overlap_count();
    run_tree_ = tree_.states();
    stall_ = 0;
    if (opt_.episode_best) kicks_since_restart_ = 0;
    if (run_best_ < best_) {
      best_ = run_best_;
      best_tree_ = run_tree_;
    }
  }

  // Back to the best tree of this episode, then a few forced moves: stays near it (which a fresh tree
  // would throw away) while changing enough to escape its local minimum.
  void kick_back() {
    tree_ = CutTree(ctx_, run_tree_);
    std::fill(tabu_until_.begin(), tabu_until_.end(), 0);
    kick_ = opt_.kick_moves;
    stall_ = 0;
    ++kicks_since_restart_;
    ++restarts_;
  }

  // A fresh tree from perturbed cut weights: close to the good trees, but different
  // enough to leave a region the walk keeps returning to. It starts a new episode: its descent is not
  // cut short by kicks back to the old best tree.
  void fresh_tree() {
    kicks_since_restart_ = 0;
    std::vector<double> w = ctx_.weight;
    std::uniform_real_distribution<double> noise(0.0, kRestartWeightNoise);
    for (double& x : w)
      x += noise(rng_);
    tree_ = CutTree(ctx_, spanning_forest(m_, w, cons_));
    std::fill(tabu_until_.begin(), tabu_until_.end(), 0);
    stall_ = 0;
    ++restarts_;
    if (opt_.episode_best) {
      run_best_ = tree_.overlap_count();
      run_tree_ = tree_.states();
    }
    if (tree_.overlap_count() < best_) {
      best_ = run_best_ = tree_.overlap_count();
      best_tree_ = run_tree_ = tree_.states();
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
  EdgeStates best_tree_, run_tree_;
  EdgeMap<int> tabu_until_;
  std::vector<int> side_;
  std::vector<EdgeId> attach_, near_;
  int steps_ = 0, moves_ = 0, restarts_ = 0;
  int stall_ = 0, kick_ = 0, kicks_since_restart_ = 0;
  std::atomic<int> shown_steps_{0}, shown_best_{0}, shown_pieces_{0};
};

// The walks of one search, advanced in rounds, with the clock, the stop flag and the progress reports
// they share.
class Portfolio {
 public:
  Portfolio(const UnfoldContext& ctx, const SearchOptions& opt, const ProgressFn& progress)
      : ctx_(ctx),
        opt_(opt),
        progress_(progress),
        start_(Clock::now()),
        caller_(std::this_thread::get_id()),
        walkers_(std::max(1, opt.portfolio)) {
    threads_ = std::min(size(), resolve_threads(opt.threads));
  }

  int size() const { return static_cast<int>(walkers_.size()); }

  /// Walk 0 first runs alone for one full round, on the calling thread: most meshes of up to ~1,000
  /// faces are solved within it, before any other walk is built or any thread started. Walker k uses
  /// seed + k; the others are built in parallel (the initial overlap test is a full pass over the mesh).
  void start(const EdgeStates& initial) {
    walkers_[0] = std::make_unique<Walker>(ctx_, initial, opt_, opt_.seed);
    walkers_[0]->run(steps_left(0, opt_.round_steps), [this] { return should_stop(); });
    if (walkers_[0]->solved()) return;
    run_parallel(size(), threads_, [&](int k) {
      if (k > 0) walkers_[k] = std::make_unique<Walker>(ctx_, initial, opt_, opt_.seed + k);
    });
  }

  /// Rounds of a fixed number of steps per walker; after each round the lowest-numbered solved walker
  /// wins, so the result depends on the seed only (unless the time limit or a cancel stops it). Returns
  /// the winner, or -1 when stopped first.
  int run_rounds() {
    int round_steps = std::max(kMinRoundSteps, opt_.round_steps / kFirstRoundDivisor);
    while (true) {
      for (int k = 0; k < size(); ++k)
        if (walkers_[k]->solved()) return k;
      if (timed_out_.load() || stop_.load()) return -1;
      if (elapsed() >= opt_.time_limit_s) return -1;
      if (out_of_steps()) return -1;
      report();
      if (stop_.load()) return -1;
      const int budget = round_steps;
      round_steps = std::min(opt_.round_steps, round_steps * 2);
      run_parallel(size(), threads_,
                   [&](int k) { walkers_[k]->run(steps_left(k, budget), [this] { return should_stop(); }); });
    }
  }

  /// The winner's tree, or (winner -1) the best tree (fewest overlapping pairs, lowest walker on ties)
  /// cut apart where it still overlaps, so the result is always valid.
  SearchResult result(int winner) const {
    SearchResult res;
    for (const auto& w : walkers_) {
      if (!w) continue;
      res.steps += w->steps();
      res.moves += w->moves();
      res.restarts += w->restarts();
    }
    if (winner >= 0) {
      const CutTree& tree = walkers_[winner]->tree();
      res.edges = tree.states();
      res.solved = true;
      res.best_tree = tree.states();
      return res;
    }
    int pick = 0;
    for (int k = 1; k < size(); ++k)
      if (walkers_[k]->best() < walkers_[pick]->best()) pick = k;
    res.overlaps_left = walkers_[pick]->best();
    res.best_tree = walkers_[pick]->best_tree();
    res.edges = res.best_tree;
    cut_until_no_overlap(*ctx_.mesh, res.edges, ctx_.weight, opt_.constraints);
    return res;
  }

 private:
  using Clock = std::chrono::steady_clock;

  double elapsed() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

  // SearchOptions::max_steps: counted per walk and checked between rounds only, so where it stops the
  // search does not depend on the clock or the thread count.
  int steps_left(int k, int budget) const {
    if (opt_.max_steps <= 0) return budget;
    return static_cast<int>(std::clamp<long>(opt_.max_steps - walkers_[k]->steps(), 0, budget));
  }
  bool out_of_steps() const {
    if (opt_.max_steps <= 0) return false;
    for (int k = 0; k < size(); ++k)
      if (walkers_[k] && walkers_[k]->steps() < opt_.max_steps) return false;
    return true;
  }

  // Asked by every walk at its checkpoints: true once cancelled or out of time. On the calling thread it
  // reports progress first, so reports come from inside rounds too.
  bool should_stop() {
    if (std::this_thread::get_id() == caller_) report();
    if (stop_.load(std::memory_order_relaxed)) return true;
    if (elapsed() >= opt_.time_limit_s) {
      timed_out_.store(true, std::memory_order_relaxed);
      return true;
    }
    return false;
  }

  // `progress`, asked on the calling thread only, at most every kReportInterval_s. The first report
  // comes before any step. Its answer false sets stop_: every walk stops at its next checkpoint.
  void report() {
    if (!progress_ || stop_.load(std::memory_order_relaxed)) return;
    const double t = elapsed();
    if (t < next_report_s_) return;
    next_report_s_ = t + kReportInterval_s;
    int best = walkers_[0]->shown_best(), steps = 0;
    for (const auto& w : walkers_) {
      if (!w) continue;
      best = std::min(best, w->shown_best());
      steps += w->shown_steps();
    }
    if (!progress_({opt_.stage, steps, walkers_[0]->shown_pieces(), static_cast<double>(best), t}))
      stop_.store(true, std::memory_order_relaxed);
  }

  const UnfoldContext& ctx_;
  const SearchOptions& opt_;
  const ProgressFn& progress_;
  const Clock::time_point start_;
  const std::thread::id caller_;
  std::vector<std::unique_ptr<Walker>> walkers_;
  int threads_ = 1;
  std::atomic<bool> stop_{false}, timed_out_{false};
  double next_report_s_ = 0;
};

}  // namespace

SearchResult search_unfold(const UnfoldContext& ctx, const EdgeStates& initial, const SearchOptions& opt,
                           const ProgressFn& progress) {
  Portfolio portfolio(ctx, opt, progress);
  portfolio.start(initial);
  return portfolio.result(portfolio.run_rounds());
}

}  // namespace foldkit::unfold
