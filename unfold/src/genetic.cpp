// GA over stitch orders. Every evaluation replays its chromosome on a copy of the run's initial
// patches; a stitch is tried only when the curvature rule allows it and kept only when the moved
// piece overlaps nothing (CutTree::stitch_cost with limit 0 stops at the first overlap).
#include "foldkit/unfold/genetic.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>
#include <random>
#include <thread>

#include "foldkit/geom/parallel.hpp"
#include "foldkit/unfold/decompose.hpp"
#include "foldkit/unfold/disjoint_sets.hpp"
#include "foldkit/unfold/rearrange.hpp"
#include "foldkit/unfold/search.hpp"

namespace foldkit::unfold {

std::vector<int> crossover(const std::vector<int>& p, int sp, const std::vector<int>& q, int sq,
                           std::uint64_t random_bits) {
  const int n = static_cast<int>(p.size());
  if (n == 0) return p;
  int max_id = *std::max_element(p.begin(), p.end());
  // 1: success in p, 2: failure in p; likewise 4 and 8 for q.
  std::vector<unsigned char> tag(max_id + 1, 0);
  for (int i = 0; i < n; ++i)
    tag[p[i]] |= i < sp ? 1 : 2;
  for (int i = 0; i < static_cast<int>(q.size()); ++i)
    if (q[i] <= max_id) tag[q[i]] |= i < sq ? 4 : 8;
  auto shared_success = [&](int x) { return tag[x] == (1 | 4); };
  auto shared_failure = [&](int x) { return tag[x] == (2 | 8); };
  auto reorder = [&](const std::vector<int>& c) {
    std::vector<int> out;
    out.reserve(c.size());
    for (int x : c)
      if (shared_success(x)) out.push_back(x);
    const int head = static_cast<int>(out.size());
    for (int x : c)
      if (!shared_success(x) && !shared_failure(x)) out.push_back(x);
    const int tail = static_cast<int>(out.size());
    for (int x : c)
      if (shared_failure(x)) out.push_back(x);
    return std::tuple{out, head, tail};
  };
  auto [p2, head, tail] = reorder(p);
  auto [q2, qhead, qtail] = reorder(q);
  const int mid = tail - head;
  if (mid < 2 || qtail - qhead != mid) return p;
  std::mt19937_64 rng(random_bits);
  int a = std::uniform_int_distribution<int>(0, mid - 1)(rng);
  int b = std::uniform_int_distribution<int>(0, mid - 1)(rng);
  if (a > b) std::swap(a, b);
  std::vector<int> where(max_id + 1, -1);
  for (int i = 0; i < n; ++i)
    where[p2[i]] = i;
  std::vector<int> p3 = p2;
  for (int i = head + a; i <= head + b; ++i) {
    // Put q's edge at this position by swapping it with wherever it sits in p's middle.
    int want = q2[qhead + (i - head)];
    int j = where[want];
    std::swap(p3[i], p3[j]);
    where[p3[i]] = i;
    where[p3[j]] = j;
  }
  // Back to p's original positions: the edge p2[k] occupied position pos_in_p[p2[k]] in p.
  std::vector<int> pos_in_p(max_id + 1, -1);
  for (int i = 0; i < n; ++i)
    pos_in_p[p[i]] = i;
  std::vector<int> p4(n);
  for (int k = 0; k < n; ++k)
    p4[pos_in_p[p2[k]]] = p3[k];
  return p4;
}

namespace {

using Clock = std::chrono::steady_clock;

// Least time between two progress reports.
constexpr double kReportInterval_s = 0.2;
// Score of an individual not yet evaluated: worse than any fitness.
constexpr double kUnscored = 1e300;
// The rearrangement may stitch and cut this many times per face before it gives up.
constexpr int kRearrangeOperationsPerFace = 4;
// Run r's generator is seeded from seed * kSeedMix + r + 1 (the golden ratio in 64 bits: runs of
// neighbouring seeds do not share streams).
constexpr std::uint64_t kSeedMix = 0x9E3779B97F4A7C15ull;

struct Individual {
  std::vector<int> genes;  // stitchable edge ids, successes first after evaluation
  int successes = 0;
  double score = kUnscored;
  int pieces = 0;
};

struct RunResult {
  EdgeStates tree;
  double score = kUnscored;
  int pieces = 0;
  int generations = 0;
  double share = 0;
};

class GaRun {
 public:
  GaRun(const UnfoldContext& ctx, const GaOptions& opt, double share, std::uint64_t seed, int components,
        Clock::time_point deadline, std::atomic<bool>& cancel)
      : opt_(opt),
        share_(share),
        rng_(seed),
        components_(components),
        deadline_(deadline),
        cancel_(cancel),
        base_(ctx, initial_patches(ctx, share, opt.constraints)) {
    cut_overlaps(base_, opt.constraints);
    const Mesh& m = *ctx.mesh;
    for (EdgeId e : all_ids<EdgeId>(m.num_edges())) {
      const auto& me = m.edge(e);
      if (me.boundary() || base_.folded(e) || opt.constraints.cut(e)) continue;
      if (base_.piece(me.face_id(0)) != base_.piece(me.face_id(1)) && base_.curvature_allows_fold(e))
        stitchable_.push_back(e);
    }
  }

  /// Evaluates the initial population.
  void start() {
    const int n = static_cast<int>(stitchable_.size());
    population_.resize(std::max(4, opt_.population));
    for (auto& ind : population_) {
      ind.genes.resize(n);
      std::iota(ind.genes.begin(), ind.genes.end(), 0);
      std::shuffle(ind.genes.begin(), ind.genes.end(), rng_);
    }
    best_.share = share_;
    for (auto& ind : population_) {
      consider(ind);
      if (out_of_time()) return;
    }
  }

  /// One generation: the worse half replaced by children of the better half.
  void step() {
    const int n = static_cast<int>(stitchable_.size());
    const int pop = static_cast<int>(population_.size());
    ++best_.generations;
    std::stable_sort(population_.begin(), population_.end(),
                     [](const Individual& a, const Individual& b) { return a.score < b.score; });
    const int keep = pop / 2;
    bool improved = false;
    std::uniform_real_distribution<double> unit(0, 1);
    std::uniform_int_distribution<int> parent(0, keep - 1);
    for (int c = keep; c < pop; ++c) {
      const Individual& p = population_[parent(rng_)];
      const Individual& q = population_[parent(rng_)];
      Individual child;
      child.genes = unit(rng_) < opt_.crossover_rate
                        ? crossover(p.genes, p.successes, q.genes, q.successes, rng_())
                        : p.genes;
      if (unit(rng_) < opt_.mutation_rate && p.successes > 0 && p.successes < n) {
        // Swap one success with one failure (positions as evaluated in p).
        int i = std::uniform_int_distribution<int>(0, p.successes - 1)(rng_);
        int j = std::uniform_int_distribution<int>(p.successes, n - 1)(rng_);
        std::swap(child.genes[i], child.genes[j]);
      }
      population_[c] = std::move(child);
      improved |= consider(population_[c]);
      if (out_of_time()) return;
    }
    stagnant_ = improved ? 0 : stagnant_ + 1;
  }

  /// True when this run has nothing more to do (one piece per component, stagnation, time).
  bool done() const {
    return best_.pieces <= components_ || stagnant_ >= opt_.stagnation_generations || out_of_time();
  }
  const RunResult& best() const { return best_; }

 private:
  bool out_of_time() const { return cancel_.load(std::memory_order_relaxed) || Clock::now() >= deadline_; }

  bool consider(Individual& ind) {
    EdgeStates tree;
    evaluate(ind, &tree);
    if (ind.score >= best_.score) return false;
    best_.score = ind.score;
    best_.pieces = ind.pieces;
    best_.tree = std::move(tree);
    return true;
  }

  void evaluate(Individual& ind, EdgeStates* tree_out) {
    CutTree tree = base_;
    std::vector<int> ok, failed;
    ok.reserve(ind.genes.size());
    for (int id : ind.genes) {
      const EdgeId e = stitchable_[id];
      const auto& me = tree.mesh().edge(e);
      bool success = tree.piece(me.face_id(0)) != tree.piece(me.face_id(1)) &&
                     tree.curvature_allows_fold(e) && tree.stitch_cost(e, 0) == 0;
      if (success) tree.stitch(e);
      (success ? ok : failed).push_back(id);
    }
    ind.successes = static_cast<int>(ok.size());
    ok.insert(ok.end(), failed.begin(), failed.end());
    ind.genes = std::move(ok);
    const FitnessTerms terms = fitness_terms(tree);
    ind.pieces = terms.pieces;
    ind.score = fitness(terms, opt_.weights);
    if (tree_out) *tree_out = tree.states();
  }

  const GaOptions& opt_;
  double share_;
  std::mt19937_64 rng_;
  int components_;
  Clock::time_point deadline_;
  std::atomic<bool>& cancel_;
  CutTree base_;
  std::vector<EdgeId> stitchable_;
  std::vector<Individual> population_;
  RunResult best_;
  int stagnant_ = 0;
};

// The fewest pieces any unfolding can have: connected components once forced cuts are removed.
int fewest_pieces(const Mesh& m, const EdgeConstraints& constraints) {
  DisjointSets joined(m.num_faces());
  int n = m.num_faces();
  for (EdgeId e : all_ids<EdgeId>(m.num_edges())) {
    const auto& me = m.edge(e);
    if (me.boundary() || constraints.cut(e)) continue;
    if (joined.join(me.face[0], me.face[1])) --n;
  }
  return n;
}

std::string percent(double share) {
  return std::to_string(static_cast<int>(std::lround(share * 100))) + "%";
}

}  // namespace

namespace {

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Runs every share to its end and returns each run's best. Runs advance in lockstep, one generation per
// round, and stop together after the first round in which one reaches one piece per component. Each run
// has its own generator seeded from (seed, run index), so neither the thread count nor the timing of
// threads changes what a round produces.
std::vector<RunResult> evolve(const UnfoldContext& ctx, const GaOptions& opt, int components,
                              Clock::time_point start, const ProgressFn& progress) {
  const auto deadline = start + std::chrono::duration_cast<Clock::duration>(
                                    std::chrono::duration<double>(std::max(0.0, opt.time_limit_s)));
  const int runs = static_cast<int>(opt.shares.size());
  std::atomic<bool> cancel{false};
  const int threads = std::clamp(resolve_threads(opt.threads), 1, std::max(1, runs));
  std::vector<std::unique_ptr<GaRun>> run(runs);
  auto parallel = [&](const auto& job) { run_parallel(runs, threads, job); };
  parallel([&](int r) {
    run[r] = std::make_unique<GaRun>(ctx, opt, opt.shares[r],
                                     opt.seed * kSeedMix + static_cast<std::uint64_t>(r) + 1, components,
                                     deadline, cancel);
    run[r]->start();
  });
  int generation = 0;
  double next_report = 0;
  while (true) {
    bool solved = false, all_done = true;
    int best_pieces = std::numeric_limits<int>::max();
    for (auto& r : run) {
      solved |= r->best().pieces <= components;
      all_done &= r->done();
      best_pieces = std::min(best_pieces, r->best().pieces);
    }
    if (progress && seconds_since(start) >= next_report) {
      next_report = seconds_since(start) + kReportInterval_s;
      if (!progress({"ga", generation, best_pieces, 0, seconds_since(start)})) cancel = true;
    }
    if (solved || all_done || cancel) break;
    ++generation;
    parallel([&](int r) {
      if (!run[r]->done()) run[r]->step();
    });
  }
  std::vector<RunResult> results(runs);
  for (int r = 0; r < runs; ++r)
    results[r] = run[r]->best();
  return results;
}

// Where the GA left more pieces than components: the §6 rearrangement, else (when allowed) the repair
// search within `seconds_left`, whichever leaves fewer pieces. Appends what it did to `method`.
void join_remaining_pieces(const UnfoldContext& ctx, const GaOptions& opt, int components,
                           double seconds_left, const ProgressFn& progress, CutTree& tree,
                           std::string& method) {
  if (tree.piece_count() <= components) return;
  CutTree rearranged = tree;
  if (rearrange_pieces(rearranged, components, opt.constraints,
                       kRearrangeOperationsPerFace * ctx.mesh->num_faces())) {
    method += "+rearrange";
    tree = std::move(rearranged);
  } else if (opt.repair_with_search) {
    SearchOptions so;
    so.seed = opt.seed;
    so.time_limit_s = std::max(0.0, seconds_left);
    so.constraints = opt.constraints;
    so.stage = "ga+search";
    SearchResult sr = search_unfold(ctx, tree.states(), so, progress);
    CutTree searched(ctx, sr.edges);
    if (searched.piece_count() < rearranged.piece_count()) {
      method += "+search";
      tree = std::move(searched);
    } else {
      method += "+rearrange";
      tree = std::move(rearranged);
    }
  }
}

}  // namespace

GaResult genetic_unfold(const UnfoldContext& ctx, const GaOptions& opt, const ProgressFn& progress) {
  const auto start = Clock::now();
  const int components = fewest_pieces(*ctx.mesh, opt.constraints);
  const std::vector<RunResult> results = evolve(ctx, opt, components, start, progress);
  int win = 0;
  for (int r = 1; r < static_cast<int>(results.size()); ++r)
    if (results[r].score < results[win].score) win = r;
  const RunResult& best = results[win];
  GaResult out;
  out.share = best.share;
  out.generations = best.generations;
  out.method = "ga(" + percent(best.share) + ")";
  CutTree tree(ctx, best.tree);
  join_remaining_pieces(ctx, opt, components, opt.time_limit_s - seconds_since(start), progress, tree,
                        out.method);
  out.edges = tree.states();
  out.pieces = tree.piece_count();
  out.score = fitness(fitness_terms(tree), opt.weights);
  return out;
}

}  // namespace foldkit::unfold
