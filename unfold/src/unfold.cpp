#include "foldkit/unfold/unfold.hpp"

#include <algorithm>
#include <chrono>
#include <functional>
#include <string>

#include "foldkit/error.hpp"
#include "foldkit/unfold/cut_tree.hpp"
#include "foldkit/unfold/dual_graph.hpp"
#include "foldkit/unfold/flat_faces.hpp"
#include "foldkit/unfold/genetic.hpp"
#include "foldkit/unfold/mst.hpp"
#include "foldkit/unfold/seams.hpp"
#include "foldkit/unfold/search.hpp"

namespace foldkit::unfold {
namespace {

// The cuts `edges` with seams moved where a move allows (seam_moves.hpp): slits closed, and cuts off
// edges too tight for their labels at the asked print scale. Bounded by work, not by the clock, so that
// the result does not depend on how busy the machine is.
EdgeStates with_seams_moved(const UnfoldContext& ctx, const EdgeStates& edges,
                            const EdgeConstraints& constraints, const UnfoldOptions& options,
                            const ProgressFn& progress, double seconds_before) {
  if (!options.move_seams) return edges;
  CutTree tree(ctx, edges);
  if (tree.overlap_count() > 0) return edges;
  SeamMoveOptions so = options.seam_moves;
  if (progress) {
    const auto start = std::chrono::steady_clock::now();
    so.progress = [&progress, start, seconds_before](long done, long total) {
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const long percent = total > 0 ? 100 * done / total : 0;
      progress({"moving seams " + std::to_string(percent) + "%", static_cast<int>(done), 0, 0,
                seconds_before + s});
    };
  }
  const SeamMoveResult r = move_seams(tree, constraints, tight_edges(*ctx.mesh, options.cuts), so);
  return r.moves > 0 ? tree.states() : edges;
}

// Trees that fold every edge too tight for a label (CutOptions::label_room) are spindlier: on a few meshes
// the search cannot untangle them into one piece where it untangles minimum-perimeter trees, so they get
// a budget of steps only (UnfoldOptions::label_room_most_steps).
struct SearchRun {
  UnfoldContext ctx;
  SearchResult result;
};

SearchRun run_search(const Mesh& mesh, const CutOptions& cuts, const EdgeConstraints& constraints,
                     const UnfoldOptions& options, double time_limit_s, const ProgressFn& progress,
                     long max_steps = 0) {
  SearchRun run{make_context(mesh, cuts), {}};
  SearchOptions so = options.search;
  so.seed = options.seed;
  so.threads = options.threads;
  so.time_limit_s = time_limit_s;
  so.max_steps = max_steps;
  if (cuts.label_room > 0) so.cut_draws = options.label_room_cut_draws;
  so.constraints = constraints;
  run.result = search_unfold(run.ctx, spanning_forest(mesh, run.ctx.weight, constraints), so, progress);
  return run;
}

SearchRun search_with_label_room(const Mesh& mesh, const EdgeConstraints& constraints,
                                 const UnfoldOptions& options, const ProgressFn& progress,
                                 const std::function<double()>& elapsed) {
  if (!(options.cuts.label_room > 0))
    return run_search(mesh, options.cuts, constraints, options, options.time_limit_s, progress);
  SearchRun roomy =
      run_search(mesh, options.cuts, constraints, options, options.label_room_share * options.time_limit_s,
                 progress, std::max(options.label_room_most_steps, 1L));
  if (roomy.result.solved) return roomy;
  CutOptions plain = options.cuts;
  plain.label_room = 0;
  plain.label_tab_length = 0;
  SearchRun fallback =
      run_search(mesh, plain, constraints, options, options.time_limit_s - elapsed(), progress);
  // A forest's cut edges are E - F + pieces: fewer cuts, fewer pieces.
  const auto pieces = [&](const SearchRun& run) {
    return std::count(run.result.edges.begin(), run.result.edges.end(), EdgeState::Cut);
  };
  if (fallback.result.solved || pieces(fallback) < pieces(roomy)) return fallback;
  return roomy;
}

}  // namespace

UnfoldResult unfold_mesh(const Mesh& mesh, const UnfoldOptions& options, const ProgressFn& progress) {
  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  if (mesh.num_faces() > options.face_limit)
    throw TooManyFaces(mesh.name, mesh.num_faces(), options.face_limit);
  EdgeConstraints constraints = resolve_seams(mesh, options.seams);
  const FlatFaces flat = find_flat_faces(mesh, options.flat_angle_rad);
  keep_flat_faces(mesh, flat, constraints);
  UnfoldResult result;
  switch (options.method) {
    case Method::Mst:
      if (progress) progress({"mst", 0, 0, 0, elapsed()});
      result.unfolding = unfold_mst(mesh, constraints, options.cuts);
      result.method = "mst";
      break;
    case Method::Search: {
      const SearchRun run = search_with_label_room(mesh, constraints, options, progress, elapsed);
      const UnfoldContext& ctx = run.ctx;
      const SearchResult& r = run.result;
      if (progress && options.move_seams) progress({"moving seams 0%", 0, 0, 0, elapsed()});
      result.unfolding =
          flatten(mesh, with_seams_moved(ctx, r.edges, constraints, options, progress, elapsed()));
      result.method = "search";
      result.iterations = r.steps;
      if (!r.solved)
        result.notes.push_back("search stopped with " + std::to_string(r.overlaps_left) +
                               " overlapping pairs left: cut apart where they overlapped");
      break;
    }
    case Method::Ga: {
      const UnfoldContext ctx = make_context(mesh, options.cuts);
      GaOptions go = options.ga;
      go.seed = options.seed;
      go.time_limit_s = options.time_limit_s;
      go.threads = options.threads;
      go.constraints = constraints;
      const GaResult r = genetic_unfold(ctx, go, progress);
      if (progress && options.move_seams) progress({"moving seams 0%", 0, 0, 0, elapsed()});
      result.unfolding =
          flatten(mesh, with_seams_moved(ctx, r.edges, constraints, options, progress, elapsed()));
      result.method = r.method;
      result.iterations = r.generations;
      break;
    }
  }
  mark_flat_faces(flat, result.unfolding);
  if (flat.non_planar_polygons > 0)
    result.notes.push_back(std::to_string(flat.non_planar_polygons) +
                           " polygon(s) not planar within the flat angle: folded along their diagonals");
  // Several connected components are the loader's note (it says they unfold separately): not repeated.
  result.seconds = elapsed();
  if (progress) progress({result.method, result.iterations, result.unfolding.piece_count, 0, result.seconds});
  return result;
}

}  // namespace foldkit::unfold
