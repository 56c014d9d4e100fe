#include "pipeline.hpp"

#include <chrono>

namespace foldkit::cli {

PipelineRun load_unfold_layout(const std::string& mesh_file, const UnfoldCliOptions& unfold_options,
                               const layout::LayoutOptions& layout_options, ProgressLine& line) {
  PipelineRun run;
  run.unfolded = load_and_unfold(mesh_file, unfold_options, line);
  line.update("laying out " + std::to_string(run.unfolded.result.unfolding.piece_count) + " pieces");
  const auto start = std::chrono::steady_clock::now();
  run.layout = layout::layout_sheets(run.unfolded.result.unfolding, layout_options);
  run.layout_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

}  // namespace foldkit::cli
