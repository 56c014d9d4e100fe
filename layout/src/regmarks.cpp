#include "foldkit/layout/regmarks.hpp"

namespace foldkit::layout {

std::vector<Path> regmark_paths(Vec2 paper, const RegMarkOptions& o) {
  const double in = o.inset_mm, s = o.square_mm, a = o.arm_mm;
  // Bracket strokes are centred half a stroke inside the mark's outer edge, so the printed ink ends
  // exactly at the inset the cutter expects.
  const double h = 0.5 * o.stroke_mm;
  std::vector<Path> out;
  Path square{PathRole::RegMark, {{in, in}, {in + s, in}, {in + s, in + s}, {in, in + s}}, true, -1, true};
  out.push_back(square);
  const double right = paper.x - in - h, top = in + h;
  out.push_back(
      {PathRole::RegMark, {{right - a + h, top}, {right, top}, {right, top + a - h}}, false, -1, false});
  const double left = in + h, bottom = paper.y - in - h;
  out.push_back({PathRole::RegMark,
                 {{left, bottom - a + h}, {left, bottom}, {left + a - h, bottom}},
                 false,
                 -1,
                 false});
  return out;
}

std::vector<Box2> regmark_keep_out(Vec2 paper, const RegMarkOptions& o) {
  const double in = o.inset_mm, c = o.clearance_mm;
  return {
      Box2{{in - c, in - c}, {in + o.square_mm + c, in + o.square_mm + c}},
      Box2{{paper.x - in - o.arm_mm - c, in - c}, {paper.x - in + c, in + o.arm_mm + c}},
      Box2{{in - c, paper.y - in - o.arm_mm - c}, {in + o.arm_mm + c, paper.y - in + c}},
  };
}

Box2 regmark_cut_area(Vec2 paper, const RegMarkOptions& o) {
  return Box2{{o.inset_mm, o.inset_mm}, {paper.x - o.inset_mm, paper.y - o.inset_mm}};
}

}  // namespace foldkit::layout
