#include "pipeline.hpp"

#include <algorithm>
#include <chrono>
#include <utility>

#include "foldkit/layout/split.hpp"
#include "limits.hpp"

namespace foldkit::cli {

PipelineRun load_unfold_layout(const std::string& mesh_file, const UnfoldCliOptions& unfold_options,
                               const layout::LayoutOptions& asked_layout_options, ProgressLine& line,
                               const std::optional<layout::FillOptions>& fills) {
  PipelineRun run;
  layout::LayoutOptions layout_options = asked_layout_options;
  run.unfolded = load_and_unfold(mesh_file, unfold_options, line, [&](const unfold::LoadedMesh& loaded) {
    check_sheet_budget(loaded.mesh, layout_options);
  });
  const bool coloured = fills && layout::has_colour(run.unfolded.loaded.mesh);
  // Bleed needs its share of the spacing between pieces.
  if (coloured)
    layout_options.spacing_mm = std::max(layout_options.spacing_mm, layout::fill_spacing_mm(*fills));
  line.update("laying out " + std::to_string(run.unfolded.result.unfolding.piece_count) + " pieces");
  const auto start = std::chrono::steady_clock::now();
  // One large piece (the unfolders' aim) may not fit the paper at the asked size: cut it into parts
  // that do, and say so, rather than refuse.
  layout::SplitLayout done =
      layout::split_and_layout(run.unfolded.loaded.mesh, run.unfolded.result.unfolding, layout_options);
  layout::SplitResult& split = done.split;
  if (split.split_pieces > 0) {
    run.unfolded.result.notes.push_back(
        std::to_string(split.split_pieces) + " piece(s) larger than the paper at this size cut into " +
        std::to_string(split.new_pieces) + " parts that fit (--fit or --no-split keeps them whole)");
    run.unfolded.result.unfolding = std::move(split.unfolding);
  }
  run.layout = std::move(done.layout);
  if (coloured)
    layout::add_fills(run.layout, run.unfolded.loaded.mesh, run.unfolded.result.unfolding, *fills);
  run.layout_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

}  // namespace foldkit::cli
