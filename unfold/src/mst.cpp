#include "foldkit/unfold/mst.hpp"

#include <algorithm>
#include <queue>
#include <string>

#include "foldkit/error.hpp"
#include "foldkit/unfold/overlap.hpp"

namespace foldkit::unfold {

FoldForest fold_forest(const Mesh& mesh, const EdgeStates& state) {
  const int nf = mesh.num_faces();
  FoldForest forest{std::vector<int>(nf, -1), std::vector<int>(nf, -1), std::vector<int>(nf, -1)};
  std::queue<int> queue;
  for (int root = 0; root < nf; ++root) {
    if (forest.depth[root] >= 0) continue;
    forest.depth[root] = 0;
    queue.push(root);
    while (!queue.empty()) {
      int f = queue.front();
      queue.pop();
      for (int i = 0; i < 3; ++i) {
        int e = mesh.face_edges[f][i];
        const MeshEdge& me = mesh.edges[e];
        if (me.boundary() || state[EdgeId(e)] == EdgeState::Cut || e == forest.parent_edge[f]) continue;
        int g = me.face[0] == f ? me.face[1] : me.face[0];
        if (forest.depth[g] >= 0) continue;
        forest.depth[g] = forest.depth[f] + 1;
        forest.parent_face[g] = f;
        forest.parent_edge[g] = e;
        queue.push(g);
      }
    }
  }
  return forest;
}

std::vector<EdgeId> fold_path(const FoldForest& forest, int a, int b) {
  std::vector<EdgeId> from_a, from_b;
  while (forest.depth[a] > forest.depth[b]) {
    from_a.emplace_back(forest.parent_edge[a]);
    a = forest.parent_face[a];
  }
  while (forest.depth[b] > forest.depth[a]) {
    from_b.emplace_back(forest.parent_edge[b]);
    b = forest.parent_face[b];
  }
  while (a != b) {
    if (forest.parent_face[a] < 0 || forest.parent_face[b] < 0) return {};
    from_a.emplace_back(forest.parent_edge[a]);
    a = forest.parent_face[a];
    from_b.emplace_back(forest.parent_edge[b]);
    b = forest.parent_face[b];
  }
  from_a.insert(from_a.end(), from_b.rbegin(), from_b.rend());
  return from_a;
}

Unfolding cut_until_no_overlap(const Mesh& mesh, EdgeStates& state, const std::vector<double>& weight,
                               const EdgeConstraints& constraints) {
  // Each round cuts at least one fold edge, so this ends after at most (faces - 1) rounds.
  for (;;) {
    Unfolding u = flatten(mesh, state);
    // flatten may have cut cycle-closing edges; keep `state` in step with what was laid flat.
    state = edge_states(u);
    std::vector<FacePair> pairs = overlapping_pairs(u.flat, u.piece_of_face);
    if (pairs.empty()) return u;
    FoldForest forest = fold_forest(mesh, state);
    EdgeMap<char> cut_this_round(mesh.num_edges(), 0);
    bool progress = false;
    for (const FacePair& pair : pairs) {
      std::vector<EdgeId> path = fold_path(forest, pair.a, pair.b);
      if (std::any_of(path.begin(), path.end(), [&](EdgeId e) { return cut_this_round[e] != 0; })) continue;
      // Prefer the middle of the path (both sides keep a fair share of faces), then the edge of largest
      // weight there, the cut the weights prefer (the shortest, or the roomiest).
      const std::size_t n = path.size();
      EdgeId best;
      for (int pass = 0; pass < 2 && !best.valid(); ++pass) {
        std::size_t lo = pass == 0 ? n / 4 : 0, hi = pass == 0 ? n - n / 4 : n;
        for (std::size_t k = lo; k < hi; ++k) {
          const EdgeId e = path[k];
          if (constraints.fold(e)) continue;
          if (!best.valid() || weight[e.index()] > weight[best.index()]) best = e;
        }
      }
      if (!best.valid())
        throw Error("the edges kept folded make faces " + std::to_string(pair.a) + " and " +
                        std::to_string(pair.b) + " overlap in the plane: keep fewer edges",
                    ExitCode::Usage);
      state[best] = EdgeState::Cut;
      cut_this_round[best] = 1;
      progress = true;
    }
    if (!progress) return u;  // unreachable: the first pair of a round always gets a cut
  }
}

Unfolding unfold_mst(const Mesh& mesh, const EdgeConstraints& constraints, const CutOptions& cuts) {
  std::vector<double> weight = cut_weights(mesh, cuts);
  EdgeStates state = spanning_forest(mesh, weight, constraints);
  return cut_until_no_overlap(mesh, state, weight, constraints);
}

}  // namespace foldkit::unfold
