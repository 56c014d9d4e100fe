#pragma once
// `--method search`: a tabu-style repair search on the cut tree (unfolding-notes.md, after Zawallich,
// "Unfolding polyhedra via tabu search", 2024). Start from a spanning tree; while pieces overlap, cut
// a tree edge on the path between two overlapping faces and re-attach the cut-off subtree through
// another of its edges, keeping moves that do not raise the number of overlapping pairs.
#include <cstdint>
#include <string>
#include <vector>

#include "foldkit/unfold/cut_tree.hpp"
#include "foldkit/unfold/dual_graph.hpp"
#include "foldkit/unfold/progress.hpp"

namespace foldkit::unfold {

struct SearchOptions {
  std::uint64_t seed = 1;
  double time_limit_s = 60;
  /// Steps per walk after which the search stops as if out of time (0: no such limit). Unlike the time
  /// limit, where it stops is the same on a busy machine and an idle one.
  long max_steps = 0;
  /// Candidate (cut, re-attach) moves evaluated per step; the best that does not add overlaps is kept.
  int candidates_per_move = 6;
  /// Moves without a new best overlap count before restarting from a freshly perturbed tree.
  int restart_after = 1000;
  /// Stalls answered by going back to the best tree plus `kick_moves` forced moves, before a fresh tree.
  int kicks_per_restart = 20;
  int kick_moves = 3;
  /// Kicks go back to the best tree since the last fresh tree (not the best overall), and a kick that
  /// leads to a new best of the episode resets the kick count: a fresh tree gets its own descent.
  bool episode_best = true;
  /// Moves an edge stays tabu after being cut or folded.
  int tabu_tenure = 12;
  /// Re-attach edges tried per cut edge (the first next to the cut edge, the others anywhere).
  int attach_tries = 2;
  /// Whether the first re-attach edge tried shares a vertex with the cut edge.
  bool near_first = true;
  /// How many overlapping pairs the best move of a step may add (0: never go uphill).
  int max_uphill = 1;
  /// Of two candidate moves that change the overlap count alike, take the one whose cut is heavier and
  /// whose re-attached edge lighter (UnfoldContext::weight): the walk drifts towards the preferred cuts.
  bool prefer_weighted_ties = false;
  /// Path edges drawn per candidate cut, the heaviest (UnfoldContext::weight) tried: 1 draws uniformly;
  /// more lean the walk towards the preferred cuts while it removes overlaps.
  int cut_draws = 1;
  /// Independent walks (walk k uses seed + k), advanced in rounds of `round_steps` steps each; after a
  /// round the lowest-numbered walk that reached one piece wins. Their number, not `threads`, decides
  /// the result, so the same seed gives the same cuts whatever the thread count.
  int portfolio = 2;
  /// Steps per walk per round (the first rounds are shorter, so that small meshes finish at once).
  int round_steps = 2048;
  /// Threads the walks are spread over (0: hardware concurrency; never more than `portfolio`).
  int threads = 0;
  EdgeConstraints constraints;
  /// Stage name reported to the progress callback.
  std::string stage = "search";
};

struct SearchResult {
  /// The edges of an overlap-free unfolding: the search's tree when it reached zero overlaps, else its
  /// best tree cut apart where it still overlapped (more pieces).
  EdgeStates edges;
  bool solved = false;    ///< one piece per connected component, without overlaps
  int overlaps_left = 0;  ///< overlapping pairs of the best tree when not solved
  int moves = 0;          ///< accepted moves, summed over the walks
  int steps = 0;          ///< steps (each evaluates up to candidates_per_move moves), summed over the walks
  int restarts = 0;
  /// The best spanning tree seen (fewest overlapping pairs).
  EdgeStates best_tree;
};

/// Runs the search from the fold forest `initial` (pieces of one component are first stitched
/// into one tree along their lightest edges), as a portfolio of walks on up to `threads` threads.
/// Deterministic for a given seed, whatever the thread count (max_steps included), unless stopped by the
/// time limit or by `progress` returning false. `progress` is called from the calling thread only, at most
/// every 0.2 s (the first time before any step), inside rounds as well as between them; once it returns false
/// every walk stops within a few steps and is not asked again.
SearchResult search_unfold(const UnfoldContext& context, const EdgeStates& initial,
                           const SearchOptions& options, const ProgressFn& progress = {});

/// Stitches every pair of pieces of `tree` joined by a cut edge, lightest edges first, whatever the
/// overlaps, until each connected component is one piece. Forced cuts are honoured.
void join_all_pieces(CutTree& tree, const EdgeConstraints& constraints);

}  // namespace foldkit::unfold
