#include "foldkit/layout/polygon.hpp"

#include <algorithm>
#include <cmath>

#include <polyclipping/clipper.hpp>

namespace foldkit::layout {
namespace {

// Clipper works on integers: 1e-5 mm steps keep rounding far below anything printable while sheets of
// a few metres stay well inside the 2^62 range.
constexpr double kClipperScale = 1e5;

ClipperLib::Path to_clipper(std::span<const Vec2> polygon) {
  ClipperLib::Path out;
  out.reserve(polygon.size());
  for (Vec2 p : polygon)
    out.push_back({static_cast<ClipperLib::cInt>(std::llround(p.x * kClipperScale)),
                   static_cast<ClipperLib::cInt>(std::llround(p.y * kClipperScale))});
  return out;
}

ClipperLib::Paths to_clipper(std::span<const Polygon> polygons) {
  ClipperLib::Paths out;
  out.reserve(polygons.size());
  for (const Polygon& p : polygons)
    if (p.size() >= 3) out.push_back(to_clipper(p));
  return out;
}

std::vector<Polygon> from_clipper(const ClipperLib::Paths& paths) {
  std::vector<Polygon> out;
  out.reserve(paths.size());
  for (const ClipperLib::Path& path : paths) {
    Polygon poly;
    poly.reserve(path.size());
    for (const ClipperLib::IntPoint& q : path)
      poly.push_back({static_cast<double>(q.X) / kClipperScale, static_cast<double>(q.Y) / kClipperScale});
    out.push_back(std::move(poly));
  }
  return out;
}

// Whether c / |e| < inset (|e| > 0): a point's signed distance to an edge's line below the inset. Label
// placement asks this many times per label; |e| (a square root) is computed only where the answer depends on
// it. The sign of the quotient is that of c, and its size against the inset is decided by squares with
// a margin far above the rounding of either form; the exact form decides near the margin and for values
// out of the safe range, so the answer is the same to the last bit.
bool nearer_than(double c, Vec2 e, double inset) {
  constexpr double kLow = 1e-100, kHigh = 1e100, kMargin = 1e-9;
  const double len2 = e.x * e.x + e.y * e.y;
  if (len2 >= kLow * kLow && len2 <= kHigh && std::isfinite(c) && std::isfinite(inset)) {
    if (c >= 0 && inset <= 0) return false;
    if (c < 0 && inset > 0) return true;
    if (c <= -kLow && inset == 0) return true;
    const double size = std::fabs(c), room = std::fabs(inset);
    if ((c > 0) == (inset > 0) && size >= kLow && size <= kHigh && room >= kLow && room <= kHigh) {
      const double c2 = c * c, bound2 = inset * inset * len2;
      if (c2 > bound2 * (1 + kMargin)) return c < 0;  // farther from the line than the inset
      if (c2 < bound2 * (1 - kMargin)) return c > 0;  // nearer to the line than the inset
    }
  }
  return c / norm(e) < inset;
}

}  // namespace

double signed_area(std::span<const Vec2> polygon) {
  double twice = 0;
  for (std::size_t i = 0, n = polygon.size(); i < n; ++i)
    twice += cross(polygon[i], polygon[(i + 1) % n]);
  return 0.5 * twice;
}

Box2 bounds_of(std::span<const Vec2> points) {
  Box2 box;
  for (Vec2 p : points)
    box.add(p);
  return box;
}

bool inside_convex(std::span<const Vec2> polygon, Vec2 p, double inset) {
  for (std::size_t i = 0, n = polygon.size(); i < n; ++i) {
    Vec2 e = polygon[(i + 1) % n] - polygon[i];
    if (e.x == 0 && e.y == 0) continue;  // |e| == 0
    if (nearer_than(cross(e, p - polygon[i]), e, inset)) return false;
  }
  return true;
}

std::vector<Polygon> polygon_union(std::span<const Polygon> polygons) {
  ClipperLib::Clipper clipper;
  clipper.AddPaths(to_clipper(polygons), ClipperLib::ptSubject, true);
  ClipperLib::Paths solution;
  clipper.Execute(ClipperLib::ctUnion, solution, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  return from_clipper(solution);
}

std::vector<Polygon> polygon_offset(std::span<const Polygon> polygons, double delta_mm,
                                    double arc_tolerance_mm) {
  // Offsetting overlapping inputs one by one would leave their overlaps doubled; union first.
  ClipperLib::Clipper clipper;
  clipper.AddPaths(to_clipper(polygons), ClipperLib::ptSubject, true);
  ClipperLib::Paths merged;
  clipper.Execute(ClipperLib::ctUnion, merged, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  ClipperLib::ClipperOffset offset(2.0, arc_tolerance_mm * kClipperScale);
  offset.AddPaths(merged, ClipperLib::jtRound, ClipperLib::etClosedPolygon);
  ClipperLib::Paths solution;
  offset.Execute(solution, delta_mm * kClipperScale);
  return from_clipper(solution);
}

double intersection_area(std::span<const Polygon> a, std::span<const Polygon> b) {
  ClipperLib::Clipper clipper;
  clipper.AddPaths(to_clipper(a), ClipperLib::ptSubject, true);
  clipper.AddPaths(to_clipper(b), ClipperLib::ptClip, true);
  ClipperLib::Paths solution;
  clipper.Execute(ClipperLib::ctIntersection, solution, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  double area = 0;
  for (const ClipperLib::Path& p : solution)
    area += ClipperLib::Area(p);
  return area / (kClipperScale * kClipperScale);
}

double total_area(std::span<const Polygon> polygons) {
  double area = 0;
  for (const Polygon& p : polygons)
    area += signed_area(p);
  return area;
}

}  // namespace foldkit::layout
