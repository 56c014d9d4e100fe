#pragma once
// Geometric predicates shared by unfolding, layout and devices. Header-only.
//
// Flat triangles come from rigid motions of 3D faces, so coordinates carry rounding noise of about
// 1e-12 of the model size. The predicates take a tolerance `eps` (a length) so that triangles that
// touch along a shared edge or vertex are never reported as overlapping, while a real crossing
// deeper than eps always is.
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>

#include "foldkit/geom/vec.hpp"

namespace foldkit {

using Triangle2 = std::array<Vec2, 3>;

/// Twice the signed area of abc: positive when counter-clockwise.
constexpr double orient2d(Vec2 a, Vec2 b, Vec2 c) {
  return cross(b - a, c - a);
}

/// Signed area of a triangle (positive when counter-clockwise).
constexpr double signed_area(const Triangle2& t) {
  return 0.5 * orient2d(t[0], t[1], t[2]);
}

inline Box2 bounds(const Triangle2& t) {
  Box2 b;
  for (Vec2 p : t)
    b.add(p);
  return b;
}

namespace detail {

/// Whether the corners `q` lie outside edge p0->p1 or within eps inside it: max over v of
/// cross(e, v - p0) / |e| <= eps, for |e| > 0. The test is hot in the unfolding's and the tabs' overlap
/// checks, so |e| (a square root) is computed only where the answer depends on it. Division by |e| > 0 is
/// monotone, so the largest quotient is the largest cross product divided once; its sign is that
/// product's, and its size against eps is decided by squares with a margin far above the rounding of
/// either form. Near the margin, and for values out of the safe range, the exact form decides: the
/// answer is the same to the last bit.
template <class Q>
bool outside_edge(Vec2 p0, Vec2 p1, const Q& q, double eps) {
  const Vec2 e = p1 - p0;
  double widest = -HUGE_VAL;
  for (Vec2 v : q) {
    const double c = cross(e, v - p0);
    widest = c > widest ? c : widest;  // skips a NaN, as std::fmax does
  }
  if (widest <= 0 && eps >= 0) return true;
  constexpr double kLow = 1e-100, kHigh = 1e100, kMargin = 1e-9;
  const double len2 = e.x * e.x + e.y * e.y;
  if (len2 >= kLow * kLow && len2 <= kHigh && std::isfinite(widest)) {
    if (widest >= 0 && eps < 0) return false;
    if (widest >= kLow && eps == 0) return false;
    const double size = std::fabs(widest), room = std::fabs(eps);
    if ((widest > 0) == (eps > 0) && size >= kLow && size <= kHigh && room >= kLow && room <= kHigh) {
      const double w2 = widest * widest, bound2 = eps * eps * len2;
      if (w2 > bound2 * (1 + kMargin)) return widest < 0;  // farther from the line than eps
      if (w2 < bound2 * (1 - kMargin)) return widest > 0;  // nearer to the line than eps
    }
  }
  const double len = norm(e);
  double deepest = -1e300;
  for (Vec2 v : q)
    deepest = std::fmax(deepest, cross(e, v - p0) / len);
  return deepest <= eps;
}

}  // namespace detail

/// True when the interiors of two counter-clockwise convex polygons (any sized ranges of Vec2: a
/// Triangle2, a Polygon, a span) overlap by more than `eps` (a length): separating-axis test over the
/// edge normals of both, each shrunk by eps. Shared edges, shared vertices and mere touching are not
/// overlaps; a negative eps asks for a clearance of -eps between them.
template <class P, class Q>
bool convex_overlap(const P& a, const Q& b, double eps) {
  // q is separated from p when, for some edge of p, every corner of q lies outside that edge's line or
  // within eps inside it. cross(e, v - p_i) / |e| is the signed distance of v to the inside of the edge.
  auto separated_by_edges_of = [eps](const auto& p, const auto& q) {
    for (std::size_t i = 0, n = std::size(p); i < n; ++i) {
      const Vec2 p0 = p[i], p1 = p[(i + 1) % n];
      if (p1.x - p0.x == 0 && p1.y - p0.y == 0) continue;  // |e| == 0
      if (detail::outside_edge(p0, p1, q, eps)) return true;
    }
    return false;
  };
  return !separated_by_edges_of(a, b) && !separated_by_edges_of(b, a);
}

/// convex_overlap of two triangles (the unfolding's overlap test).
inline bool triangles_overlap(const Triangle2& a, const Triangle2& b, double eps) {
  return convex_overlap(a, b, eps);
}

/// True when segments pq and rs cross at a point interior to both (proper crossing, beyond eps).
inline bool segments_cross(Vec2 p, Vec2 q, Vec2 r, Vec2 s, double eps) {
  double lpq = norm(q - p), lrs = norm(s - r);
  if (lpq == 0 || lrs == 0) return false;
  double d1 = orient2d(p, q, r) / lpq, d2 = orient2d(p, q, s) / lpq;
  double d3 = orient2d(r, s, p) / lrs, d4 = orient2d(r, s, q) / lrs;
  return ((d1 > eps && d2 < -eps) || (d1 < -eps && d2 > eps)) &&
         ((d3 > eps && d4 < -eps) || (d3 < -eps && d4 > eps));
}

}  // namespace foldkit
