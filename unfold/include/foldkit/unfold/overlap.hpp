#pragma once
// Finding overlapping triangles within pieces of an unfolding: the whole-unfolding check used by the
// MST baseline and by check_unfolding. The incremental index of the search lives elsewhere.
#include <vector>

#include "foldkit/geom/predicates.hpp"

namespace foldkit::unfold {

/// Two faces, a < b.
struct FacePair {
  int a = -1, b = -1;
  friend bool operator==(const FacePair&, const FacePair&) = default;
};

/// The tolerance (a length) under which interiors that meet are treated as touching, not overlapping:
/// a millionth of the mean edge length, far below anything a blade or a printer resolves and far
/// above the rounding error of flattening.
double overlap_tolerance(const std::vector<Triangle2>& flat);

/// Every pair of faces of the same piece whose flat triangles' interiors overlap by more than
/// `eps_length` (touching along an edge or at a vertex is not an overlap), sorted by (a, b).
/// A uniform grid over bounding boxes keeps this near linear in the number of faces.
std::vector<FacePair> overlapping_pairs(const std::vector<Triangle2>& flat,
                                        const std::vector<int>& piece_of_face, double eps_length);

/// Same, with overlap_tolerance(flat).
std::vector<FacePair> overlapping_pairs(const std::vector<Triangle2>& flat,
                                        const std::vector<int>& piece_of_face);

}  // namespace foldkit::unfold
