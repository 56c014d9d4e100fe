#include "foldkit/layout/scale.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "foldkit/layout/polygon.hpp"

namespace foldkit::layout {
namespace {

constexpr double kPi = 3.14159265358979323846;

// (scale, angle) of the best fit.
std::pair<double, double> best_fit(std::span<const Vec2> points, Vec2 room) {
  if (!(room.x > 0 && room.y > 0)) return {0, 0};
  const Polygon hull = convex_hull(std::vector<Vec2>(points.begin(), points.end()));
  std::vector<double> angles;
  for (int k = 0; k < 360; ++k)
    angles.push_back(kPi * k / 360);
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Vec2 e = hull[(i + 1) % hull.size()] - hull[i];
    const double a = -std::atan2(e.y, e.x);
    angles.push_back(a);
    angles.push_back(a + kPi / 2);
  }
  double best_scale = 0, best_angle = 0;
  for (double a : angles) {
    Box2 box;
    for (Vec2 p : hull)
      box.add(rotated(p, a));
    const double w = std::max(box.width(), 1e-300), h = std::max(box.height(), 1e-300);
    const double s = std::min(room.x / w, room.y / h);
    if (s > best_scale) {
      best_scale = s;
      best_angle = a;
    }
  }
  return {best_scale, best_angle};
}

}  // namespace

double scale_for_size(double model_extent, double size_mm) {
  return size_mm / model_extent;
}

double max_fit_scale(std::span<const Vec2> points, Vec2 room_mm) {
  return best_fit(points, room_mm).first;
}

double best_fit_angle(std::span<const Vec2> points, Vec2 room_mm) {
  return best_fit(points, room_mm).second;
}

}  // namespace foldkit::layout
