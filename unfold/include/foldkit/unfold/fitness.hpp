#pragma once
// The seed's fitness of an unfolding (§5.3): f = λp·Np + λl·Rl + λm·Rm + λb·Rb, lower is better.
#include "foldkit/unfold/cut_tree.hpp"

namespace foldkit::unfold {

struct FitnessTerms {
  int pieces = 0;  ///< Np
  double rl = 0;   ///< R_l: faces outside the largest piece / all faces
  double rm = 0;   ///< margin left around the pieces after a shelf packing of their bounding boxes, in [0, 1]
  double rb = 0;  ///< mean outline distance between the two sides of a glued seam / outline length, in [0, 1]
};

struct FitnessWeights {
  double lambda_p = 100, lambda_l = 100, lambda_m = 10, lambda_b = 1;
};

/// The four terms for the current state of `tree`. Seams whose sides lie on different pieces count as
/// half an outline apart, the farthest two edges of one outline can be.
FitnessTerms fitness_terms(const CutTree& tree);

inline double fitness(const FitnessTerms& t, const FitnessWeights& w) {
  return w.lambda_p * t.pieces + w.lambda_l * t.rl + w.lambda_m * t.rm + w.lambda_b * t.rb;
}

}  // namespace foldkit::unfold
