#include "foldkit/unfold/rearrange.hpp"

#include "foldkit/unfold/decompose.hpp"

namespace foldkit::unfold {

bool rearrange_pieces(CutTree& tree, int components, const EdgeConstraints& constraints, int max_operations) {
  const Mesh& m = tree.mesh();
  const auto& w = tree.context().weight;
  // Edges cut on entry count as visited: the cuts that undo an overlap must be new ones, or the walk
  // would only reopen the seams it just closed.
  EdgeMap<char> visited(m.num_edges(), 0);
  for (EdgeId e : all_ids<EdgeId>(m.num_edges()))
    visited[e] = tree.folded(e) ? 0 : 1;
  int ops = 0;
  while (tree.piece_count() > components && ops < max_operations) {
    EdgeId join;
    for (EdgeId e : all_ids<EdgeId>(m.num_edges())) {
      const auto& me = m.edge(e);
      if (me.boundary() || tree.folded(e) || constraints.cut(e)) continue;
      if (tree.piece(me.face_id(0)) == tree.piece(me.face_id(1))) continue;
      if (!join.valid() || w[e.index()] < w[join.index()]) join = e;
    }
    if (!join.valid()) break;  // forced cuts separate the remaining pieces
    tree.stitch(join);
    ++ops;
    while (tree.overlap_count() > 0 && ops < max_operations) {
      const FaceId f(tree.overlapping_faces().front());
      const FaceId g(tree.overlap_partners(f.index()).front());
      EdgeId best;
      bool best_visited = true;
      for (EdgeId e : tree.path(f, g)) {
        if (constraints.fold(e)) continue;
        bool v = visited[e] != 0;
        // Unvisited edges first, the heaviest (shortest) among them; a visited one only if no other.
        if (!best.valid() || (best_visited && !v) || (v == best_visited && w[e.index()] > w[best.index()])) {
          best = e;
          best_visited = v;
        }
      }
      if (!best.valid()) break;
      tree.cut(best);
      visited[best] = 1;
      ++ops;
    }
  }
  cut_overlaps(tree, constraints);
  return tree.piece_count() <= components;
}

}  // namespace foldkit::unfold
