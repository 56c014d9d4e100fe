#pragma once
// `foldkit inspect`: what the loader made of a mesh file, before unfolding.
#include <optional>
#include <string>
#include <vector>

namespace foldkit::cli {

/// What `foldkit inspect` was asked; the parser fills it, run_inspect does the work.
struct InspectArgs {
  std::string mesh;
  bool json = false;
  std::optional<int> max_faces;
};

/// Loads the mesh and prints its topology, curvature and colour report on stdout (JSON with --json). Throws
/// InputError.
void run_inspect(const InspectArgs& args);

}  // namespace foldkit::cli
