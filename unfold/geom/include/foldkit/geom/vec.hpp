#pragma once
// Plain 2D and 3D double vectors. POD on purpose: cheap to copy, store in vectors and compare.
#include <cmath>

namespace foldkit {

/// A point or direction in the plane. Millimetres on a sheet; model units inside unfold/.
struct Vec2 {
  double x = 0, y = 0;
  friend constexpr Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
  friend constexpr Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
  friend constexpr Vec2 operator-(Vec2 a) { return {-a.x, -a.y}; }
  friend constexpr Vec2 operator*(Vec2 a, double s) { return {a.x * s, a.y * s}; }
  friend constexpr Vec2 operator*(double s, Vec2 a) { return {a.x * s, a.y * s}; }
  friend constexpr Vec2 operator/(Vec2 a, double s) { return {a.x / s, a.y / s}; }
  constexpr Vec2& operator+=(Vec2 b) {
    x += b.x;
    y += b.y;
    return *this;
  }
  constexpr Vec2& operator-=(Vec2 b) {
    x -= b.x;
    y -= b.y;
    return *this;
  }
  friend constexpr bool operator==(Vec2 a, Vec2 b) = default;
};

constexpr double dot(Vec2 a, Vec2 b) {
  return a.x * b.x + a.y * b.y;
}
/// z of the 3D cross product: positive when b is counter-clockwise from a.
constexpr double cross(Vec2 a, Vec2 b) {
  return a.x * b.y - a.y * b.x;
}
// Not std::hypot: its guard against overflow cost 13% of a 2,000-face `make` (plane_2000 at 250 mm). The
// loaders keep coordinates within the float range (3.4e38), whose square is far inside a double's.
inline double norm(Vec2 a) {
  return std::sqrt(dot(a, a));
}
inline Vec2 normalized(Vec2 a) {
  double n = norm(a);
  return n > 0 ? a / n : Vec2{};
}
/// a rotated by +90 degrees (counter-clockwise).
constexpr Vec2 perp_ccw(Vec2 a) {
  return {-a.y, a.x};
}
/// A rotation by a fixed angle with its cosine and sine taken once: for rotating many points alike
/// (the same result as rotated() to the last bit, without a sine and cosine per point).
struct Rotation {
  double c = 1, s = 0;
  explicit Rotation(double radians) : c(std::cos(radians)), s(std::sin(radians)) {}
  Vec2 operator()(Vec2 a) const { return {c * a.x - s * a.y, s * a.x + c * a.y}; }
};

inline Vec2 rotated(Vec2 a, double radians) {
  return Rotation(radians)(a);
}

/// A point or direction in model space (mesh units).
struct Vec3 {
  double x = 0, y = 0, z = 0;
  friend constexpr Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
  friend constexpr Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
  friend constexpr Vec3 operator*(Vec3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
  friend constexpr Vec3 operator*(double s, Vec3 a) { return {a.x * s, a.y * s, a.z * s}; }
  friend constexpr Vec3 operator/(Vec3 a, double s) { return {a.x / s, a.y / s, a.z / s}; }
  friend constexpr bool operator==(Vec3 a, Vec3 b) = default;
};

constexpr double dot(Vec3 a, Vec3 b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
constexpr Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double norm(Vec3 a) {
  return std::sqrt(dot(a, a));
}
inline Vec3 normalized(Vec3 a) {
  double n = norm(a);
  return n > 0 ? a / n : Vec3{};
}

/// Axis-aligned box in the plane.
struct Box2 {
  Vec2 min{1e300, 1e300}, max{-1e300, -1e300};
  bool empty() const { return min.x > max.x || min.y > max.y; }
  void add(Vec2 p) {
    min = {std::fmin(min.x, p.x), std::fmin(min.y, p.y)};
    max = {std::fmax(max.x, p.x), std::fmax(max.y, p.y)};
  }
  void add(const Box2& b) {
    if (!b.empty()) {
      add(b.min);
      add(b.max);
    }
  }
  double width() const { return max.x - min.x; }
  double height() const { return max.y - min.y; }
  bool overlaps(const Box2& b) const {
    return min.x <= b.max.x && b.min.x <= max.x && min.y <= b.max.y && b.min.y <= max.y;
  }
};

/// `b` with every side moved out by `d` (in by a negative `d`).
inline Box2 grown(const Box2& b, double d) {
  return Box2{b.min - Vec2{d, d}, b.max + Vec2{d, d}};
}

}  // namespace foldkit
