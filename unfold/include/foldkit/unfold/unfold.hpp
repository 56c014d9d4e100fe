#pragma once
// The unfolding stage: Mesh -> Unfolding. Not reaching one piece is a result, not an exception.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "foldkit/unfold/mesh.hpp"
#include "foldkit/unfold/slits.hpp"
#include "foldkit/unfold/unfolding.hpp"

namespace foldkit::unfold {

enum class Method {
  Mst,     ///< [SP05]: minimum-perimeter spanning tree, overlaps resolved by cutting
  Ga,      ///< the seed's genetic topological surgery (§4-§6)
  Search,  ///< tabu-style repair search on a spanning tree (unfolding-notes.md)
};

/// Edges named by the user (pairs of vertex indices, 0-based, into the loaded mesh).
struct SeamConstraints {
  std::vector<std::array<int, 2>> force_cut;   ///< --cut FILE
  std::vector<std::array<int, 2>> forbid_cut;  ///< --keep FILE
};

struct UnfoldOptions {
  Method method = Method::Search;  ///< default: the repair search (bench: one piece where mst leaves many)
  std::uint64_t seed = 1;
  double time_limit_s = 60;  ///< wall-clock budget for GA/search
  int threads = 0;           ///< 0: as many as the hardware has
  int population = 64;       ///< GA population size
  /// Meshes with more faces are refused: no paper model has that many, and the work outside the time
  /// limit (index building, the final cutting apart) grows with the face count. Decimate first.
  int face_limit = 100'000;
  /// Fitness weights of §5.3: f = λp·Np + λl·Rl + λm·Rm + λb·Rb.
  double lambda_p = 100, lambda_l = 100, lambda_m = 10, lambda_b = 1;
  SeamConstraints seams;
  /// Triangles of a planar input polygon, and coplanar neighbours, within this angle of one normal are one
  /// flat face that is never cut (see flat_faces.hpp).
  double flat_angle_rad = 0.5 * 3.14159265358979323846 / 180.0;
  /// After the search or the GA, move cuts away from leaves at nearly flat vertices (slits.hpp), where
  /// no glue tab fits.
  bool close_slits = true;
  SlitOptions slits;
};

/// Progress report while unfolding; return false to cancel (the best result so far is returned).
struct UnfoldProgress {
  std::string stage;  ///< e.g. "ga 70%", "search"
  int iteration = 0;  ///< generation or move count
  int pieces = 0;     ///< best number of pieces so far
  double best_score = 0;
  double seconds = 0;
};
using ProgressFn = std::function<bool(const UnfoldProgress&)>;

struct UnfoldResult {
  Unfolding unfolding;
  double seconds = 0;
  std::string method;  ///< what produced the result, e.g. "mst", "ga(70%)+search"
  int iterations = 0;
  std::vector<std::string> notes;
};

/// Unfolds every connected component of `mesh`; pieces of all components are numbered together.
UnfoldResult unfold_mesh(const Mesh& mesh, const UnfoldOptions& options, const ProgressFn& progress = {});

}  // namespace foldkit::unfold
