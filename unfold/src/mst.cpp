#include "foldkit/unfold/mst.hpp"

#include <algorithm>
#include <queue>
#include <string>

#include "foldkit/error.hpp"
#include "foldkit/unfold/overlap.hpp"

namespace foldkit::unfold {

FoldForest fold_forest(const Mesh& mesh, const std::vector<char>& cut) {
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
        if (me.boundary() || cut[e] || e == forest.parent_edge[f]) continue;
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

std::vector<int> fold_path(const FoldForest& forest, int a, int b) {
  std::vector<int> from_a, from_b;
  while (forest.depth[a] > forest.depth[b]) {
    from_a.push_back(forest.parent_edge[a]);
    a = forest.parent_face[a];
  }
  while (forest.depth[b] > forest.depth[a]) {
    from_b.push_back(forest.parent_edge[b]);
    b = forest.parent_face[b];
  }
  while (a != b) {
    if (forest.parent_face[a] < 0 || forest.parent_face[b] < 0) return {};
    from_a.push_back(forest.parent_edge[a]);
    a = forest.parent_face[a];
    from_b.push_back(forest.parent_edge[b]);
    b = forest.parent_face[b];
  }
  from_a.insert(from_a.end(), from_b.rbegin(), from_b.rend());
  return from_a;
}

Unfolding cut_until_no_overlap(const Mesh& mesh, std::vector<char>& cut, const std::vector<double>& weight,
                               const EdgeConstraints& constraints) {
  // Each round cuts at least one fold edge, so this ends after at most (faces - 1) rounds.
  for (;;) {
    Unfolding u = flatten(mesh, cut);
    // flatten may have cut cycle-closing edges; keep `cut` in step with what was laid flat.
    for (int e = 0; e < mesh.num_edges(); ++e)
      cut[e] = u.edges[e].cut ? 1 : 0;
    std::vector<FacePair> pairs = overlapping_pairs(u.flat, u.piece_of_face);
    if (pairs.empty()) return u;
    FoldForest forest = fold_forest(mesh, cut);
    std::vector<char> cut_this_round(mesh.num_edges(), 0);
    bool progress = false;
    for (const FacePair& pair : pairs) {
      std::vector<int> path = fold_path(forest, pair.a, pair.b);
      if (std::any_of(path.begin(), path.end(), [&](int e) { return cut_this_round[e] != 0; })) continue;
      // Prefer the middle of the path (both sides keep a fair share of faces), then the shortest edge
      // there (largest minimum-perimeter weight), so seams stay short.
      const std::size_t n = path.size();
      int best = -1;
      for (int pass = 0; pass < 2 && best < 0; ++pass) {
        std::size_t lo = pass == 0 ? n / 4 : 0, hi = pass == 0 ? n - n / 4 : n;
        for (std::size_t k = lo; k < hi; ++k) {
          int e = path[k];
          if (constraints.fold(e)) continue;
          if (best < 0 || weight[e] > weight[best]) best = e;
        }
      }
      if (best < 0)
        throw Error("the edges kept by --keep make faces " + std::to_string(pair.a) + " and " +
                        std::to_string(pair.b) + " overlap in the plane: keep fewer edges",
                    ExitCode::Usage);
      cut[best] = 1;
      cut_this_round[best] = 1;
      progress = true;
    }
    if (!progress) return u;  // unreachable: the first pair of a round always gets a cut
  }
}

Unfolding unfold_mst(const Mesh& mesh, const EdgeConstraints& constraints) {
  std::vector<double> weight = min_perimeter_weights(mesh);
  std::vector<char> cut = spanning_forest_cuts(mesh, weight, constraints);
  return cut_until_no_overlap(mesh, cut, weight, constraints);
}

}  // namespace foldkit::unfold
