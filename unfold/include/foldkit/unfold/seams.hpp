#pragma once
// Seams chosen by the user (the seed's interface for seams): edges that must be cut (`--cut FILE`)
// or must stay folded (`--keep FILE`), named by the vertex indices of their two ends.
#include <array>
#include <filesystem>
#include <vector>

#include "foldkit/unfold/dual_graph.hpp"
#include "foldkit/unfold/mesh.hpp"
#include "foldkit/unfold/unfold.hpp"

namespace foldkit::unfold {

/// Reads an edge list: one edge per line as two 0-based vertex indices of the loaded mesh ("12 40",
/// commas allowed), blank lines and '#' comments ignored. Throws InputError(file, "line N: ...").
std::vector<std::array<int, 2>> read_edge_list(const std::filesystem::path& path);

/// Turns vertex pairs into per-edge flags. Throws Error (ExitCode::Usage) naming the first pair that is
/// not an edge of the mesh, an edge that is both cut and kept, or kept edges that close a loop of
/// folds (which no flat piece can have).
EdgeConstraints resolve_seams(const Mesh& mesh, const SeamConstraints& seams);

}  // namespace foldkit::unfold
