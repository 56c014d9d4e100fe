#include "print_cuts.hpp"

#include <algorithm>
#include <cmath>

#include "foldkit/layout/tabs.hpp"

namespace foldkit::cli {
namespace {

// Seam numbers run per part and pair of parts: at a few hundred faces most have two digits.
constexpr double kTypicalDigits = 2;

}  // namespace

unfold::CutOptions cuts_for_print(const unfold::Mesh& mesh, const layout::LayoutOptions& o,
                                  unfold::CutOptions cuts) {
  if (!o.size_mm || o.fit || !o.numbers || mesh.vertices.empty()) return cuts;
  const double extent = unfold::bounds_of(mesh).largest_dimension();
  if (!(extent > 0) || !(*o.size_mm > 0)) return cuts;
  const layout::LabelOptions& label = o.label;
  // The label's box, standing on the edge: from the edge to the clearance above the cap height, and the
  // number's width with the clearance either side.
  const double height_mm = label.gap_mm + label.min_mm + label.clearance_mm;
  const double width_mm = kTypicalDigits * label.char_width * label.min_mm + 2 * label.clearance_mm;
  cuts.label_aspect = width_mm / height_mm;
  cuts.label_room = height_mm * extent / *o.size_mm;
  // A tab carries the label when it is as wide as the label's box is tall (it is at most
  // width_per_length of its edge) and its edge leaves the label's width between two steep ends.
  if (o.tabs && o.tab.width_per_length > 0) {
    const double tab_mm = std::max(height_mm / o.tab.width_per_length,
                                   width_mm + 2 * height_mm / std::tan(layout::kSteepestTabSlant_rad));
    cuts.label_tab_length = tab_mm * extent / *o.size_mm;
  }
  return cuts;
}

}  // namespace foldkit::cli
