#pragma once
// Hand-made sheets for the device tests: small, exact, and covering every role a cutter handles.
#include <cmath>
#include <vector>

#include "foldkit/sheet/sheet.hpp"

namespace foldkit::test {

/// A closed axis-aligned rectangle path.
inline Path rect_path(PathRole role, Vec2 min, Vec2 max, int piece = -1) {
  return {role, {min, {max.x, min.y}, max, {min.x, max.y}}, true, piece, false};
}

/// An open two-point path.
inline Path line_path(PathRole role, Vec2 a, Vec2 b, int piece = -1) {
  return {role, {a, b}, false, piece, false};
}

/// Two pieces side by side at `origin`, each w x h mm with a mountain and a valley fold inside, a square
/// hole in the first, a label text and a label path: every role a cutter handles, inside (origin,
/// origin + (2w + 10, h)).
inline Sheet two_piece_sheet(Vec2 origin = {10, 10}, double w = 40, double h = 30) {
  Sheet s;
  s.size_mm = {origin.x * 2 + 2 * w + 10, origin.y * 2 + h};
  s.printable_mm.add(origin);
  s.printable_mm.add(origin + Vec2{2 * w + 10, h});
  const Vec2 o2 = origin + Vec2{w + 10, 0};
  // Sheet order on purpose far from a good tool order: second piece first, outline before contents.
  s.paths.push_back(rect_path(PathRole::Cut, o2, o2 + Vec2{w, h}, 1));
  s.paths.push_back(rect_path(PathRole::Cut, origin, origin + Vec2{w, h}, 0));
  s.paths.push_back(line_path(PathRole::Mountain, origin + Vec2{w / 2, 0}, origin + Vec2{w / 2, h}, 0));
  s.paths.push_back(line_path(PathRole::Valley, o2 + Vec2{0, h / 2}, o2 + Vec2{w, h / 2}, 1));
  s.paths.push_back(rect_path(PathRole::Cut, origin + Vec2{5, 5}, origin + Vec2{10, 10}, 0));
  s.paths.push_back(line_path(PathRole::Label, o2 + Vec2{2, 2}, o2 + Vec2{6, 2}, 1));
  s.paths.push_back(line_path(PathRole::Hint, origin, o2, -1));
  s.texts.push_back({"A1", origin + Vec2{w / 4, h - 4}, 3, 0, PathRole::Label, 0});
  return s;
}

/// Adds Silhouette-style registration marks (a `square`-mm square top-left, L brackets top-right and
/// bottom-left drawn `stroke` wide) with their outer corners at `min` and `max`, as the layout draws them:
/// bracket strokes centred half a stroke inside the outer edge.
inline void add_regmarks(Sheet& s, Vec2 min, Vec2 max, double arm = 20, double square = 5,
                         double stroke = 0.5) {
  const double h = stroke / 2;
  s.paths.push_back({PathRole::RegMark,
                     {min, min + Vec2{square, 0}, min + Vec2{square, square}, min + Vec2{0, square}},
                     true,
                     -1,
                     true});
  const double right = max.x - h, top = min.y + h, left = min.x + h, bottom = max.y - h;
  s.paths.push_back(
      {PathRole::RegMark, {{right - arm + h, top}, {right, top}, {right, top + arm - h}}, false, -1, false});
  s.paths.push_back({PathRole::RegMark,
                     {{left, bottom - arm + h}, {left, bottom}, {left + arm - h, bottom}},
                     false,
                     -1,
                     false});
}

}  // namespace foldkit::test
