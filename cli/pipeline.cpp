#include "pipeline.hpp"

#include <chrono>
#include <cstdio>
#include <utility>

#include "choose_parts.hpp"
#include "foldkit/error.hpp"
#include "limits.hpp"

namespace foldkit::cli {
namespace {

// --time-limit bounds the whole command; the unfolders stop early with a valid result, the layout
// cannot, so the unfolding gets this share and the layout the rest.
constexpr double kUnfoldShareOfTimeLimit = 0.75;

}  // namespace

std::optional<layout::LayoutResult> choose_and_note_parts(const unfold::Mesh& mesh,
                                                          unfold::UnfoldResult& result,
                                                          const layout::LayoutOptions& layout_options) {
  // One large piece (the unfolders' aim) may not fit the paper at the asked size: cut it into parts
  // that do, and say so, rather than refuse.
  ChosenParts parts = choose_parts(mesh, result.unfolding, layout_options);
  if (parts.split_pieces > 0)
    result.notes.push_back(
        std::to_string(parts.split_pieces) + " piece(s) larger than the paper at this size cut into " +
        std::to_string(parts.new_pieces) + " parts that fit (--fit or --no-split keeps them whole)");
  result.unfolding = std::move(parts.unfolding);
  return std::move(parts.layout);
}

PipelineRun load_unfold_layout(const std::string& mesh_file, const UnfoldCliOptions& unfold_options,
                               const layout::LayoutOptions& layout_options, ProgressLine& line) {
  const double limit_s = unfold_options.unfold.time_limit_s;
  const auto deadline =
      std::chrono::steady_clock::now() +
      std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(limit_s));
  UnfoldCliOptions unfold_share = unfold_options;
  unfold_share.unfold.time_limit_s = kUnfoldShareOfTimeLimit * limit_s;
  layout::LayoutOptions bounded = layout_options;
  bounded.deadline = deadline;

  PipelineRun run;
  run.unfolded = load_and_unfold(mesh_file, unfold_share, line, [&](const unfold::LoadedMesh& loaded) {
    check_sheet_budget(loaded.mesh, layout_options);
  });
  line.update("laying out " + std::to_string(run.unfolded.result.unfolding.piece_count) + " pieces");
  const auto start = std::chrono::steady_clock::now();
  try {
    auto laid_out = choose_and_note_parts(run.unfolded.loaded.mesh, run.unfolded.result, bounded);
    run.layout =
        laid_out ? std::move(*laid_out) : layout::layout_sheets(run.unfolded.result.unfolding, bounded);
  } catch (const LayoutError& e) {
    if (std::chrono::steady_clock::now() <= deadline) throw;
    char limit[32];
    std::snprintf(limit, sizeof limit, "%g", limit_s);
    throw LayoutError(mesh_file + ": " + e.what() + " (--time-limit " + limit +
                      " s bounds the whole command: give more time, a smaller --size or --max-faces)");
  }
  run.layout_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

}  // namespace foldkit::cli
