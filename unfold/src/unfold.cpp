#include "foldkit/unfold/unfold.hpp"

#include <chrono>
#include <string>

#include "foldkit/error.hpp"
#include "foldkit/unfold/dual_graph.hpp"
#include "foldkit/unfold/mst.hpp"
#include "foldkit/unfold/seams.hpp"

namespace foldkit::unfold {

UnfoldResult unfold_mesh(const Mesh& mesh, const UnfoldOptions& options, const ProgressFn& progress) {
  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  const EdgeConstraints constraints = resolve_seams(mesh, options.seams);
  UnfoldResult result;
  switch (options.method) {
    case Method::Mst:
      if (progress) progress({"mst", 0, 0, 0, elapsed()});
      result.unfolding = unfold_mst(mesh, constraints);
      result.method = "mst";
      break;
    case Method::Ga:
    case Method::Search:
      throw Error("--method ga and --method search are not available yet: use --method mst", ExitCode::Usage);
  }
  if (int components = count_components(mesh); components > 1)
    result.notes.push_back(std::to_string(components) + " connected components unfolded separately");
  result.seconds = elapsed();
  if (progress) progress({result.method, result.iterations, result.unfolding.piece_count, 0, result.seconds});
  return result;
}

}  // namespace foldkit::unfold
