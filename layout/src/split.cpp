#include "foldkit/layout/split.hpp"

#include <deque>

#include "foldkit/layout/polygon.hpp"
#include "foldkit/layout/scale.hpp"

namespace foldkit::layout {
namespace {

// Corner points of a set of faces, in model units; only hull points matter for the fit test, so the
// set is kept as a hull that grows face by face.
bool fits(const std::vector<Vec2>& hull, const Triangle2& extra, double scale, Vec2 room) {
  std::vector<Vec2> points = hull;
  points.insert(points.end(), extra.begin(), extra.end());
  return max_fit_scale(points, room) >= scale;
}

}  // namespace

SplitResult split_to_fit(const unfold::Mesh& mesh, const unfold::Unfolding& u, const LayoutOptions& o) {
  SplitResult result{u, 0, 0};
  if (!o.size_mm || o.fit || !(u.model_extent > 0)) return result;
  const double scale = *o.size_mm / u.model_extent;
  const Vec2 room = piece_room_mm(o);
  const auto pieces = u.piece_faces();

  std::vector<char> cut(u.edges.size(), 0);
  for (std::size_t e = 0; e < u.edges.size(); ++e)
    cut[e] = u.edges[e].cut ? 1 : 0;
  bool changed = false;
  std::vector<int> part(u.num_faces(), -1);
  for (const std::vector<int>& faces : pieces) {
    std::vector<Vec2> all;
    for (int f : faces)
      all.insert(all.end(), u.flat[f].begin(), u.flat[f].end());
    if (max_fit_scale(all, room) >= scale) continue;
    result.split_pieces += 1;
    // Grow parts breadth-first over folds; a face that would make its part too large starts a later part.
    int parts = 0;
    for (int seed : faces) {
      if (part[seed] >= 0) continue;
      const int id = parts++;
      std::vector<Vec2> hull;
      std::deque<int> queue{seed};
      part[seed] = id;
      hull = convex_hull({u.flat[seed].begin(), u.flat[seed].end()});
      while (!queue.empty()) {
        const int f = queue.front();
        queue.pop_front();
        for (int c = 0; c < 3; ++c) {
          const int e = u.face_edges[f][c];
          const unfold::UnfoldEdge& edge = u.edges[e];
          if (edge.cut || edge.boundary()) continue;
          const int g = edge.face[0] == f ? edge.face[1] : edge.face[0];
          if (part[g] >= 0) continue;
          if (!fits(hull, u.flat[g], scale, room)) continue;
          part[g] = id;
          std::vector<Vec2> grown = hull;
          grown.insert(grown.end(), u.flat[g].begin(), u.flat[g].end());
          hull = convex_hull(std::move(grown));
          queue.push_back(g);
        }
      }
    }
    result.new_pieces += parts;
    for (int f : faces)
      for (int c = 0; c < 3; ++c) {
        const int e = u.face_edges[f][c];
        const unfold::UnfoldEdge& edge = u.edges[e];
        if (edge.cut || edge.boundary()) continue;
        if (part[edge.face[0]] != part[edge.face[1]]) {
          cut[e] = 1;
          changed = true;
        }
      }
  }
  if (changed) result.unfolding = unfold::flatten(mesh, cut);
  return result;
}

}  // namespace foldkit::layout
