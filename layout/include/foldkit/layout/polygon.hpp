#pragma once
// Small polygon toolkit shared by the layout modules: simple polygons as point lists, rigid motions
// of the plane, convex overlap tests and (through polyclipping) unions and offsets.
//
// Frame: every layout module works in millimetres with y pointing UP (the frame of the flat net, where
// faces are counter-clockwise). Only layout.cpp flips to the sheet's y-down frame when it emits a Sheet.
#include <span>
#include <vector>

#include "foldkit/geom/hull.hpp"  // convex_hull
#include "foldkit/geom/predicates.hpp"
#include "foldkit/geom/vec.hpp"

namespace foldkit::layout {

/// A closed polygon, last point joined to the first; counter-clockwise unless said otherwise.
using Polygon = std::vector<Vec2>;

/// Signed area (positive when counter-clockwise).
double signed_area(std::span<const Vec2> polygon);
/// Bounding box of a set of points.
Box2 bounds_of(std::span<const Vec2> points);

/// A rigid motion of the plane: rotate by angle_rad (counter-clockwise) about the origin, then translate.
struct Rigid2 {
  double angle_rad = 0;
  Vec2 offset_mm;
  /// Image of a point.
  Vec2 apply(Vec2 p) const { return rotated(p, angle_rad) + offset_mm; }
  /// Image of a direction (rotation only).
  Vec2 apply_dir(Vec2 d) const { return rotated(d, angle_rad); }
  /// Image of a polygon, point by point.
  Polygon apply(const Polygon& polygon) const {
    Polygon out;
    out.reserve(polygon.size());
    for (Vec2 p : polygon)
      out.push_back(apply(p));
    return out;
  }
};

/// The convex overlap test is foldkit::convex_overlap (geom/predicates.hpp), shared with the unfolding.
using foldkit::convex_overlap;

/// True when p lies inside the convex counter-clockwise polygon at least `inset` from every edge.
bool inside_convex(std::span<const Vec2> polygon, Vec2 p, double inset);

/// Union of polygons (non-zero fill): outer boundaries counter-clockwise, holes clockwise.
std::vector<Polygon> polygon_union(std::span<const Polygon> polygons);

/// The union grown outwards by `delta_mm` (round joins, within `arc_tolerance_mm` of the exact offset).
std::vector<Polygon> polygon_offset(std::span<const Polygon> polygons, double delta_mm,
                                    double arc_tolerance_mm = 0.05);

/// Area of the intersection of two polygon sets (each taken with non-zero fill), mm².
double intersection_area(std::span<const Polygon> a, std::span<const Polygon> b);

/// Total signed area of a polygon set (holes subtract).
double total_area(std::span<const Polygon> polygons);

}  // namespace foldkit::layout
