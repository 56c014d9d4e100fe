#pragma once
// Piece outlines: the closed loops of cut edges around each piece of an unfolding, and the pieces
// scaled to millimetres (y up, the net's own frame) with their outlines.
#include <array>
#include <span>
#include <vector>

#include "foldkit/geom/predicates.hpp"
#include "foldkit/unfold/unfolding.hpp"

namespace foldkit::layout {

/// One side of a cut edge on a piece's outline: it runs from `a` to `b` with the piece on its left.
struct OutlineEdge {
  int edge = -1;    ///< mesh edge
  int face = -1;    ///< face of the piece on this side
  int corner = -1;  ///< the side runs flat[face][corner] -> flat[face][(corner + 1) % 3]
  Vec2 a, b;
};

/// A closed boundary loop, in order: edges[i].b == edges[i + 1].a.
using OutlineLoop = std::vector<OutlineEdge>;

/// Boundary loops of the piece made of `faces`, interior on the left (the outer loop counter-clockwise),
/// in the unfolding's model units. A piece whose folds form a tree is a disk, so this is normally one
/// loop; it may touch itself at vertices.
std::vector<OutlineLoop> piece_outline(const unfold::Unfolding& unfolding, std::span<const int> faces);

/// One piece in its own frame, in millimetres with y up.
struct ScaledPiece {
  int index = -1;                       ///< piece number in the unfolding
  std::vector<int> faces;               ///< mesh faces, increasing
  std::vector<Triangle2> triangles_mm;  ///< triangles_mm[k] is face faces[k], counter-clockwise
  std::vector<OutlineLoop> outline_mm;  ///< piece_outline scaled
  double area_mm2 = 0;
};

/// Every piece of the unfolding scaled by `scale_mm_per_unit`.
std::vector<ScaledPiece> scaled_pieces(const unfold::Unfolding& unfolding, double scale_mm_per_unit);

/// Where one side of a seam sits: pieces[piece].outline_mm[loop][index].
struct SeamSide {
  int piece = -1, loop = -1, index = -1;
};

/// A glued seam: a cut edge with a partner, and its two sides on the outlines. sides[k] is the side of
/// the edge's face[k].
struct Seam {
  int edge = -1;
  double fold_angle_rad = 0;
  std::array<SeamSide, 2> sides;
};

/// Every glued seam of the unfolding, in increasing edge order.
std::vector<Seam> find_seams(const unfold::Unfolding& unfolding, std::span<const ScaledPiece> pieces);

}  // namespace foldkit::layout
