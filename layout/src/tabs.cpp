#include "foldkit/layout/tabs.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace foldkit::layout {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Clockwise angle from direction u to direction v, in (0, 2pi]: the free angle outside the piece
// between an edge leaving a vertex (u) and the previous edge coming back to it (v).
double clockwise_angle(Vec2 u, Vec2 v) {
  double a = std::atan2(cross(v, u), dot(u, v));
  if (a <= 1e-12) a += 2 * kPi;
  return a;
}

// A tab's footprint for collision tests: pulled a hair off its own edge so that touching the face it is
// glued to, or a neighbour tab at a shared corner, does not count as an overlap.
Polygon test_shape(const Polygon& quad) {
  const Vec2 a = quad[0], b = quad[3];
  const Vec2 dir = normalized(b - a);
  const Vec2 out{dir.y, -dir.x};
  constexpr double kLift = 0.05;
  Polygon shape = quad;
  const Vec2 sa = normalized(quad[1] - a), sb = normalized(quad[2] - b);
  shape[0] = a + sa * (kLift / std::max(dot(sa, out), 0.05));
  shape[3] = b + sb * (kLift / std::max(dot(sb, out), 0.05));
  return shape;
}

struct PieceState {
  std::vector<Box2> triangle_box;
  std::vector<Polygon> tab_shapes;
  std::vector<Box2> tab_box;
  std::vector<std::vector<char>> has_tab;  // per loop, per outline index
};

}  // namespace

Polygon tab_trapezoid(Vec2 a, Vec2 b, double w, double slant_a, double slant_b) {
  const double length = norm(b - a);
  const Vec2 dir = (b - a) / length;
  const Vec2 out{dir.y, -dir.x};  // right of a->b: away from the piece
  const double ca = 1 / std::tan(slant_a), cb = 1 / std::tan(slant_b);
  // Keep a short outer side: a pointed tab is hard to glue and its tip tears.
  w = std::min(w, 0.9 * length / (ca + cb));
  return {a, a + out * w + dir * (w * ca), b + out * w - dir * (w * cb), b};
}

TabPlan plan_tabs(std::span<const ScaledPiece> pieces, std::span<const Seam> seams, const TabOptions& options,
                  std::span<const int> order) {
  TabPlan plan;
  plan.tab_of_seam.resize(seams.size());
  std::vector<PieceState> state(pieces.size());
  for (std::size_t p = 0; p < pieces.size(); ++p) {
    for (const Triangle2& t : pieces[p].triangles_mm)
      state[p].triangle_box.push_back(bounds(t));
    for (const OutlineLoop& loop : pieces[p].outline_mm)
      state[p].has_tab.emplace_back(loop.size(), 0);
  }

  auto fits = [&](int p, const Polygon& shape) {
    const Box2 box = bounds_of(shape);
    const ScaledPiece& piece = pieces[p];
    for (std::size_t k = 0; k < piece.triangles_mm.size(); ++k)
      if (box.overlaps(state[p].triangle_box[k]) && convex_overlap(shape, piece.triangles_mm[k], 1e-9))
        return false;
    for (std::size_t k = 0; k < state[p].tab_shapes.size(); ++k)
      if (box.overlaps(state[p].tab_box[k]) && convex_overlap(shape, state[p].tab_shapes[k], 1e-9))
        return false;
    return true;
  };

  // A tab for one side, as wide as fits (full width, then narrower), or nothing.
  auto try_side = [&](const Seam& seam, int k) -> std::optional<Tab> {
    const SeamSide& s = seam.sides[k];
    if (s.piece < 0) return std::nullopt;
    const OutlineLoop& loop = pieces[s.piece].outline_mm[s.loop];
    const int n = static_cast<int>(loop.size());
    const OutlineEdge& e = loop[s.index];
    const OutlineEdge& prev = loop[(s.index + n - 1) % n];
    const OutlineEdge& next = loop[(s.index + 1) % n];
    const double length = norm(e.b - e.a);
    if (length <= 0) return std::nullopt;
    // Half the free angle at each corner: the neighbour edge's tab may take the other half.
    const double free_a = clockwise_angle(e.b - e.a, prev.a - e.a);
    const double free_b = clockwise_angle(next.b - e.b, e.a - e.b);
    // A tab along p->q (a stretch of the edge) whose corners have free angles free_p, free_q.
    auto attempt = [&](Vec2 p, Vec2 q, double free_p, double free_q) -> std::optional<Tab> {
      const double stretch = norm(q - p);
      double w =
          std::min(options.width_mm, std::max(options.width_per_length * stretch, options.min_width_mm));
      for (; w >= options.min_width_mm - 1e-9; w *= 0.8) {
        // Gentle slants first; steeper ones (still within half the free angle) when the edge is short.
        for (double cap : {options.max_slant_rad, kPi / 3, 5 * kPi / 12}) {
          const double slant_p = std::min(cap, 0.5 * free_p), slant_q = std::min(cap, 0.5 * free_q);
          Polygon quad = tab_trapezoid(p, q, w, slant_p, slant_q);
          const double actual = std::fabs(cross(normalized(q - p), quad[1] - p));
          if (actual < std::max(0.95 * w, options.min_width_mm - 1e-9)) continue;
          if (fits(s.piece, test_shape(quad))) return Tab{-1, k, s.piece, std::move(quad), actual};
        }
      }
      return std::nullopt;
    };
    if (auto tab = attempt(e.a, e.b, free_a, free_b)) return tab;
    // In a narrow notch the corner at the notch's tip leaves no room; the wide part of the edge, towards
    // the notch's mouth, often does: a tab along that part only (its inner end is mid-edge, free 180°).
    for (double part : {0.6, 0.4}) {
      if (part * length < 2 * options.min_width_mm) break;
      const Vec2 cut = free_a < free_b ? e.b + (e.a - e.b) * part : e.a + (e.b - e.a) * part;
      auto tab = free_a < free_b ? attempt(cut, e.b, kPi, free_b) : attempt(e.a, cut, free_a, kPi);
      if (tab) return tab;
    }
    return std::nullopt;
  };

  auto neighbours_with_tabs = [&](const SeamSide& s) {
    if (s.piece < 0) return 3;
    const auto& flags = state[s.piece].has_tab[s.loop];
    const int n = static_cast<int>(flags.size());
    return flags[(s.index + n - 1) % n] + flags[(s.index + 1) % n];
  };

  std::vector<int> sequence(order.begin(), order.end());
  if (sequence.empty()) {
    sequence.resize(seams.size());
    std::iota(sequence.begin(), sequence.end(), 0);
  }
  for (int index : sequence) {
    const Seam& seam = seams[index];
    // Alternate: prefer the side whose outline neighbours carry no tab yet, so a zipper of neighbouring
    // seams gets tab, no tab, tab… and every flap has a plain edge to be glued under.
    int first = neighbours_with_tabs(seam.sides[1]) < neighbours_with_tabs(seam.sides[0]) ? 1 : 0;
    std::optional<Tab> tab = try_side(seam, first);
    if (!tab) tab = try_side(seam, 1 - first);
    if (!tab) {
      plan.dropped.push_back(index);
      continue;
    }
    tab->seam = index;
    const SeamSide& s = seam.sides[tab->side];
    PieceState& ps = state[s.piece];
    ps.tab_shapes.push_back(test_shape(tab->quad_mm));
    ps.tab_box.push_back(bounds_of(ps.tab_shapes.back()));
    ps.has_tab[s.loop][s.index] = 1;
    plan.tab_of_seam[index] = std::move(tab);
  }
  std::sort(plan.dropped.begin(), plan.dropped.end());
  return plan;
}

}  // namespace foldkit::layout
