#pragma once
// Scale: model units to millimetres, from a wanted model size or from the room a sheet offers.
#include <span>

#include "foldkit/geom/vec.hpp"

namespace foldkit::layout {

/// mm per model unit so that the model's largest dimension (`model_extent`, model units) is `size_mm`.
double scale_for_size(double model_extent, double size_mm);

/// The largest scale at which the points, turned to the best rotation, fit a `room_mm` rectangle
/// (0 when the room is empty). Rotations are searched every half degree and at every hull edge.
double max_fit_scale(std::span<const Vec2> points, Vec2 room_mm);

/// The rotation (radians, counter-clockwise) at which max_fit_scale is reached.
double best_fit_angle(std::span<const Vec2> points, Vec2 room_mm);

}  // namespace foldkit::layout
