// shape_sheet_bound: a lower bound on sheets that sees shapes. The area bound cannot tell that two
// 103 mm squares fit on A4 but three do not; counting lattice points that every placement must cover can.
//
// Why it holds: fix a finite point set P inside the area. Items on one sheet have disjoint interiors, so
// each point lies inside at most one of them: a sheet holds items covering at most |P| points. An item
// covers at least as many points as the core inside it, and a core covers at least c_i points wherever it
// lies, so the sheets hold sum c_i points in all and number at least ceil(sum c_i / |P|).
//
// c_i is the least count over every rotation and position. Rotations are sampled 2 degrees apart over
// half a turn (the lattices and the area are symmetric under a half turn about the area's centre). A
// core turned by any angle contains the core eroded by reach * 1 degree turned by the nearest sample
// (a point at distance r from the centre moves at most r * 1 degree), and lies in the area only where
// the eroded core does: so the least count of the eroded core over the samples is at most c_i. For one
// rotation, the positions where point p is covered form the convex polygon p - core; the count is the
// depth of their arrangement over the rectangle of positions that keep the core inside the area, and its
// least value is taken at a vertex of that arrangement (the covered sets are open, the depth lower
// semi-continuous), so the vertices are the only positions tried. A point counts only when it lies
// inside the core by a margin: rounding can only lower the counts, never raise the bound.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include "foldkit/layout/pack.hpp"

namespace foldkit::layout {
namespace {

constexpr int kTurnSamples = 90;        // over half a turn: 2 degrees apart
constexpr double kInset_mm = 1e-6;      // how deep a point must lie inside a core to count
constexpr double kCongruent_mm = 1e-4;  // cores this close in shape share one count (eroded by it)
constexpr int kMostPoints = 16;         // larger lattices cost more than they tell
constexpr double kSteps[] = {0.98, 0.85, 0.7, 0.6, 0.49};  // lattice steps, shares of a core's width
constexpr int kMostSpans = 4;                              // point sets that cut the area in up to 4 x 4
constexpr int kMostShapes = 4;                             // lattices are spaced after the widest few cores
constexpr double kNarrowShare = 1.0 / 8.0;  // cores narrower than this share of the area count nothing

// The part of convex counter-clockwise `poly` left of the line a->b moved inwards by `by`.
Polygon clip_left(const Polygon& poly, Vec2 a, Vec2 b, double by) {
  const Vec2 n = normalized(perp_ccw(b - a));
  const double d = dot(n, a) + by;
  Polygon out;
  for (std::size_t i = 0, m = poly.size(); i < m; ++i) {
    const Vec2 p = poly[i], q = poly[(i + 1) % m];
    const double sp = dot(n, p) - d, sq = dot(n, q) - d;
    if (sp >= 0) out.push_back(p);
    if ((sp >= 0) != (sq >= 0)) out.push_back(p + (q - p) * (sp / (sp - sq)));
  }
  return out;
}

// The convex polygon shrunk by `by` on every side (empty when nothing is left).
Polygon eroded(const Polygon& convex, double by) {
  Polygon out = convex;
  for (std::size_t i = 0, m = convex.size(); i < m && out.size() >= 3; ++i)
    out = clip_left(out, convex[i], convex[(i + 1) % m], by);
  return out.size() >= 3 ? out : Polygon{};
}

// Counter-clockwise, without repeated points; empty unless convex with some area.
Polygon convex_core(Polygon p) {
  if (signed_area(p) < 0) std::reverse(p.begin(), p.end());
  Polygon q;
  for (Vec2 v : p)
    if (q.empty() || norm(v - q.back()) > 1e-9) q.push_back(v);
  while (q.size() > 1 && norm(q.front() - q.back()) <= 1e-9)
    q.pop_back();
  if (q.size() < 3 || !(signed_area(q) > 1e-9)) return {};
  for (std::size_t i = 0, m = q.size(); i < m; ++i)
    if (cross(q[(i + 1) % m] - q[i], q[(i + 2) % m] - q[(i + 1) % m]) < -1e-9) return {};
  return q;
}

// Least distance between two parallel lines enclosing the convex polygon (some edge lies on one).
double least_width(const Polygon& c) {
  double least = 1e300;
  for (std::size_t i = 0, m = c.size(); i < m; ++i) {
    const Vec2 e = c[(i + 1) % m] - c[i];
    const double len = norm(e);
    if (len == 0) continue;
    double far = 0;
    for (Vec2 v : c)
      far = std::max(far, cross(e, v - c[i]) / len);
    least = std::min(least, far);
  }
  return least;
}

// Same edge lengths and turns in the same cyclic order, starting anywhere.
bool congruent(const Polygon& a, const Polygon& b) {
  const std::size_t m = a.size();
  if (b.size() != m) return false;
  auto edge = [](const Polygon& p, std::size_t i) { return p[(i + 1) % p.size()] - p[i % p.size()]; };
  for (std::size_t shift = 0; shift < m; ++shift) {
    bool same = true;
    for (std::size_t i = 0; i < m && same; ++i) {
      const Vec2 ea = edge(a, i), eb = edge(b, i + shift);
      const Vec2 na = edge(a, i + 1), nb = edge(b, i + shift + 1);
      same = std::fabs(norm(ea) - norm(eb)) < 1e-6 && std::fabs(cross(ea, na) - cross(eb, nb)) < 1e-6 &&
             std::fabs(dot(ea, na) - dot(eb, nb)) < 1e-6;
    }
    if (same) return true;
  }
  return false;
}

// One shape of core: eroded for the rotation samples, centred on its vertex mean, with how many items
// have it.
struct Shape {
  Polygon core;  // eroded, centred
  double width = 0;
  long items = 0;
};

std::vector<Shape> shapes_of(std::span<const Polygon> cores_mm, const Box2& area) {
  const double narrow = kNarrowShare * std::min(area.width(), area.height());
  std::vector<Polygon> kinds;
  std::vector<long> counts;
  for (const Polygon& given : cores_mm) {
    const Polygon c = convex_core(given);
    if (c.empty() || least_width(c) < narrow) continue;
    std::size_t k = 0;
    while (k < kinds.size() && !congruent(kinds[k], c))
      ++k;
    if (k == kinds.size()) {
      kinds.push_back(c);
      counts.push_back(0);
    }
    ++counts[k];
  }
  std::vector<Shape> shapes;
  for (std::size_t k = 0; k < kinds.size(); ++k) {
    Vec2 centre;
    for (Vec2 v : kinds[k])
      centre += v / static_cast<double>(kinds[k].size());
    Polygon centred = kinds[k];
    double reach = 0;
    for (Vec2& v : centred) {
      v -= centre;
      reach = std::max(reach, norm(v));
    }
    const double turn_slack = reach * (0.5 * std::numbers::pi / kTurnSamples);
    Shape s{eroded(centred, turn_slack + kCongruent_mm), 0, counts[k]};
    if (s.core.empty()) continue;
    s.width = least_width(s.core);
    shapes.push_back(std::move(s));
  }
  std::stable_sort(shapes.begin(), shapes.end(),
                   [](const Shape& a, const Shape& b) { return a.width > b.width; });
  return shapes;
}

std::optional<Vec2> crossing(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const Vec2 r = b - a, s = d - c;
  const double den = cross(r, s);
  if (std::fabs(den) < 1e-15) return std::nullopt;
  const double t = cross(c - a, s) / den, u = cross(c - a, r) / den;
  if (t < -1e-12 || t > 1 + 1e-12 || u < -1e-12 || u > 1 + 1e-12) return std::nullopt;
  return a + r * t;
}

// The fewest points the core q covers at any position that keeps it inside `area` (at this rotation),
// or `best` when that is not fewer: the depth at every vertex of the arrangement of the covered sets.
int least_cover(const Polygon& q, std::span<const Vec2> points, const Box2& area, int best) {
  const Box2 qb = bounds_of(q);
  const Box2 t{area.min - qb.min, area.max - qb.max};  // positions of q's origin
  if (t.empty()) return best;                          // the core fits nowhere at this rotation
  auto depth = [&](Vec2 c) {
    int d = 0;
    for (Vec2 p : points)
      if (inside_convex(q, p - c, kInset_mm) && ++d >= best) break;
    return d;
  };
  auto visit = [&](Vec2 c) {
    if (c.x < t.min.x - 1e-9 || c.x > t.max.x + 1e-9 || c.y < t.min.y - 1e-9 || c.y > t.max.y + 1e-9) return;
    c = {std::clamp(c.x, t.min.x, t.max.x), std::clamp(c.y, t.min.y, t.max.y)};
    best = std::min(best, depth(c));
  };
  const Vec2 corners[4] = {t.min, {t.max.x, t.min.y}, t.max, {t.min.x, t.max.y}};
  for (Vec2 c : corners)
    visit(c);
  // The covered set of p (positions c with p inside c + q) is p - q; those that reach t.
  std::vector<Polygon> sets;
  std::vector<Box2> boxes;
  for (Vec2 p : points) {
    const Box2 b{p - qb.max, p - qb.min};
    if (b.max.x < t.min.x || b.min.x > t.max.x || b.max.y < t.min.y || b.min.y > t.max.y) continue;
    Polygon s;
    for (Vec2 v : q)
      s.push_back(p - v);
    sets.push_back(std::move(s));
    boxes.push_back(b);
  }
  for (std::size_t i = 0; i < sets.size() && best > 0; ++i) {
    const Polygon& a = sets[i];
    for (std::size_t k = 0; k < a.size(); ++k) {
      const Vec2 a0 = a[k], a1 = a[(k + 1) % a.size()];
      visit(a0);
      for (int side = 0; side < 4; ++side)
        if (auto x = crossing(a0, a1, corners[side], corners[(side + 1) % 4])) visit(*x);
      for (std::size_t j = i + 1; j < sets.size(); ++j) {
        const Box2& bj = boxes[j];
        if (bj.max.x < boxes[i].min.x || bj.min.x > boxes[i].max.x || bj.max.y < boxes[i].min.y ||
            bj.min.y > boxes[i].max.y)
          continue;
        for (std::size_t l = 0; l < sets[j].size(); ++l)
          if (auto x = crossing(a0, a1, sets[j][l], sets[j][(l + 1) % sets[j].size()])) visit(*x);
      }
    }
  }
  return best;
}

Polygon turned(const Polygon& p, double angle) {
  Polygon out = p;
  for (Vec2& v : out)
    v = rotated(v, angle);
  return out;
}

// The least count over the rotation samples (only the first when `first_only`: an upper bound).
int least_cover_turning(const Shape& s, std::span<const Vec2> points, const Box2& area, bool first_only) {
  int best = static_cast<int>(points.size());
  for (int k = 0; k < (first_only ? 1 : kTurnSamples) && best > 0; ++k)
    best = least_cover(turned(s.core, std::numbers::pi * k / kTurnSamples), points, area, best);
  return best;
}

// A lattice of spacings `step` centred on the area (shifted half a step along x and/or y), its
// points strictly inside the area.
std::vector<Vec2> lattice(const Box2& area, Vec2 step, bool shift_x, bool shift_y) {
  const Vec2 centre = 0.5 * (area.min + area.max);
  auto coordinates = [&](double mid, double lo, double hi, double step, bool shift) {
    std::vector<double> out;
    const int most = static_cast<int>((hi - lo) / step) + 2;
    for (int k = -most; k <= most; ++k) {
      const double v = mid + (k + (shift ? 0.5 : 0.0)) * step;
      if (v > lo && v < hi) out.push_back(v);
    }
    return out;
  };
  std::vector<Vec2> points;
  for (double x : coordinates(centre.x, area.min.x, area.max.x, step.x, shift_x))
    for (double y : coordinates(centre.y, area.min.y, area.max.y, step.y, shift_y))
      points.push_back({x, y});
  return points;
}

// nx x ny points that cut the area into equal spans: (i + 1) / (nx + 1) of its width, alike in y. Cores
// about a third of the area tall cover one of two such points wherever they lie (two to a sheet), which
// no lattice spaced after their width tells.
std::vector<Vec2> spans(const Box2& area, int nx, int ny) {
  std::vector<Vec2> points;
  for (int i = 1; i <= nx; ++i)
    for (int j = 1; j <= ny; ++j)
      points.push_back({area.min.x + area.width() * i / (nx + 1), area.min.y + area.height() * j / (ny + 1)});
  return points;
}

long ceil_div(long a, long b) {
  return (a + b - 1) / b;
}

}  // namespace

long shape_sheet_bound(std::span<const Polygon> cores_mm, const Box2& area_mm) {
  if (area_mm.empty()) return 0;
  const std::vector<Shape> shapes = shapes_of(cores_mm, area_mm);
  long bound = 0;
  const auto consider = [&](const std::vector<Vec2>& points) {
    const long n = static_cast<long>(points.size());
    if (n == 0 || n > kMostPoints) return;
    // Upper bounds first (one rotation each): most point sets cannot beat the bound so far.
    long most = 0;
    for (const Shape& s : shapes)
      most += s.items * least_cover_turning(s, points, area_mm, true);
    if (ceil_div(most, n) <= bound) return;
    long covered = 0;
    for (const Shape& s : shapes)
      covered += s.items * least_cover_turning(s, points, area_mm, false);
    bound = std::max(bound, ceil_div(covered, n));
  };
  for (std::size_t k = 0; k < std::min<std::size_t>(shapes.size(), kMostShapes); ++k)
    for (double share_x : kSteps)
      for (double share_y : kSteps)
        for (int shift = 0; shift < 4; ++shift)
          consider(
              lattice(area_mm, {share_x * shapes[k].width, share_y * shapes[k].width}, shift & 1, shift & 2));
  if (shapes.empty()) return bound;
  for (int nx = 1; nx <= kMostSpans; ++nx)
    for (int ny = 1; ny <= kMostSpans; ++ny)
      consider(spans(area_mm, nx, ny));
  return bound;
}

}  // namespace foldkit::layout
