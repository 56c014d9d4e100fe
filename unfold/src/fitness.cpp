// Rm packs the pieces' bounding boxes on shelves (tallest first, shelf width fixed at about the
// square root of their total area); the seed used an approximate bin packing [IC01] for the same
// purpose. Rb walks each piece's outline as a loop of cut half-edges around the flat piece.
#include "foldkit/unfold/fitness.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace foldkit::unfold {

namespace {

double margin_ratio(const CutTree& tree) {
  std::map<int, Box2> boxes;
  double area = 0;
  for (FaceId f : all_ids<FaceId>(tree.num_faces())) {
    const Triangle2& t = tree.flat(f);
    area += signed_area(t);
    Box2& b = boxes[tree.piece(f)];
    for (Vec2 p : t)
      b.add(p);
  }
  std::vector<Box2> list;
  double box_area = 0, widest = 0;
  for (auto& [p, b] : boxes) {
    list.push_back(b);
    box_area += b.width() * b.height();
    widest = std::max(widest, b.width());
  }
  std::sort(list.begin(), list.end(), [](const Box2& a, const Box2& b) { return a.height() > b.height(); });
  const double shelf_width = std::max(widest, std::sqrt(box_area));
  double x = 0, y = 0, shelf = 0, used_width = 0;
  for (const Box2& b : list) {
    if (x > 0 && x + b.width() > shelf_width) {
      y += shelf;
      x = 0;
      shelf = 0;
    }
    x += b.width();
    used_width = std::max(used_width, x);
    shelf = std::max(shelf, b.height());
  }
  const double sheet = used_width * (y + shelf);
  return sheet > 0 ? std::clamp(1.0 - area / sheet, 0.0, 1.0) : 0.0;
}

double boundary_distance_ratio(const CutTree& tree) {
  const Mesh& m = tree.mesh();
  const int nf = m.num_faces();
  // Half-edge (f, i): corner i of face f, the edge faces[f][i] -> faces[f][i+1]. On the outline when cut.
  auto is_cut = [&](int f, int i) { return !tree.folded(m.edges_of(FaceId(f))[i]); };
  std::vector<int> loop_of(3 * nf, -1), pos(3 * nf, -1);
  std::vector<int> loop_len;
  for (int f0 = 0; f0 < nf; ++f0) {
    for (int i0 = 0; i0 < 3; ++i0) {
      if (!is_cut(f0, i0) || loop_of[3 * f0 + i0] >= 0) continue;
      const int id = static_cast<int>(loop_len.size());
      int f = f0, i = i0, n = 0;
      // Follow the outline: from the end vertex of this half-edge, turn through fold edges until the
      // next cut half-edge leaving that vertex.
      while (loop_of[3 * f + i] < 0) {
        loop_of[3 * f + i] = id;
        pos[3 * f + i] = n++;
        int j = (i + 1) % 3;
        int guard = 0;
        while (!is_cut(f, j) && guard++ < 64) {
          int e = m.face_edges[f][j];
          int g = tree.across(EdgeId(e), FaceId(f)).index();
          int k = 0;
          while (m.face_edges[g][k] != e)
            ++k;
          f = g;
          j = (k + 1) % 3;
        }
        i = j;
        if (guard >= 64) break;
      }
      loop_len.push_back(n);
    }
  }
  double total = 0;
  for (int n : loop_len)
    total += n;
  if (total == 0) return 0;
  double sum = 0;
  int seams = 0;
  for (EdgeId e : all_ids<EdgeId>(m.num_edges())) {
    const auto& me = m.edge(e);
    if (me.boundary() || tree.folded(e)) continue;
    int h0 = 3 * me.face[0] + me.corner[0], h1 = 3 * me.face[1] + me.corner[1];
    ++seams;
    if (loop_of[h0] != loop_of[h1] || loop_of[h0] < 0) {
      sum += 0.5 * total;
      continue;
    }
    int len = loop_len[loop_of[h0]];
    int d = std::abs(pos[h0] - pos[h1]);
    sum += std::min(d, len - d);
  }
  return seams > 0 ? std::clamp(sum / seams / total, 0.0, 1.0) : 0.0;
}

}  // namespace

FitnessTerms fitness_terms(const CutTree& tree) {
  FitnessTerms t;
  t.pieces = tree.piece_count();
  int largest = 0;
  std::map<int, int> sizes;
  for (FaceId f : all_ids<FaceId>(tree.num_faces()))
    largest = std::max(largest, ++sizes[tree.piece(f)]);
  t.rl = tree.num_faces() > 0 ? 1.0 - static_cast<double>(largest) / tree.num_faces() : 0.0;
  t.rm = margin_ratio(tree);
  t.rb = boundary_distance_ratio(tree);
  return t;
}

}  // namespace foldkit::unfold
