#include "foldkit/unfold/rearrange.hpp"

#include "foldkit/unfold/decompose.hpp"

namespace foldkit::unfold {

bool rearrange_pieces(CutTree& tree, int components, const EdgeConstraints& constraints, int max_operations) {
  const Mesh& m = tree.mesh();
  const auto& w = tree.context().weight;
  // Edges cut on entry count as visited: the cuts that undo an overlap must be new ones, or the walk
  // would only reopen the seams it just closed.
  std::vector<char> visited(m.num_edges(), 0);
  for (int e = 0; e < m.num_edges(); ++e)
    visited[e] = tree.folded(e) ? 0 : 1;
  int ops = 0;
  while (tree.piece_count() > components && ops < max_operations) {
    int join = -1;
    for (int e = 0; e < m.num_edges(); ++e) {
      const auto& me = m.edges[e];
      if (me.boundary() || tree.folded(e) || constraints.cut(e)) continue;
      if (tree.piece(me.face[0]) == tree.piece(me.face[1])) continue;
      if (join < 0 || w[e] < w[join]) join = e;
    }
    if (join < 0) break;  // forced cuts separate the remaining pieces
    tree.stitch(join);
    ++ops;
    while (tree.overlap_count() > 0 && ops < max_operations) {
      int f = tree.overlapping_faces().front();
      int g = tree.overlap_partners(f).front();
      int best = -1;
      bool best_visited = true;
      for (int e : tree.path(f, g)) {
        if (constraints.fold(e)) continue;
        bool v = visited[e] != 0;
        // Unvisited edges first, the heaviest (shortest) among them; a visited one only if no other.
        if (best < 0 || (best_visited && !v) || (v == best_visited && w[e] > w[best])) {
          best = e;
          best_visited = v;
        }
      }
      if (best < 0) break;
      tree.cut(best);
      visited[best] = 1;
      ++ops;
    }
  }
  cut_overlaps(tree, constraints);
  return tree.piece_count() <= components;
}

}  // namespace foldkit::unfold
