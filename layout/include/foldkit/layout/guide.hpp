#pragma once
// The assembly guide: one page showing the model from four viewpoints (front, back and two
// three-quarter views from above), every part filled in its own colour (Path::tint = its letter's
// rank) and marked with its letter where it shows, so the builder sees where each part goes before
// gluing. Drawn by depth-sorting the projected triangles (painter's algorithm); a small raster of the
// painted result tells where each part is visible for its letter. With a glue order, the page lists
// the steps by part.
#include <string>
#include <vector>

#include "foldkit/layout/label_text.hpp"  // letter_rank: the tint of a part
#include "foldkit/layout/layout.hpp"
#include "foldkit/sheet/sheet.hpp"
#include "foldkit/unfold/mesh.hpp"
#include "foldkit/unfold/unfolding.hpp"

namespace foldkit::layout {

/// Which way is up in the guide's views: found from the mesh (upright_axis), or as the file was drawn.
enum class UpAxis { Auto, Y, Z };

struct GuideOptions {
  UpAxis up = UpAxis::Auto;
  Vec2 paper_mm{210, 297};
  double margin_mm = 10;
  std::string model_name;
  double letter_mm = 4;  ///< cap height of the part letters on the views
};

/// Which way the model stands in the guide's views: +Z where more of its surface lies flat at its lowest Z,
/// facing down, than at its lowest Y (a barn or a drum drawn for CAD, printing or by most low-poly
/// generators stands on Z), else +Y (the OBJ and glTF convention, and organic models with no flat base).
/// With Z up the front view looks along +Y. A box has no such cue: it is shown on its largest face
/// (GuideOptions::up says otherwise).
Vec3 upright_axis(const unfold::Mesh& mesh);

/// The guide page for `unfolding` (of `mesh`) as laid out in `layout` (letters, sheets, glue order).
/// Its paths are filled triangles in role Piece with Path::tint = the letter's rank and Path::shade
/// the lighting; its texts are the letters (role Piece) and the titles (role Sheet).
Sheet guide_sheet(const unfold::Mesh& mesh, const unfold::Unfolding& unfolding, const LayoutResult& layout,
                  const GuideOptions& options = {});

}  // namespace foldkit::layout
