#pragma once
// Printed colour: each face's colour or region of its texture on its flat triangle, grown past the cut
// lines by a bleed so that a cut a little off the line leaves no white edge, and tabs in the colour of
// the face they glue under. Added to sheets that layout_sheets made; nothing else on them changes.
#include "foldkit/layout/layout.hpp"
#include "foldkit/unfold/mesh.hpp"
#include "foldkit/unfold/unfolding.hpp"

namespace foldkit::layout {

enum class TabFill { Face, White };

struct FillOptions {
  /// How far colour reaches past every cut line, mm. Packing must leave pieces at least twice this apart
  /// (fill_spacing_mm).
  double bleed_mm = 1;
  TabFill tab_fill = TabFill::Face;
  /// Neighbouring faces overlap by this much across their folds, so antialiased edges leave no hairline.
  double fold_overlap_mm = 0.05;
};

/// True when the mesh has anything to print in colour (a material on some face).
bool has_colour(const unfold::Mesh& mesh);

/// The least spacing between pieces that keeps two pieces' bleeds apart.
double fill_spacing_mm(const FillOptions& options);

/// Adds a Fill per coloured face (and per tab, with TabFill::Face) to the sheets of `layout`, which
/// must have been laid out from `unfolding` of `mesh`. Texture images become Sheet::images.
void add_fills(LayoutResult& layout, const unfold::Mesh& mesh, const unfold::Unfolding& unfolding,
               const FillOptions& options);

}  // namespace foldkit::layout
