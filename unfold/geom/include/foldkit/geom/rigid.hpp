#pragma once
// The rigid motion the unfolders glue faces with: a rotation given by its cosine and sine about a point,
// then a translation of that point. Kept as (c, s) rather than an angle so that gluing one edge onto
// another needs no trigonometry.
#include "foldkit/geom/vec.hpp"

namespace foldkit {

/// Rotates by (c, s) (cos and sin of the angle, counter-clockwise) about `from`, then moves `from` to `to`.
struct RigidMotion {
  double c = 1, s = 0;
  Vec2 from, to;
  /// Image of a point.
  Vec2 operator()(Vec2 p) const {
    const Vec2 d = p - from;
    return {to.x + c * d.x - s * d.y, to.y + s * d.x + c * d.y};
  }
};

/// The motion taking segment p0-p1 onto segment q0-q1 (same length): p1 - p0 turned onto the direction of
/// q1 - q0, the midpoint of p onto the midpoint of q. The identity rotation when either segment is a point.
inline RigidMotion motion_onto(Vec2 p0, Vec2 p1, Vec2 q0, Vec2 q1) {
  const Vec2 dp = p1 - p0, dq = q1 - q0;
  const double n = norm(dp) * norm(dq);
  RigidMotion m;
  if (n > 0) {
    m.c = dot(dp, dq) / n;
    m.s = cross(dp, dq) / n;
  }
  m.from = (p0 + p1) * 0.5;
  m.to = (q0 + q1) * 0.5;
  return m;
}

}  // namespace foldkit
