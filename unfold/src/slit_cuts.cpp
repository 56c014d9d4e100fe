#include "foldkit/unfold/slit_cuts.hpp"

#include <algorithm>
#include <queue>
#include <tuple>
#include <utility>

#include "foldkit/unfold/dual_graph.hpp"
#include "foldkit/unfold/slits.hpp"

namespace foldkit::unfold {
namespace {

// A side of a cut with fewer faces than this is a scrap the builder must find and match: another cut
// that leaves none is taken first.
constexpr int kScrapFaces = 4;

// The parts as the trees their folds form: each face's parent towards its part's lowest face.
struct FoldForest {
  FaceMap<FaceId> parent;
  FaceMap<EdgeId> parent_edge;  ///< the fold to the parent; invalid at a root
  FaceMap<int> depth;
  FaceMap<FaceId> root;
  FaceMap<int> subtree_faces;  ///< faces at and below the face: what cutting its parent edge parts off
};

FoldForest fold_forest(const Unfolding& u, const EdgeStates& state) {
  const int n = u.num_faces();
  FoldForest t{FaceMap<FaceId>(n, FaceId()), FaceMap<EdgeId>(n, EdgeId()), FaceMap<int>(n, -1),
               FaceMap<FaceId>(n, FaceId()), FaceMap<int>(n, 1)};
  std::vector<FaceId> order;
  order.reserve(static_cast<std::size_t>(n));
  for (FaceId start : all_ids<FaceId>(n)) {
    if (t.depth[start] >= 0) continue;
    t.depth[start] = 0;
    t.root[start] = start;
    std::queue<FaceId> queue;
    queue.push(start);
    while (!queue.empty()) {
      const FaceId f = queue.front();
      queue.pop();
      order.push_back(f);
      for (int e : u.face_edges[f.index()]) {
        const UnfoldEdge& edge = u.edges[e];
        if (edge.boundary() || state[EdgeId(e)] == EdgeState::Cut) continue;
        const FaceId g(edge.face[0] == f.index() ? edge.face[1] : edge.face[0]);
        if (t.depth[g] >= 0) continue;
        t.depth[g] = t.depth[f] + 1;
        t.parent[g] = f;
        t.parent_edge[g] = EdgeId(e);
        t.root[g] = start;
        queue.push(g);
      }
    }
  }
  for (auto f = order.rbegin(); f != order.rend(); ++f)
    if (t.parent_edge[*f].valid()) t.subtree_faces[t.parent[*f]] += t.subtree_faces[*f];
  return t;
}

// Per fold edge, how many of the slits (two faces each) still in one part a cut there would part.
EdgeMap<int> slits_parted(const FoldForest& t, const std::vector<std::pair<FaceId, FaceId>>& slits,
                          int num_edges) {
  EdgeMap<int> parted(num_edges, 0);
  for (auto [f, g] : slits) {
    if (t.root[f] != t.root[g]) continue;
    while (f != g) {
      if (t.depth[f] < t.depth[g]) std::swap(f, g);
      parted[t.parent_edge[f]] += 1;
      f = t.parent[f];
    }
  }
  return parted;
}

// The fold edge to cut next, by the order cut_open_at_slits promises; invalid when no allowed cut parts
// a slit.
EdgeId best_cut(const Unfolding& u, const FoldForest& t, const EdgeMap<int>& parted,
                const EdgeConstraints& kept, const std::vector<LabelFit>& fit) {
  EdgeId best;
  std::tuple<int, int, int, int, double> best_key{};
  for (FaceId child : all_ids<FaceId>(u.num_faces())) {
    const EdgeId e = t.parent_edge[child];
    if (!e.valid() || parted[e] == 0 || kept.fold(e)) continue;
    const int below = t.subtree_faces[child];
    const int smaller_side = std::min(below, t.subtree_faces[t.root[child]] - below);
    const int labels = fit.empty() ? 2 : 2 - static_cast<int>(fit[static_cast<std::size_t>(e.index())]);
    const std::tuple key{std::min(smaller_side, kScrapFaces), parted[e], labels, smaller_side,
                         u.edges[e.index()].length};
    if (!best.valid() || key > best_key) {
      best = e;
      best_key = key;
    }
  }
  return best;
}

}  // namespace

Unfolding cut_open_at_slits(const Mesh& mesh, const Unfolding& parts, const PartOptions& options) {
  if (!(options.slit_gap_mm > 0) || !(options.mm_per_unit > 0)) return parts;
  const std::vector<std::vector<int>> partners =
      narrow_seam_partners(parts, options.slit_gap_mm / options.mm_per_unit);
  const auto opened = [&](int f) {
    return options.also_split.empty() ||
           std::binary_search(options.also_split.begin(), options.also_split.end(), parts.piece_of_face[f]);
  };
  std::vector<std::pair<FaceId, FaceId>> slits;
  for (int f = 0; f < parts.num_faces(); ++f)
    for (int g : partners[f])
      if (f < g && opened(f)) slits.emplace_back(FaceId(f), FaceId(g));
  if (slits.empty()) return parts;
  const EdgeConstraints kept = move_constraints(parts, options.constraints);
  const std::vector<LabelFit> fit = tight_edges(mesh, options.cuts);
  EdgeStates state = edge_states(parts);
  bool cut = false;
  for (;;) {
    const FoldForest forest = fold_forest(parts, state);
    const EdgeId e =
        best_cut(parts, forest, slits_parted(forest, slits, static_cast<int>(parts.edges.size())), kept, fit);
    if (!e.valid()) break;
    state[e] = EdgeState::Cut;
    cut = true;
  }
  return cut ? flatten_like(mesh, state, parts) : parts;
}

}  // namespace foldkit::unfold
