#pragma once
// Convex hulls and fitting a point set into a rectangle at its best rotation: what both the unfolding
// (parts that fit the sheet) and the layout (scale, packing) ask of a shape.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>
#include <utility>
#include <vector>

#include "foldkit/geom/predicates.hpp"
#include "foldkit/geom/vec.hpp"

namespace foldkit {

/// Counter-clockwise convex hull (Andrew's monotone chain), collinear points dropped.
inline std::vector<Vec2> convex_hull(std::vector<Vec2> points) {
  std::sort(points.begin(), points.end(),
            [](Vec2 a, Vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) return points;
  std::vector<Vec2> hull(2 * points.size());
  std::size_t k = 0;
  for (Vec2 p : points) {
    while (k >= 2 && orient2d(hull[k - 2], hull[k - 1], p) <= 0)
      --k;
    hull[k++] = p;
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    Vec2 p = points[i];
    while (k >= lower && orient2d(hull[k - 2], hull[k - 1], p) <= 0)
      --k;
    hull[k++] = p;
  }
  hull.resize(k - 1);
  return hull;
}

/// The rotation (radians) that makes the points' axis-aligned bounding box smallest in area: the
/// smallest box has a side on a hull edge, so only those rotations are tried.
inline double min_area_rect_angle(std::span<const Vec2> points) {
  const std::vector<Vec2> hull = convex_hull(std::vector<Vec2>(points.begin(), points.end()));
  double best_angle = 0, best_area = 1e300;
  for (std::size_t i = 0, n = hull.size(); i < n; ++i) {
    const Vec2 e = hull[(i + 1) % n] - hull[i];
    if (norm(e) == 0) continue;
    const double angle = -std::atan2(e.y, e.x);
    const Rotation turn(angle);
    Box2 box;
    for (Vec2 p : hull)
      box.add(turn(p));
    if (box.width() * box.height() < best_area - 1e-9) {
      best_area = box.width() * box.height();
      best_angle = angle;
    }
  }
  return best_angle;
}

/// The largest scale at which a shape fits a rectangle, and the rotation (radians, counter-clockwise)
/// that reaches it.
struct RectFit {
  double scale = 0;
  double angle_rad = 0;
};

/// Best fit of the points into a `room` rectangle (same unit as the points times the scale), over
/// rotations every half degree and at every hull edge (0 when the room is empty).
inline RectFit fit_in_rect(std::span<const Vec2> points, Vec2 room) {
  if (!(room.x > 0 && room.y > 0)) return {};
  const std::vector<Vec2> hull = convex_hull(std::vector<Vec2>(points.begin(), points.end()));
  RectFit best;
  auto consider = [&](double a) {
    const Rotation turn(a);
    Box2 box;
    for (Vec2 p : hull)
      box.add(turn(p));
    const double w = std::max(box.width(), 1e-300), h = std::max(box.height(), 1e-300);
    const double s = std::min(room.x / w, room.y / h);
    if (s > best.scale) best = {s, a};
  };
  for (int k = 0; k < 360; ++k)
    consider(std::numbers::pi * k / 360);
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Vec2 e = hull[(i + 1) % hull.size()] - hull[i];
    const double a = -std::atan2(e.y, e.x);
    consider(a);
    consider(a + std::numbers::pi / 2);
  }
  return best;
}

}  // namespace foldkit
