#include "foldkit/layout/outline.hpp"

#include <unordered_map>

namespace foldkit::layout {
namespace {

bool is_outline_side(const unfold::Unfolding& u, const std::vector<char>& in_piece, int face, int corner) {
  const unfold::UnfoldEdge& e = u.edges[u.face_edges[face][corner]];
  if (e.cut || e.boundary()) return true;
  // A fold into another piece would break the Unfolding invariants; treating it as outline keeps the
  // drawing closed instead of looping forever.
  const int other = e.face[0] == face ? e.face[1] : e.face[0];
  return !in_piece[other];
}

}  // namespace

std::vector<OutlineLoop> piece_outline(const unfold::Unfolding& u, std::span<const int> faces) {
  std::vector<char> in_piece(u.num_faces(), 0);
  for (int f : faces)
    in_piece[f] = 1;

  // Half-edges are (face, corner) pairs, keyed face * 3 + corner.
  std::vector<int> sides;
  for (int f : faces)
    for (int c = 0; c < 3; ++c)
      if (is_outline_side(u, in_piece, f, c)) sides.push_back(f * 3 + c);

  // The outline side after (f, c) leaves the end vertex of (f, c): turn around that vertex through the
  // piece's fold edges until an outline side appears.
  auto next_side = [&](int key) {
    int f = key / 3, c = (key % 3 + 1) % 3;
    for (int guard = 0; guard < 4 * u.num_faces() + 8; ++guard) {
      if (is_outline_side(u, in_piece, f, c)) return f * 3 + c;
      const unfold::UnfoldEdge& e = u.edges[u.face_edges[f][c]];
      const int k = e.face[0] == f ? 1 : 0;
      // In the neighbour the edge runs the other way, so our vertex is its corner + 1.
      f = e.face[k];
      c = (e.corner[k] + 1) % 3;
    }
    return -1;
  };

  std::unordered_map<int, char> visited;
  visited.reserve(sides.size() * 2);
  std::vector<OutlineLoop> loops;
  for (int start : sides) {
    if (visited[start]) continue;
    OutlineLoop loop;
    for (int key = start; key >= 0 && !visited[key]; key = next_side(key)) {
      visited[key] = 1;
      const int f = key / 3, c = key % 3;
      loop.push_back({u.face_edges[f][c], f, c, u.flat[f][c], u.flat[f][(c + 1) % 3]});
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

std::vector<ScaledPiece> scaled_pieces(const unfold::Unfolding& u, double scale) {
  std::vector<std::vector<int>> faces_of(u.piece_count);
  for (int f = 0; f < u.num_faces(); ++f)
    faces_of[u.piece_of_face[f]].push_back(f);
  std::vector<ScaledPiece> pieces(u.piece_count);
  for (int p = 0; p < u.piece_count; ++p) {
    ScaledPiece& piece = pieces[p];
    piece.index = p;
    piece.faces = std::move(faces_of[p]);
    for (int f : piece.faces) {
      Triangle2 t = u.flat[f];
      for (Vec2& v : t)
        v = v * scale;
      piece.triangles_mm.push_back(t);
      piece.area_mm2 += signed_area(t);
    }
    piece.outline_mm = piece_outline(u, piece.faces);
    for (OutlineLoop& loop : piece.outline_mm)
      for (OutlineEdge& e : loop) {
        e.a = e.a * scale;
        e.b = e.b * scale;
      }
  }
  return pieces;
}

std::vector<Seam> find_seams(const unfold::Unfolding& u, std::span<const ScaledPiece> pieces) {
  std::vector<Seam> seams;
  std::vector<int> seam_of_edge(u.edges.size(), -1);
  for (std::size_t e = 0; e < u.edges.size(); ++e) {
    if (!u.edges[e].glued_seam()) continue;
    seam_of_edge[e] = static_cast<int>(seams.size());
    seams.push_back({static_cast<int>(e), u.edges[e].fold_angle, {}});
  }
  for (const ScaledPiece& piece : pieces)
    for (std::size_t l = 0; l < piece.outline_mm.size(); ++l)
      for (std::size_t i = 0; i < piece.outline_mm[l].size(); ++i) {
        const OutlineEdge& side = piece.outline_mm[l][i];
        const int s = seam_of_edge[side.edge];
        if (s < 0) continue;
        const unfold::UnfoldEdge& edge = u.edges[side.edge];
        const int k = edge.face[0] == side.face && edge.corner[0] == side.corner ? 0 : 1;
        seams[s].sides[k] = {piece.index, static_cast<int>(l), static_cast<int>(i)};
      }
  return seams;
}

}  // namespace foldkit::layout
