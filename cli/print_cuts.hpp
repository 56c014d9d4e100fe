#pragma once
// The cuts the print scale asks for: at a known model size, edges beside which the smallest edge number
// cannot sit clear of the lines are folded rather than cut (unfold::CutOptions::label_room), by the
// unfolders and by the split into parts alike, so that the seams are where labels fit.
#include "foldkit/layout/layout.hpp"
#include "foldkit/unfold/dual_graph.hpp"
#include "foldkit/unfold/mesh.hpp"

namespace foldkit::cli {

/// `cuts` with label_room and label_aspect set for printing `mesh` at o.size_mm: the box a two-digit
/// number at the smallest cap height needs beside its edge (lifted by the gap, kept clear by the
/// clearance; o.label). Unchanged without a size (--fit decides the scale after the unfolding) or
/// without numbers.
unfold::CutOptions cuts_for_print(const unfold::Mesh& mesh, const layout::LayoutOptions& o,
                                  unfold::CutOptions cuts);

}  // namespace foldkit::cli
