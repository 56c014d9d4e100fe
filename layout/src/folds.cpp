#include "foldkit/layout/folds.hpp"

#include <algorithm>
#include <cmath>

namespace foldkit::layout {

PathRole fold_role(double angle_rad) {
  return angle_rad > 0 ? PathRole::Mountain : PathRole::Valley;
}

std::vector<FoldLine> fold_lines(const unfold::Unfolding& u, const ScaledPiece& piece,
                                 const FoldOptions& options) {
  std::vector<FoldLine> out;
  for (std::size_t k = 0; k < piece.faces.size(); ++k) {
    const int f = piece.faces[k];
    for (int c = 0; c < 3; ++c) {
      const int e = u.face_edges[f][c];
      const unfold::UnfoldEdge& edge = u.edges[e];
      // Each fold is shared by two faces of the piece: draw it from face[0]'s side only.
      if (edge.cut || edge.boundary() || edge.inside_face || edge.face[0] != f) continue;
      if (std::fabs(edge.fold_angle) < options.flat_fold_rad) continue;
      Vec2 a = piece.triangles_mm[k][c], b = piece.triangles_mm[k][(c + 1) % 3];
      const double length = norm(b - a);
      if (length <= 0) continue;
      const double inset = std::min(options.inset_mm, 0.25 * length);
      const Vec2 dir = (b - a) / length;
      out.push_back({fold_role(edge.fold_angle), a + dir * inset, b - dir * inset, e});
    }
  }
  return out;
}

}  // namespace foldkit::layout
