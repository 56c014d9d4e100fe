#include "foldkit/unfold/slits.hpp"

#include <algorithm>
#include <limits>

namespace foldkit::unfold {
namespace {

Vec2 corner_of(const CutTree& tree, int f, int v) {
  const auto& face = tree.mesh().faces[f];
  const Triangle2& t = tree.flat(FaceId(f));
  for (int i = 0; i < 3; ++i)
    if (face[i] == v) return t[i];
  return t[0];
}

}  // namespace

double seam_gap_per_length(const CutTree& tree, EdgeId e, FaceId moved, const RigidMotion& motion) {
  const auto& edge = tree.mesh().edge(e);
  if (edge.boundary()) return std::numeric_limits<double>::infinity();
  const int m = moved.index(), other = edge.face[0] == m ? edge.face[1] : edge.face[0];
  const auto& v = edge.v;
  const Vec2 a0 = motion(corner_of(tree, m, v[0])), a1 = motion(corner_of(tree, m, v[1]));
  const Vec2 b0 = corner_of(tree, other, v[0]), b1 = corner_of(tree, other, v[1]);
  const double length = norm(b1 - b0);
  if (length <= 0) return std::numeric_limits<double>::infinity();
  return std::max(norm(a0 - b0), norm(a1 - b1)) / length;
}

double seam_gap_per_length(const CutTree& tree, EdgeId e) {
  const auto& edge = tree.mesh().edge(e);
  if (edge.boundary() || tree.folded(e) || tree.piece(edge.face_id(0)) != tree.piece(edge.face_id(1)))
    return std::numeric_limits<double>::infinity();
  return seam_gap_per_length(tree, e, edge.face_id(0), RigidMotion{});
}

std::vector<std::vector<int>> narrow_seam_partners(const Unfolding& u, double gap) {
  std::vector<std::vector<int>> partners(static_cast<std::size_t>(u.num_faces()));
  if (!(gap > 0)) return partners;
  for (const UnfoldEdge& e : u.edges) {
    if (!e.glued_seam() || u.piece_of_face[e.face[0]] != u.piece_of_face[e.face[1]]) continue;
    const Triangle2& a = u.flat[e.face[0]];
    const Triangle2& b = u.flat[e.face[1]];
    // Each face runs the edge from its corner to the next one, the two faces in opposite directions.
    const int ca = e.corner[0], cb = e.corner[1];
    if (norm(a[ca] - b[(cb + 1) % 3]) < gap && norm(a[(ca + 1) % 3] - b[cb]) < gap) {
      partners[e.face[0]].push_back(e.face[1]);
      partners[e.face[1]].push_back(e.face[0]);
    }
  }
  return partners;
}

int count_slits(const CutTree& tree, double min_gap_per_length) {
  int n = 0;
  for (EdgeId e : all_ids<EdgeId>(tree.mesh().num_edges()))
    n += seam_gap_per_length(tree, e) < min_gap_per_length;
  return n;
}

double slit_cost(double gap_per_length, double min_gap_per_length) {
  return gap_per_length < min_gap_per_length ? 2 - gap_per_length / min_gap_per_length : 0;
}

}  // namespace foldkit::unfold
