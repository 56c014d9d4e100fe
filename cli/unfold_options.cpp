#include "unfold_options.hpp"

#include <cstdio>
#include <map>
#include <numbers>

#include "choices.hpp"
#include "foldkit/error.hpp"
#include "foldkit/unfold/seams.hpp"
#include "length_option.hpp"

namespace foldkit::cli {
namespace {

// What --method takes: "default", then the methods.
std::vector<std::string> method_names_and_default() {
  std::vector<std::string> names = choice_names(unfold_methods());
  names.insert(names.begin(), "default");
  return names;
}

}  // namespace

const std::vector<std::pair<std::string, unfold::Method>>& unfold_methods() {
  static const std::vector<std::pair<std::string, unfold::Method>> methods = {
      {"mst", unfold::Method::Mst}, {"search", unfold::Method::Search}, {"ga", unfold::Method::Ga}};
  return methods;
}

void add_unfold_options(CLI::App& cmd, UnfoldCliOptions& o) {
  auto* group = "Unfolding";
  cmd.add_option("--max-faces", o.load.max_faces, "Decimate to at most N faces first (default: keep all)")
      ->check(number_in(4, 100e6, "faces"))
      ->group(group);
  cmd.add_option("--method", o.method, "Unfolding method: mst (baseline), search, ga, or default")
      ->check(CLI::IsMember(method_names_and_default()))
      ->group(group);
  cmd.add_option("--seed", o.unfold.seed, "Random seed: the same seed gives the same result")->group(group);
  cmd.add_option("--time-limit", o.unfold.time_limit_s,
                 "Seconds the command may take: the search or GA gets 3/4 of it, layout the rest; past it "
                 "the command stops with a message (default 60)")
      ->check(number_in(0.01, 1e6, "s"))
      ->group(group);
  cmd.add_option("--threads", o.unfold.threads, "Worker threads (0: all cores)")
      ->check(number_in(0, 256, "threads"))
      ->group(group);
  cmd.add_option("--population", o.unfold.ga.population, "GA population size (default 64)")
      ->check(number_in(4, 100000))
      ->group(group);
  cmd.add_option("--lambda-p", o.unfold.ga.weights.lambda_p, "GA fitness weight of the piece count")
      ->group(group);
  cmd.add_option("--lambda-l", o.unfold.ga.weights.lambda_l,
                 "GA fitness weight of R_l, the share of faces outside the largest piece")
      ->group(group);
  cmd.add_option("--lambda-m", o.unfold.ga.weights.lambda_m, "GA fitness weight of the sheet margin")
      ->group(group);
  cmd.add_option("--lambda-b", o.unfold.ga.weights.lambda_b, "GA fitness weight of matching-edge distance")
      ->group(group);
  cmd.add_option(
         "--flat-angle", o.flat_angle_deg,
         "Degrees within which a polygon, or a run of triangles, counts as one flat face that is never "
         "cut (default 0.5)")
      ->check(number_in(0, 30, "degrees"))
      ->group(group);
  cmd.add_option("--cut", o.cut_file,
                 "File of edges that must be cut: pairs of vertex numbers as the mesh file writes them")
      ->group(group);
  cmd.add_option("--keep", o.keep_file, "File of edges that must stay folded (vertex number pairs, as --cut)")
      ->group(group);
  cmd.add_option("--index-base", o.index_base,
                 "Number of the first vertex in --cut/--keep lists (default: the mesh format's own, OBJ 1, "
                 "OFF and PLY 0)")
      ->check(number_in(0, 1))
      ->group(group);
}

void finish_unfold_options(UnfoldCliOptions& o) {
  for (const auto& [name, method] : unfold_methods())
    if (o.method == name) o.unfold.method = method;
  o.unfold.flat_angle_rad = o.flat_angle_deg * std::numbers::pi / 180.0;
}

namespace {

// The user's seams and the file's own, in the loaded mesh's numbering.
unfold::SeamConstraints seams_of(const unfold::LoadedMesh& loaded, const std::string& mesh_file,
                                 const UnfoldCliOptions& o, std::vector<std::string>& notes) {
  unfold::SeamConstraints seams = o.unfold.seams;
  const int base = o.index_base.value_or(loaded.index_base);
  const auto add = [&](const std::string& list, std::vector<std::array<int, 2>>& to) {
    if (list.empty()) return;
    const auto edges = unfold::to_mesh_edges(loaded, unfold::read_edge_list(list, base), list, base);
    to.insert(to.end(), edges.begin(), edges.end());
  };
  add(o.cut_file, seams.force_cut);
  add(o.keep_file, seams.forbid_cut);
  if (!loaded.file_seams.empty()) {
    const auto edges = unfold::to_mesh_edges(loaded, loaded.file_seams, mesh_file, loaded.index_base);
    seams.force_cut.insert(seams.force_cut.end(), edges.begin(), edges.end());
    notes.push_back(std::to_string(loaded.file_seams.size()) +
                    " seam edge(s) marked in the file (l elements) cut");
  }
  return seams;
}

}  // namespace

UnfoldRun load_and_unfold(const std::string& mesh_file, const UnfoldCliOptions& options, ProgressLine& line,
                          const PrepareUnfold& prepare) {
  UnfoldRun run;
  line.update("loading " + mesh_file);
  run.loaded = unfold::load_mesh(mesh_file, options.load);
  unfold::UnfoldOptions unfold_options = options.unfold;
  if (prepare) prepare(run.loaded, unfold_options);
  auto report = [&line](const unfold::UnfoldProgress& p) {
    char text[160];
    char pieces[32] = "";  // not known between stages
    if (p.pieces > 0)
      std::snprintf(pieces, sizeof pieces, ", %d piece%s", p.pieces, p.pieces == 1 ? "" : "s");
    std::snprintf(text, sizeof text, "unfolding: %s, step %d%s, %.1f s", p.stage.c_str(), p.iteration, pieces,
                  p.seconds);
    line.update(text);
    return true;
  };
  unfold_options.seams = seams_of(run.loaded, mesh_file, options, run.loaded.notes);
  try {
    run.result = unfold::unfold_mesh(run.loaded.mesh, unfold_options, report);
    run.options = unfold_options;
  } catch (const unfold::TooManyFaces& e) {
    throw InputError(e.file(), e.problem() + ", e.g. --max-faces 5000");
  } catch (const unfold::SeamError& e) {
    throw Error(e.message({"--cut", "--keep"}), ExitCode::Usage);
  }
  return run;
}

}  // namespace foldkit::cli
