#pragma once
// load -> unfold -> lay out: the part `foldkit make` and `foldkit cut` share.
#include <optional>
#include <string>

#include "choose_parts.hpp"
#include "foldkit/layout/fills.hpp"
#include "foldkit/layout/layout.hpp"
#include "progress.hpp"
#include "unfold_options.hpp"

namespace foldkit::cli {

struct PipelineRun {
  UnfoldRun unfolded;
  layout::LayoutResult layout;
  double layout_seconds = 0;
};

/// A layout whose labels left unclear (crossing a line or touching another) and seams without a glue tab
/// add up to at most this share of its labels is left as it is; beyond it, choose_and_note_parts tries a
/// second unfolding.
inline constexpr double kFewFlawsShare = 0.005;

/// Past this share of its labels in flaws, a layout's faces are too small for numbers at its size and
/// only the size mends them (the remedy note says which): choose_and_note_parts unfolds no other way.
/// Over `bench --layout` the other unfoldings took the worst share they met, 41% (212 of 518), to 34%;
/// cat_500 at 60 mm on 105x148 mm paper (flaws 1.6 times its labels) spent 48 of its 56 s on them and
/// printed 21 parts with 12 seams without a tab where its own unfolding gives 7 with 27 (session 47).
inline constexpr double kOnlyTheSizeMendsShare = 0.5;

/// Replaces result.unfolding by the parts a layout with `layout_options` needs (choose_parts.hpp), noting
/// any split in result.notes. What `make` lays out and `unfold --size` writes. Where those parts have
/// more flaws than kFewFlawsShare allows, and no more than kOnlyTheSizeMendsShare (meshes up to 500
/// faces at a fixed size), the mesh is unfolded again with seams where labels have room
/// (SeamPreference::Balanced) and that choice is kept when it takes fewer sheets, or as many with fewer
/// labels unclear and seams without a tab in all: run.result and run.options are then the second unfolding's.
/// Returns the layout of those parts when the choice made one. `choose` says what the choice may do beyond
/// picking parts (ChooseOptions; give it bleed_room first).
std::optional<layout::LayoutResult> choose_and_note_parts(UnfoldRun& run,
                                                          const layout::LayoutOptions& layout_options,
                                                          const ChooseOptions& choose = {});
/// `choose` with the gap its parts may close to kept wide enough for the colour `fills` bleed past the
/// cut lines, where `mesh` prints in colour (nullopt: it prints white).
ChooseOptions bleed_room(ChooseOptions choose, const unfold::Mesh& mesh,
                         const std::optional<layout::FillOptions>& fills);
/// `o` with the gap between pieces widened to what the colour `fills` bleed past the cut lines needs,
/// where `mesh` prints in colour (nullopt: it prints white). What `make` and `cut` lay out with, so what
/// `unfold --size` and `bench --layout` choose their parts with too.
layout::LayoutOptions with_bleed_gap(layout::LayoutOptions o, const unfold::Mesh& mesh,
                                     const std::optional<layout::FillOptions>& fills);

/// `e`, a refusal met once `mesh_file` was read, worded for the command line: "<file>: <problem>", the
/// model size of a piece too large for the sheet called --size. A script running many files learns
/// which one it was.
LayoutError naming_mesh(const std::string& mesh_file, const LayoutError& e);

/// Loads `mesh_file`, unfolds it and lays out the sheets, showing progress on `line`. Pieces too large
/// for the paper at the asked --size are first cut into parts that fit (choose_and_note_parts).
/// Throws InputError (mesh), LayoutError (does not fit: the options alone, or naming_mesh) or Error.
PipelineRun load_unfold_layout(const std::string& mesh_file, const UnfoldCliOptions& unfold_options,
                               const layout::LayoutOptions& layout_options, ProgressLine& line,
                               const std::optional<layout::FillOptions>& fills = std::nullopt,
                               const ChooseOptions& choose = {});

}  // namespace foldkit::cli
