#pragma once
// The unfolding stage: Mesh -> Unfolding. Not reaching one piece is a result, not an exception.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "foldkit/error.hpp"
#include "foldkit/unfold/flat_faces.hpp"
#include "foldkit/unfold/genetic.hpp"
#include "foldkit/unfold/mesh.hpp"
#include "foldkit/unfold/progress.hpp"
#include "foldkit/unfold/seam_moves.hpp"
#include "foldkit/unfold/search.hpp"
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

/// The stage options nest: `search`, `ga` and `seam_moves` are passed down whole. The run-wide `seed`,
/// `time_limit_s` and `threads` (and the constraints resolved from `seams` and the flat faces) are the
/// ones every stage gets: unfold_mesh sets them on the nested options, whatever those hold.
struct UnfoldOptions {
  Method method = Method::Search;  ///< default: the repair search (bench: one piece where mst leaves many)
  std::uint64_t seed = 1;
  double time_limit_s = 60;  ///< wall-clock budget for GA/search
  int threads = 0;           ///< 0: as many as the hardware has
  /// Meshes with more faces are refused: no paper model has that many, and the work outside the time
  /// limit (index building, the final cutting apart) grows with the face count. Decimate first.
  int face_limit = 100'000;
  SeamConstraints seams;
  /// Triangles of a planar input polygon, and coplanar neighbours, within this angle of one normal are one
  /// flat face that is never cut (see flat_faces.hpp).
  double flat_angle_rad = kDefaultFlatAngleRad;
  /// After the search or the GA, move cuts away from leaves at nearly flat vertices (slits.hpp), where
  /// no glue tab fits, and, with cuts.label_room set, off edges too tight for their labels
  /// (seam_moves.hpp).
  bool move_seams = true;
  SeamMoveOptions seam_moves;
  /// Which cuts every unfolder prefers where several trees unfold as well (dual_graph.hpp).
  CutOptions cuts;
  /// With cuts.label_room set, the search first gets at most label_room_most_steps steps per walk on
  /// the trees that keep seams where labels fit (about 5 s on the slowest 2,000-face meshes, the same
  /// on a busy machine, where a wall-clock share gave other trees); where those leave overlaps, it starts
  /// again without label room with the time left, and the result with fewer pieces is kept. The share
  /// label_room_share of time_limit_s is only an outer safety.
  double label_room_share = 0.25;
  long label_room_most_steps = 250'000;
  /// With cuts.label_room set, the search's SearchOptions::cut_draws: its walk cuts roomy edges more
  /// often while it removes overlaps, and so fewer tight ones.
  int label_room_cut_draws = 6;
  SearchOptions search;  ///< `--method search` (portfolio, tabu tenure, ...)
  GaOptions ga;          ///< `--method ga` (population, fitness weights, ...)
};

struct UnfoldResult {
  Unfolding unfolding;
  double seconds = 0;
  std::string method;  ///< what produced the result, e.g. "mst", "ga(70%)+search"
  int iterations = 0;
  std::vector<std::string> notes;
};

/// A mesh over UnfoldOptions::face_limit: decimate first (the CLI says how).
class TooManyFaces : public InputError {
 public:
  TooManyFaces(const std::string& mesh_name, int faces, int limit)
      : InputError(mesh_name, std::to_string(faces) + " faces, more than the " + std::to_string(limit) +
                                  " foldkit unfolds (no paper model has that many): decimate first") {}
};

/// Unfolds every connected component of `mesh`; pieces of all components are numbered together.
/// Throws TooManyFaces over the face limit, SeamError for impossible seams.
UnfoldResult unfold_mesh(const Mesh& mesh, const UnfoldOptions& options, const ProgressFn& progress = {});

}  // namespace foldkit::unfold
