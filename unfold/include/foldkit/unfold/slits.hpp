#pragma once
// Slits: glued seams whose two sides lie against each other in one piece, so that no glue tab fits on
// either side. The common one is a cut-tree leaf at a nearly flat vertex: its two sides meet there at
// an angle equal to the vertex's defect, about a degree on a 1,000-face mesh. A cut path through flat
// vertices whose branch beyond turns by almost nothing makes a longer one, both sides touching along
// several edges. Moving the cuts closes most of them (seam_moves.hpp); the leaves left are at the cone
// points (nose, ears, tips), where the wedge is wide.
#include "foldkit/geom/rigid.hpp"
#include "foldkit/unfold/cut_tree.hpp"
#include "foldkit/unfold/unfolding.hpp"

namespace foldkit::unfold {

/// A seam within one piece is a slit when the two copies of each of its ends are closer than this
/// fraction of its length: the far end of a leaf's wedge then opens by less than about 40 degrees, too
/// little for a tab of a third of the edge's length whose slants stay in the wedge.
inline constexpr double kSlitGapPerLength = 0.7;

/// How far apart the two sides of cut edge e lie, relative to its length: the larger of the distances
/// between the two copies of each end. Infinite for a boundary edge, a fold or a seam between pieces.
double seam_gap_per_length(const CutTree& tree, EdgeId e);

/// The same for cut edge e between face `moved`, placed by `motion`, and its other face where it lies
/// (whether or not they are in one piece): what the gap would be after a rigid move of `moved`'s side.
double seam_gap_per_length(const CutTree& tree, EdgeId e, FaceId moved, const RigidMotion& motion);

/// Per face of `u`, the faces across its seams within one piece whose two sides lie closer than
/// `gap` (model units) at both ends of the edge: while the two faces stay in one part, no glue tab of
/// that width fits between them.
std::vector<std::vector<int>> narrow_seam_partners(const Unfolding& u, double gap);

/// Number of slits of `tree` (seams whose gap per length is below `min_gap_per_length`).
int count_slits(const CutTree& tree, double min_gap_per_length);

/// What a seam of this gap costs as a slit: 0 when it is none, else 1 plus up to 1 more the tighter it
/// is (a wider slit is progress: from there it may close).
double slit_cost(double gap_per_length, double min_gap_per_length);

}  // namespace foldkit::unfold
