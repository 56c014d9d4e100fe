#include "pipeline.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <utility>

#include "choose_parts.hpp"
#include "foldkit/error.hpp"
#include "limits.hpp"
#include "print_cuts.hpp"

namespace foldkit::cli {
namespace {

// --time-limit bounds the whole command; the unfolders stop early with a valid result, the layout
// cannot, so the unfolding gets this share and the layout the rest.
constexpr double kUnfoldShareOfTimeLimit = 0.75;

}  // namespace

std::optional<layout::LayoutResult> choose_and_note_parts(UnfoldRun& run,
                                                          const layout::LayoutOptions& layout_options) {
  // One large piece (the unfolders' aim) may not fit the paper at the asked size: cut it into parts
  // that do, and say so, rather than refuse.
  unfold::UnfoldResult& result = run.result;
  ChosenParts parts = choose_parts(run.loaded.mesh, result.unfolding, layout_options,
                                   part_options_of(run.loaded.mesh, run.options));
  if (parts.patches)
    result.notes.push_back(std::to_string(parts.split_pieces) +
                           " piece(s) larger than the paper at this size: the model cut into " +
                           std::to_string(parts.new_pieces) +
                           " compact parts, which take fewer sheets than parts cut from the pieces (--fit or "
                           "--no-split keeps them whole)");
  else if (parts.split_pieces > 0)
    result.notes.push_back(
        std::to_string(parts.split_pieces) + " piece(s) larger than the paper at this size cut into " +
        std::to_string(parts.new_pieces) + " parts that fit (--fit or --no-split keeps them whole)");
  result.unfolding = std::move(parts.unfolding);
  return std::move(parts.layout);
}

PipelineRun load_unfold_layout(const std::string& mesh_file, const UnfoldCliOptions& unfold_options,
                               const layout::LayoutOptions& asked_layout_options, ProgressLine& line,
                               const std::optional<layout::FillOptions>& fills) {
  const double limit_s = unfold_options.unfold.time_limit_s;
  const auto deadline =
      std::chrono::steady_clock::now() +
      std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(limit_s));
  UnfoldCliOptions unfold_share = unfold_options;
  unfold_share.unfold.time_limit_s = kUnfoldShareOfTimeLimit * limit_s;
  layout::LayoutOptions layout_options = asked_layout_options;
  layout_options.deadline = deadline;

  PipelineRun run;
  run.unfolded = load_and_unfold(mesh_file, unfold_share, line,
                                 [&](const unfold::LoadedMesh& loaded, unfold::UnfoldOptions& options) {
                                   check_sheet_budget(loaded.mesh, layout_options);
                                   options.cuts = cuts_for_print(loaded.mesh, layout_options, options.cuts);
                                 });
  const bool coloured = fills && layout::has_colour(run.unfolded.loaded.mesh);
  // Bleed needs its share of the spacing between pieces.
  if (coloured)
    layout_options.pack.spacing_mm =
        std::max(layout_options.pack.spacing_mm, layout::fill_spacing_mm(*fills));
  const int pieces = run.unfolded.result.unfolding.piece_count;
  const std::string laying_out =
      "laying out " + std::to_string(pieces) + (pieces == 1 ? " piece: " : " pieces: ");
  line.update(laying_out + "starting");
  layout_options.progress = [&line, &laying_out](const layout::LayoutProgress& p) {
    if (!line.due()) return;
    const long percent = p.total > 0 ? 100 * p.done / p.total : 0;
    line.update(laying_out + p.stage + " " + std::to_string(percent) + "%");
  };
  const auto start = std::chrono::steady_clock::now();
  try {
    auto laid_out = choose_and_note_parts(run.unfolded, layout_options);
    run.layout = laid_out ? std::move(*laid_out)
                          : layout::layout_sheets(run.unfolded.result.unfolding, layout_options);
  } catch (const LayoutError& e) {
    if (std::chrono::steady_clock::now() <= deadline) throw;
    char limit[32];
    std::snprintf(limit, sizeof limit, "%g", limit_s);
    throw LayoutError(mesh_file + ": " + e.what() + " (--time-limit " + limit +
                      " s bounds the whole command: give more time, a smaller --size or --max-faces)");
  }
  if (coloured)
    layout::add_fills(run.layout, run.unfolded.loaded.mesh, run.unfolded.result.unfolding, *fills);
  run.layout_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

}  // namespace foldkit::cli
