#pragma once
// Parts cut open at their slits. A slit (slits.hpp) is a seam whose two sides lie in one part too close
// for a glue tab: mostly a cut-tree leaf at a nearly flat vertex, a dart a few degrees wide. A part's
// folds form a tree, so cutting one fold on the way from one side of a slit to the other splits the part
// in two with the sides apart, and the slit becomes a seam between two parts, which the layout gives a
// tab. For a dart the way runs round its tip, so one fold edge at the tip parts the whole dart. Each new
// part is a piece of an overlap-free part that fitted the room: it is overlap-free and fits as well.
#include "foldkit/unfold/mesh.hpp"
#include "foldkit/unfold/parts.hpp"
#include "foldkit/unfold/unfolding.hpp"

namespace foldkit::unfold {

/// `parts` with parts cut until none holds both sides of a seam narrower than options.slit_gap_mm at
/// options.mm_per_unit, one fold edge at a time: the edge that parts the most slits, leaving no side
/// smaller than a few faces where another edge does not, then the one where both labels of the new seam
/// fit (options.cuts), then the one with the most even sides, then the longest. Never a fold inside a
/// flat face or one the user asked to keep (options.constraints); a slit that only such folds could part
/// stays. With options.also_split (sorted part indices) only those parts are opened. `parts` itself
/// when nothing is cut.
Unfolding cut_open_at_slits(const Mesh& mesh, const Unfolding& parts, const PartOptions& options);

}  // namespace foldkit::unfold
