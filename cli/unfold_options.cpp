#include "unfold_options.hpp"

#include <cstdio>
#include <map>

#include "foldkit/error.hpp"
#include "foldkit/unfold/seams.hpp"

namespace foldkit::cli {

void add_unfold_options(CLI::App& cmd, UnfoldCliOptions& o) {
  auto* group = "Unfolding";
  cmd.add_option("--max-faces", o.load.max_faces, "Decimate to at most N faces first (default: keep all)")
      ->check(CLI::Range(4, 100'000'000))
      ->group(group);
  cmd.add_option("--method", o.method, "Unfolding method: mst (baseline), search, ga, or default")
      ->check(CLI::IsMember({"default", "mst", "search", "ga"}))
      ->group(group);
  cmd.add_option("--seed", o.unfold.seed, "Random seed: the same seed gives the same result")->group(group);
  cmd.add_option("--time-limit", o.unfold.time_limit_s, "Seconds the search or GA may take (default 60)")
      ->check(CLI::Range(0.01, 1e6))
      ->group(group);
  cmd.add_option("--threads", o.unfold.threads, "Worker threads (0: all cores)")
      ->check(CLI::Range(0, 256))
      ->group(group);
  cmd.add_option("--population", o.unfold.population, "GA population size (default 64)")
      ->check(CLI::Range(4, 100000))
      ->group(group);
  cmd.add_option("--lambda-p", o.unfold.lambda_p, "GA fitness weight of the piece count")->group(group);
  cmd.add_option("--lambda-l", o.unfold.lambda_l, "GA fitness weight of the outline length")->group(group);
  cmd.add_option("--lambda-m", o.unfold.lambda_m, "GA fitness weight of the sheet margin")->group(group);
  cmd.add_option("--lambda-b", o.unfold.lambda_b, "GA fitness weight of matching-edge distance")
      ->group(group);
  cmd.add_option("--cut", o.cut_file, "File of edges (vertex index pairs) that must be cut")->group(group);
  cmd.add_option("--keep", o.keep_file, "File of edges (vertex index pairs) that must stay folded")
      ->group(group);
}

void finish_unfold_options(UnfoldCliOptions& o) {
  static const std::map<std::string, unfold::Method> methods = {
      {"mst", unfold::Method::Mst}, {"search", unfold::Method::Search}, {"ga", unfold::Method::Ga}};
  if (auto it = methods.find(o.method); it != methods.end()) o.unfold.method = it->second;
  if (!o.cut_file.empty()) o.unfold.seams.force_cut = unfold::read_edge_list(o.cut_file);
  if (!o.keep_file.empty()) o.unfold.seams.forbid_cut = unfold::read_edge_list(o.keep_file);
}

UnfoldRun load_and_unfold(const std::string& mesh_file, const UnfoldCliOptions& options, ProgressLine& line,
                          const std::function<void(const unfold::LoadedMesh&)>& check_loaded) {
  UnfoldRun run;
  line.update("loading " + mesh_file);
  run.loaded = unfold::load_mesh(mesh_file, options.load);
  if (check_loaded) check_loaded(run.loaded);
  auto report = [&line](const unfold::UnfoldProgress& p) {
    char text[160];
    std::snprintf(text, sizeof text, "unfolding: %s, step %d, %d piece%s, %.1f s", p.stage.c_str(),
                  p.iteration, p.pieces, p.pieces == 1 ? "" : "s", p.seconds);
    line.update(text);
    return true;
  };
  run.result = unfold::unfold_mesh(run.loaded.mesh, options.unfold, report);
  return run;
}

}  // namespace foldkit::cli
