#pragma once
// The options every command that unfolds shares (unfold, make, cut, bench): loading (--max-faces),
// the method and its parameters, and the user's seams (--cut/--keep).
#include <functional>
#include <string>

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
};

/// Adds --max-faces, --method, --seed, --time-limit, --threads, --population, --lambda-p/-l/-m/-b,
/// --cut FILE and --keep FILE to `cmd`, bound to `options`.
void add_unfold_options(CLI::App& cmd, UnfoldCliOptions& options);

/// Completes `options` after parsing: the method name and the seam files. Throws Error/InputError.
void finish_unfold_options(UnfoldCliOptions& options);

/// Loads the mesh and unfolds it, showing progress on `line`; notes from loading and unfolding are
/// appended to `notes`.
struct UnfoldRun {
  unfold::LoadedMesh loaded;
  unfold::UnfoldResult result;
};
/// `check_loaded` runs between loading and unfolding (e.g. to refuse a size before any work).
UnfoldRun load_and_unfold(const std::string& mesh_file, const UnfoldCliOptions& options, ProgressLine& line,
                          const std::function<void(const unfold::LoadedMesh&)>& check_loaded = {});

}  // namespace foldkit::cli
