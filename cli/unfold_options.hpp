#pragma once
// The options every command that unfolds shares (unfold, make, cut, bench): loading (--max-faces),
// the method and its parameters, and the user's seams (--cut/--keep).
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "foldkit/unfold/mesh_io.hpp"
#include "foldkit/unfold/unfold.hpp"
#include "progress.hpp"

namespace foldkit::cli {

struct UnfoldCliOptions {
  unfold::LoadOptions load;
  unfold::UnfoldOptions unfold;
  std::string method = "default";
  std::string cut_file, keep_file;
  double flat_angle_deg = unfold::kDefaultFlatAngleDeg;  ///< --flat-angle
  /// The number of the first vertex in --cut/--keep lists; nullopt: the mesh format's own (OBJ 1, OFF/PLY 0).
  std::optional<int> index_base;
};

/// The unfolding methods by the names --method and `bench --methods` take, in the order messages list them
/// (--method also takes "default": the library's choice).
const std::vector<std::pair<std::string, unfold::Method>>& unfold_methods();

/// Adds --max-faces, --method, --seed, --time-limit, --threads, --population, --lambda-p/-l/-m/-b,
/// --cut FILE, --keep FILE and --index-base to `cmd`, bound to `options`.
void add_unfold_options(CLI::App& cmd, UnfoldCliOptions& options);

/// Completes `options` after parsing: the method name. Throws Error.
void finish_unfold_options(UnfoldCliOptions& options);

/// Loads the mesh and unfolds it, showing progress on `line`. The seams of --cut/--keep and the mesh
/// file's own (OBJ `l` elements) are named by the file's vertex numbers and mapped onto the loaded mesh;
/// a pair that is not an edge of the file is an InputError (exit 3).
struct UnfoldRun {
  unfold::LoadedMesh loaded;
  unfold::UnfoldResult result;
  /// What the unfolding ran with (the cuts at the print scale, the --cut/--keep seams): the split into
  /// parts keeps to the same (part_options_of, choose_parts.hpp).
  unfold::UnfoldOptions options;
};
/// `prepare` runs between loading and unfolding: it may refuse (e.g. a size before any work) or fit the
/// unfold options to the loaded mesh (e.g. the cuts to the print scale, print_cuts.hpp).
using PrepareUnfold = std::function<void(const unfold::LoadedMesh&, unfold::UnfoldOptions&)>;
UnfoldRun load_and_unfold(const std::string& mesh_file, const UnfoldCliOptions& options, ProgressLine& line,
                          const PrepareUnfold& prepare = {});

}  // namespace foldkit::cli
