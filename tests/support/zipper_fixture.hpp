#pragma once
// Two 30 x 10 mm pieces zipped together along three 10 mm seams: the bottom of piece 0 (outline edges
// 0, 1, 2, left to right) is glued to the top of piece 1 (edges 4, 3, 2). sides[0] of every seam is on
// piece 0, so a tab plan that ignored alternation would put all three tabs there, side by side.
#include <vector>

#include "foldkit/layout/outline.hpp"

namespace foldkit::test {

struct Zipper {
  std::vector<layout::ScaledPiece> pieces;
  std::vector<layout::Seam> seams;
};

inline Zipper two_pieces_zipped_along_three_seams() {
  auto piece = [](int index, std::vector<Vec2> corners) {
    layout::ScaledPiece p;
    p.index = index;
    p.faces = {2 * index, 2 * index + 1};
    p.triangles_mm = {Triangle2{Vec2{0, 0}, Vec2{30, 0}, Vec2{30, 10}},
                      Triangle2{Vec2{0, 0}, Vec2{30, 10}, Vec2{0, 10}}};
    layout::OutlineLoop loop;
    for (std::size_t i = 0; i < corners.size(); ++i)
      loop.push_back({static_cast<int>(loop.size()), -1, -1, corners[i], corners[(i + 1) % corners.size()]});
    p.outline_mm = {loop};
    p.area_mm2 = 300;
    return p;
  };
  Zipper z;
  z.pieces.push_back(piece(0, {{0, 0}, {10, 0}, {20, 0}, {30, 0}, {30, 10}, {0, 10}}));
  z.pieces.push_back(piece(1, {{0, 0}, {30, 0}, {30, 10}, {20, 10}, {10, 10}, {0, 10}}));
  for (int k = 0; k < 3; ++k) {
    layout::Seam seam;
    seam.edge = k;
    seam.sides = {layout::SeamSide{0, 0, k}, layout::SeamSide{1, 0, 4 - k}};
    z.seams.push_back(seam);
  }
  return z;
}

}  // namespace foldkit::test
