#pragma once
// `--method ga`: the seed's genetic topological surgery (§4-§6). Small initial patches (65/70/75% of
// the dual edges cut), a chromosome per order of the stitchable edges, evaluation by stitching in
// that order (successes move to the head, failures to the tail), the §5.4 crossover and mutation,
// then the §6 rearrangement; finally the repair search where pieces remain.
#include <cstdint>
#include <string>
#include <vector>

#include "foldkit/unfold/cut_tree.hpp"
#include "foldkit/unfold/dual_graph.hpp"
#include "foldkit/unfold/fitness.hpp"
#include "foldkit/unfold/progress.hpp"

namespace foldkit::unfold {

struct GaOptions {
  std::uint64_t seed = 1;
  double time_limit_s = 60;
  int threads = 0;  ///< 0: hardware concurrency; the result does not depend on it
  int population = 64;
  double crossover_rate = 0.9;
  double mutation_rate = 0.1;
  /// Stop when the best fitness has not improved for this many generations.
  int stagnation_generations = 30;
  /// Shares of the dual edges cut in the initial patches; one independent run each, best wins.
  std::vector<double> shares{0.65, 0.70, 0.75};
  FitnessWeights weights;
  EdgeConstraints constraints;
  /// Finish with the repair search (search.hpp) when the GA and the rearrangement leave pieces.
  bool repair_with_search = true;
};

struct GaResult {
  EdgeStates edges;  ///< the edges of an overlap-free unfolding
  int pieces = 0;
  double score = 0;     ///< fitness of the returned unfolding
  double share = 0;     ///< share of the run that won
  int generations = 0;  ///< of the winning run
  std::string method;   ///< e.g. "ga(70%)", "ga(65%)+rearrange", "ga(75%)+search"
};

/// Runs the three shares (in parallel where threads allow; same seed, same result whatever the thread
/// count unless the time limit cuts a run short) and returns the best by fitness.
GaResult genetic_unfold(const UnfoldContext& context, const GaOptions& options,
                        const ProgressFn& progress = {});

/// The §5.4 crossover of two evaluated chromosomes (each: successes first, `successes_*` of them):
/// shared successes and shared failures stay in place, a random range of the middle of `p` takes the
/// order of `q`'s by swaps, and the result is mapped back to `p`'s original positions.
std::vector<int> crossover(const std::vector<int>& p, int successes_p, const std::vector<int>& q,
                           int successes_q, std::uint64_t random_bits);

}  // namespace foldkit::unfold
