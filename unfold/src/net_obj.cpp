// The flat net as OBJ: corners joined through folds become one vertex, polygons are written whole.
#include "foldkit/unfold/net_obj.hpp"

#include <algorithm>
#include <map>
#include <vector>

#include "foldkit/unfold/disjoint_sets.hpp"

namespace foldkit::unfold {
namespace {

// One OBJ vertex per group of flat corners joined through folds: corners of one mesh vertex in one
// piece share a vertex where the piece is folded there, and no vertex is shared between pieces.
std::vector<int> net_vertices(const Unfolding& u) {
  const int nf = u.num_faces();
  DisjointSets corners(nf * 3);
  for (const UnfoldEdge& e : u.edges) {
    if (e.cut) continue;
    // Face 0 runs corner i -> i+1; face 1 runs the other way, so its corner j+1 meets face 0's corner i.
    int f = e.face[0], g = e.face[1], i = e.corner[0], j = e.corner[1];
    corners.join(f * 3 + i, g * 3 + (j + 1) % 3);
    corners.join(f * 3 + (i + 1) % 3, g * 3 + j);
  }
  std::vector<int> root(static_cast<std::size_t>(nf) * 3);
  for (int c = 0; c < nf * 3; ++c)
    root[c] = corners.find(c);
  return root;
}

// The outline of one input polygon: its triangles' corners (as net vertex ids) around the loop of
// edges that no two of its triangles share. Empty when a cut runs between its triangles (possible only
// for a polygon that is not planar; its triangles then go out one by one).
std::vector<int> polygon_loop(const Unfolding& u, const std::vector<int>& vertex,
                              const std::vector<int>& faces) {
  if (faces.size() == 1) return {vertex[faces[0] * 3], vertex[faces[0] * 3 + 1], vertex[faces[0] * 3 + 2]};
  std::map<int, int> next;
  for (int f : faces)
    for (int c = 0; c < 3; ++c) {
      const UnfoldEdge& e = u.edges[u.face_edges[f][c]];
      const int other = e.face[0] == f ? e.face[1] : e.face[0];
      const bool inside = !e.cut && std::find(faces.begin(), faces.end(), other) != faces.end();
      if (inside) continue;
      if (!next.emplace(vertex[f * 3 + c], vertex[f * 3 + (c + 1) % 3]).second) return {};
    }
  std::vector<int> loop{next.begin()->first};
  while (loop.size() <= next.size()) {
    auto it = next.find(loop.back());
    if (it == next.end()) return {};
    if (it->second == loop.front()) break;
    loop.push_back(it->second);
  }
  if (loop.size() != next.size()) return {};
  return loop;
}

}  // namespace

// Face k of the net is face k of the input file; only a non-planar polygon that the unfolding cut
// apart is written as its triangles (said in the header).
void write_net_obj(std::ostream& out, const Mesh& mesh, const Unfolding& u) {
  const int nf = u.num_faces();
  const std::vector<int> vertex = net_vertices(u);
  int polygons = 0;
  for (int f = 0; f < nf; ++f)
    polygons = std::max(polygons, mesh.polygon_of(f) + 1);
  std::vector<std::vector<int>> faces_of(polygons);
  for (int f = 0; f < nf; ++f)
    faces_of[mesh.polygon_of(f)].push_back(f);
  std::vector<std::vector<int>> loops;
  int folded = 0;
  for (const auto& faces : faces_of) {
    if (faces.empty()) continue;
    std::vector<int> loop = polygon_loop(u, vertex, faces);
    if (!loop.empty()) {
      loops.push_back(std::move(loop));
      continue;
    }
    ++folded;
    for (int f : faces)
      loops.push_back({vertex[f * 3], vertex[f * 3 + 1], vertex[f * 3 + 2]});
  }
  std::vector<int> index(vertex.size(), -1);
  int next = 1;
  out << "# foldkit flat net of " << mesh.name << ": " << loops.size() << " faces, " << u.piece_count
      << " pieces\n";
  if (folded > 0)
    out << "# " << folded
        << " non-planar input face(s) cut apart and written as their triangles: later faces shift\n";
  out.precision(17);
  for (const auto& loop : loops)
    for (int r : loop) {
      if (index[r] >= 0) continue;
      index[r] = next++;
      const Vec2 p = u.flat[r / 3][r % 3];
      out << "v " << p.x << ' ' << p.y << " 0\n";
    }
  int current = -1;
  for (const auto& loop : loops) {
    const int piece = u.piece_of_face[loop.front() / 3];
    if (piece != current) {
      current = piece;
      out << "g piece_" << current << "\n";
    }
    out << "f";
    for (int r : loop)
      out << ' ' << index[r];
    out << "\n";
  }
}

}  // namespace foldkit::unfold
