#include "foldkit/layout/scale.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "foldkit/geom/hull.hpp"

namespace foldkit::layout {

double scale_for_size(double model_extent, double size_mm) {
  return size_mm / model_extent;
}

double max_fit_scale(std::span<const Vec2> points, Vec2 room_mm) {
  return fit_in_rect(points, room_mm).scale;
}

double best_fit_angle(std::span<const Vec2> points, Vec2 room_mm) {
  return fit_in_rect(points, room_mm).angle_rad;
}

}  // namespace foldkit::layout
