#pragma once
// The result of unfolding: flat triangles grouped into pieces, plus per-edge fold information.
// Self-contained, so layout/ needs nothing but this to draw pieces, folds and matching edges.
#include <array>
#include <string>
#include <vector>

#include "foldkit/geom/predicates.hpp"
#include "foldkit/geom/vec.hpp"
#include "foldkit/unfold/edge_state.hpp"
#include "foldkit/unfold/mesh.hpp"

namespace foldkit::unfold {

/// One mesh edge as seen by the unfolding.
struct UnfoldEdge {
  /// The (one or two) faces and corners of the mesh edge; face[1] == -1 on a mesh boundary.
  std::array<int, 2> face{-1, -1};
  std::array<int, 2> corner{-1, -1};
  /// Cut (outline) or fold; boundary edges are always cut. A plain flag for layout; the unfolders'
  /// typed form is state() and edge_states().
  bool cut = false;
  double fold_angle = 0;     ///< signed dihedral in radians: > 0 mountain, < 0 valley (see fold_angle())
  double length = 0;         ///< model units
  bool inside_face = false;  ///< joins two triangles of one flat face: never cut, never drawn
  bool boundary() const { return face[1] < 0; }
  EdgeState state() const { return cut ? EdgeState::Cut : EdgeState::Fold; }
  /// A cut edge with a partner on the other side: the two sides are glued together.
  bool glued_seam() const { return cut && !boundary(); }
};

/// Invariants (checked by check_unfolding): every flat triangle congruent to its 3D face and
/// counter-clockwise (nothing mirrored); faces of a piece connected through fold edges; the two
/// copies of a fold edge coincide; no two triangles of one piece overlap.
struct Unfolding {
  /// flat[f][i] is corner i of mesh face f (mesh.faces[f][i]) in the plane, model units.
  std::vector<Triangle2> flat;
  /// piece_of_face[f] in 0..piece_count-1.
  std::vector<int> piece_of_face;
  int piece_count = 0;
  /// Same as Mesh::face_edges.
  std::vector<std::array<int, 3>> face_edges;
  std::vector<UnfoldEdge> edges;
  /// Largest dimension of the 3D model's bounding box, model units (for --size).
  double model_extent = 0;

  int num_faces() const { return static_cast<int>(flat.size()); }
  /// Faces of each piece, in increasing face order.
  std::vector<std::vector<int>> piece_faces() const;
  /// Number of cut edges that are glued seams (have a partner).
  int seam_count() const;
};

/// The state of every edge of `unfolding` (as flatten() takes it back).
EdgeStates edge_states(const Unfolding& unfolding);

/// Lays every piece of the spanning forest given by `state` (one per mesh edge; boundary edges are
/// treated as cut whatever their state, edges past its end as folds) flat: a breadth-first walk over fold
/// edges from the lowest face of each piece, each face placed by the rigid motion that maps its fold edge
/// onto its parent's. The fold edges must form a forest (no cycle): cycles are broken by cutting the edge
/// that closes them.
Unfolding flatten(const Mesh& mesh, const EdgeStates& state);

/// flatten(), with the edges inside flat faces marked as in `like` (an unfolding of the same mesh) where
/// they stay folded: the flat faces of an unfolding a partition was made from.
Unfolding flatten_like(const Mesh& mesh, const EdgeStates& state, const Unfolding& like);

/// Every violation of the invariants above, one readable line each; empty when the unfolding is valid.
/// `rel_tol` bounds the relative error of flat edge lengths.
std::vector<std::string> check_unfolding(const Mesh& mesh, const Unfolding& unfolding, double rel_tol = 1e-9);

}  // namespace foldkit::unfold
