#pragma once
// The dual graph of a mesh (faces joined across interior edges) and its spanning forests. A dual edge
// is identified with its mesh edge: folding a mesh edge keeps the dual edge, cutting it drops it.
#include <limits>
#include <vector>

#include "foldkit/unfold/edge_state.hpp"
#include "foldkit/unfold/mesh.hpp"

namespace foldkit::unfold {

/// The seed's minimum-perimeter weights (§4.1, after [SP05]): w(e) = (l_max - l) / (l_max - l_min),
/// so the longest edges weigh 0 and are folded first and the seams add up to a short total length.
/// Boundary edges get weight 1. All 0 when every edge has the same length.
std::vector<double> min_perimeter_weights(const Mesh& mesh);

/// Roomy-seam weights: the room of edge e is the size s of the largest label, `label_aspect` times as
/// wide as tall, that fits between e and the apex of each of its two triangles (L h / (L + aspect h),
/// L the edge's length, h the height of the triangle above it; the smaller of the two sides),
/// normalised to [0, 1] over the interior edges. Roomy edges weigh most and are cut first, so the
/// seams are long edges beside tall faces and the folds take the short edges and the slivers' edges,
/// where neither a seam label nor a glue tab would fit. Boundary edges get weight 1. All 0 when every
/// edge has the same room.
std::vector<double> roomy_seam_weights(const Mesh& mesh, double label_aspect);

/// Which cuts an unfolder prefers where several trees unfold as well.
enum class SeamPreference : unsigned char {
  Short,  ///< min_perimeter_weights: the shortest total seam length
  Roomy,  ///< roomy_seam_weights: seams with room for a label and a tab beside them
  /// Short seams, but tight ones last: min_perimeter_weights scaled by the edge's room over
  /// `tight_share` of the median room (no more than 1), so that edges with less room fold first.
  Balanced,
};

/// How the unfolders weigh the edges they may cut (UnfoldOptions::cuts).
struct CutOptions {
  /// Short by default for now: Balanced (with SearchOptions::prefer_weighted_ties) measured better on
  /// labels and tabs at 150 mm (docs/unfolding.md, "Seams with room"), but its different parts trip four
  /// layout tests (part letters, guide, label remedy, choose parts) that must be looked at first.
  SeamPreference prefer = SeamPreference::Short;
  /// Roomy, and label_room: the label shape the room is measured for (width over height; "B12" at
  /// 2 mm is about 3).
  double label_aspect = 3;
  /// Balanced: edges with less room than this share of the median room count as tight.
  double tight_share = 1;
  /// The room (edge_label_room, model units) the smallest label printed at the asked scale needs beside
  /// its edge. A seam's two sides each carry a label; cut where a side has less room, the label there
  /// crosses a line, so such edges (tight_edges) are folded before every edge with room on both sides,
  /// whatever `prefer` says, which decides among edges alike. 0 (the scale is not known): no edge is
  /// tight. At large print sizes no edge is: nothing changes.
  double label_room = 0;
  /// Edges at least this long (model units) carry the label of a side without room on that side's glue
  /// tab; 0: labels never sit on tabs.
  double label_tab_length = 0;
};

/// Per edge, the size s of the largest label, `label_aspect` times as wide as tall, that fits between
/// the edge and the apex of each of its two triangles (L h / (L + aspect h), L the edge's length, h the
/// height of the triangle above it; the smaller of the two sides). 0 on boundary edges.
std::vector<double> edge_label_room(const Mesh& mesh, double label_aspect);

/// How well a seam's two labels would fit if an edge were cut, tightest last: cut_weights lowers each
/// step by the whole range of the weights, so tighter edges fold first.
enum class LabelFit : unsigned char {
  BothSides,  ///< both faces have room beside the edge (and every edge when label_room is 0, boundaries)
  OnTab,      ///< one face has; the edge is long enough for the other side's label on its glue tab
  Tight,      ///< a cut there leaves some label without room
};

/// LabelFit of each edge at options.label_room.
std::vector<LabelFit> tight_edges(const Mesh& mesh, const CutOptions& options);

/// The weights `options` asks for: light edges are folded first, heavy ones cut.
std::vector<double> cut_weights(const Mesh& mesh, const CutOptions& options);

/// What an edge must be, whatever an unfolder prefers: the user's --cut and --keep lists and the edges
/// inside flat faces (always folded).
enum class EdgeRule : unsigned char { Free, MustCut, MustFold };

/// One EdgeRule per mesh edge (or none at all: every edge free).
struct EdgeConstraints {
  EdgeMap<EdgeRule> rule;  ///< empty or one per mesh edge
  bool cut(EdgeId e) const { return e.index() < rule.size() && rule[e] == EdgeRule::MustCut; }
  bool fold(EdgeId e) const { return e.index() < rule.size() && rule[e] == EdgeRule::MustFold; }
};

/// Kruskal over the dual edges in increasing weight (ties by edge index, so the result is
/// deterministic): forced folds first, then every interior edge whose weight is below `threshold` and
/// that joins two different trees; every other edge is cut (boundary edges always). With the default
/// threshold this is the minimum spanning forest (one tree per connected component); a lower threshold
/// leaves spanning subtrees (the seed's initial patches).
EdgeStates spanning_forest(const Mesh& mesh, const std::vector<double>& weight,
                           const EdgeConstraints& constraints = {},
                           double threshold = std::numeric_limits<double>::infinity());

/// Number of connected components of the mesh (faces joined across interior edges).
int count_components(const Mesh& mesh);

}  // namespace foldkit::unfold
