#include "foldkit/layout/tabs.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

namespace foldkit::layout {
namespace {

// Clockwise angle from direction u to direction v, in (0, 2pi]: the free angle outside the piece
// between an edge leaving a vertex (u) and the previous edge coming back to it (v).
double clockwise_angle(Vec2 u, Vec2 v) {
  double a = std::atan2(cross(v, u), dot(u, v));
  if (a <= 1e-12) a += 2 * std::numbers::pi;
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
  std::vector<int> tab_seam;               // the seam of each tab shape
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

  auto edge_length = [&](const SeamSide& s) {
    if (s.piece < 0) return 0.0;
    const OutlineEdge& e = pieces[s.piece].outline_mm[s.loop][s.index];
    return norm(e.b - e.a);
  };

  // Which seam each outline edge belongs to, and which seams are settled (tab placed or dropped).
  std::vector<std::vector<std::vector<int>>> seam_at(pieces.size());
  for (std::size_t p = 0; p < pieces.size(); ++p)
    for (const OutlineLoop& loop : pieces[p].outline_mm)
      seam_at[p].emplace_back(loop.size(), -1);
  for (std::size_t i = 0; i < seams.size(); ++i)
    for (const SeamSide& s : seams[i].sides)
      if (s.piece >= 0) seam_at[s.piece][s.loop][s.index] = static_cast<int>(i);
  std::vector<char> settled(seams.size(), 0);

  // The share of a corner's free angle a tab may take: all of it when the neighbour edge will never
  // carry a tab (it is this seam's partner, a settled seam without a tab here, or no seam at all), else
  // half, so that the neighbour's tab can take the other half.
  auto corner_cap = [&](const SeamSide& s, int neighbour, int seam, double free) {
    const int other = seam_at[s.piece][s.loop][neighbour];
    const bool open =
        other == seam || other < 0 || (settled[other] && !state[s.piece].has_tab[s.loop][neighbour]);
    return open ? std::max(0.5 * free, free - 0.12) : 0.5 * free;
  };

  // A tab for one side: the largest that fits. The full edge first, full width then narrower; then a
  // stretch of the edge only (its inner ends are mid-edge, free 180°), slid along the edge so that it
  // finds the edge's widest free part, e.g. the mouth of a narrow notch.
  auto try_side = [&](const Seam& seam, int seam_index, int k) -> std::optional<Tab> {
    const SeamSide& s = seam.sides[k];
    if (s.piece < 0) return std::nullopt;
    const OutlineLoop& loop = pieces[s.piece].outline_mm[s.loop];
    const int n = static_cast<int>(loop.size());
    const OutlineEdge& e = loop[s.index];
    const OutlineEdge& prev = loop[(s.index + n - 1) % n];
    const OutlineEdge& next = loop[(s.index + 1) % n];
    const double length = norm(e.b - e.a);
    if (length <= 0) return std::nullopt;
    const double free_a =
        corner_cap(s, (s.index + n - 1) % n, seam_index, clockwise_angle(e.b - e.a, prev.a - e.a));
    const double free_b =
        corner_cap(s, (s.index + 1) % n, seam_index, clockwise_angle(next.b - e.b, e.a - e.b));
    // A tab along p->q (a stretch of the edge) whose slants are at most limit_p, limit_q.
    auto attempt = [&](Vec2 p, Vec2 q, double limit_p, double limit_q, double w) -> std::optional<Tab> {
      // Gentle slants first; steeper ones (still within the corner's share) when the edge is short.
      for (double cap : {options.max_slant_rad, std::numbers::pi / 3, 5 * std::numbers::pi / 12}) {
        const double slant_p = std::min(cap, limit_p), slant_q = std::min(cap, limit_q);
        Polygon quad = tab_trapezoid(p, q, w, slant_p, slant_q);
        const double actual = std::fabs(cross(normalized(q - p), quad[1] - p));
        if (actual < std::max(0.95 * w, options.min_width_mm - 1e-9)) continue;
        if (fits(s.piece, test_shape(quad))) return Tab{-1, k, s.piece, std::move(quad), actual};
      }
      return std::nullopt;
    };
    const double top =
        std::min(options.width_mm, std::max(options.width_per_length * length, options.min_width_mm));
    std::vector<double> widths;
    for (double w = top; w >= options.min_width_mm - 1e-9; w *= 0.8)
      widths.push_back(w);
    if (widths.empty() || widths.back() > options.min_width_mm + 1e-9) widths.push_back(options.min_width_mm);
    for (double w : widths)
      if (auto tab = attempt(e.a, e.b, free_a, free_b, w)) return tab;
    // Stretches: the longest that fits at the widest width, among positions along the edge.
    std::optional<Tab> best;
    double best_area = 0;
    for (double part : {0.75, 0.6, 0.45, 0.33, 0.25, 0.18, 0.12}) {
      const double stretch = part * length;
      if (stretch < 1.5 * options.min_width_mm) break;
      for (double start : {1.0, 0.0, 0.5, 0.25, 0.75}) {
        const double t0 = start * (1 - part), t1 = t0 + part;
        const Vec2 p = e.a + (e.b - e.a) * t0, q = e.a + (e.b - e.a) * t1;
        const double lp = t0 < 1e-9 ? free_a : std::numbers::pi,
                     lq = t1 > 1 - 1e-9 ? free_b : std::numbers::pi;
        for (double w : widths) {
          if (w * stretch <= best_area) break;
          if (auto tab = attempt(p, q, lp, lq,
                                 std::min(w, options.width_per_length * stretch + options.min_width_mm))) {
            const double area = signed_area(tab->quad_mm);
            if (area > best_area) {
              best_area = area;
              best = std::move(tab);
            }
            break;
          }
        }
      }
      if (best && best->width_mm >= 0.95 * widths.front()) break;
    }
    return best;
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
  // Places the tab of one seam (the preferred side's, or the other side's when that keeps a larger
  // tab); false when neither side has room.
  auto place = [&](int index) {
    const Seam& seam = seams[index];
    // Alternate: prefer the side whose outline neighbours carry no tab yet, so a zipper of neighbouring
    // seams gets tab, no tab, tab… and every flap has a plain edge to be glued under.
    int first = neighbours_with_tabs(seam.sides[1]) < neighbours_with_tabs(seam.sides[0]) ? 1 : 0;
    std::optional<Tab> tab = try_side(seam, index, first);
    // A full tab on the preferred side is taken as is; otherwise the side that keeps the larger tab.
    const bool full =
        tab &&
        tab->width_mm >= 0.95 * std::min(options.width_mm, options.width_per_length *
                                                               norm(tab->quad_mm[3] - tab->quad_mm[0])) &&
        norm(tab->quad_mm[3] - tab->quad_mm[0]) >= 0.999 * edge_length(seam.sides[first]);
    if (!full) {
      std::optional<Tab> other = try_side(seam, index, 1 - first);
      if (other && (!tab || signed_area(other->quad_mm) > 1.2 * signed_area(tab->quad_mm)))
        tab = std::move(other);
    }
    settled[index] = 1;
    if (!tab) return false;
    tab->seam = index;
    const SeamSide& s = seam.sides[tab->side];
    PieceState& ps = state[s.piece];
    ps.tab_shapes.push_back(test_shape(tab->quad_mm));
    ps.tab_box.push_back(bounds_of(ps.tab_shapes.back()));
    ps.tab_seam.push_back(index);
    ps.has_tab[s.loop][s.index] = 1;
    plan.tab_of_seam[index] = std::move(tab);
    return true;
  };
  auto remove = [&](int index) {
    const Tab& tab = *plan.tab_of_seam[index];
    const SeamSide& s = seams[index].sides[tab.side];
    PieceState& ps = state[s.piece];
    for (std::size_t k = 0; k < ps.tab_seam.size(); ++k)
      if (ps.tab_seam[k] == index) {
        ps.tab_shapes.erase(ps.tab_shapes.begin() + static_cast<std::ptrdiff_t>(k));
        ps.tab_box.erase(ps.tab_box.begin() + static_cast<std::ptrdiff_t>(k));
        ps.tab_seam.erase(ps.tab_seam.begin() + static_cast<std::ptrdiff_t>(k));
        break;
      }
    ps.has_tab[s.loop][s.index] = 0;
    plan.tab_of_seam[index].reset();
  };

  std::vector<int> dropped;
  for (int index : sequence)
    if (!place(index)) dropped.push_back(index);

  // Repair: a seam left without a tab is often blocked by one neighbour's tab that would also fit
  // elsewhere (the other side, or narrower). Take that tab away, place this seam's, and put the
  // neighbour's back; keep the swap only when both seams end up with a tab.
  for (int index : dropped) {
    bool repaired = false;
    Box2 reach;
    for (const SeamSide& side : seams[index].sides) {
      if (side.piece < 0) continue;
      const OutlineEdge& e = pieces[side.piece].outline_mm[side.loop][side.index];
      reach.add(e.a);
      reach.add(e.b);
    }
    reach = Box2{reach.min - Vec2{options.width_mm, options.width_mm},
                 reach.max + Vec2{options.width_mm, options.width_mm}};
    std::vector<int> near;
    for (const SeamSide& side : seams[index].sides) {
      if (side.piece < 0) continue;
      const PieceState& ps = state[side.piece];
      for (std::size_t k = 0; k < ps.tab_seam.size(); ++k)
        if (reach.overlaps(ps.tab_box[k])) near.push_back(ps.tab_seam[k]);
    }
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());
    for (int other : near) {
      if (!plan.tab_of_seam[other]) continue;
      const Tab kept = *plan.tab_of_seam[other];
      remove(other);
      if (place(index)) {
        if (place(other)) {
          repaired = true;
          break;
        }
        remove(index);
      }
      // Put the neighbour's tab back exactly as it was.
      const SeamSide& s = seams[other].sides[kept.side];
      PieceState& ps = state[s.piece];
      ps.tab_shapes.push_back(test_shape(kept.quad_mm));
      ps.tab_box.push_back(bounds_of(ps.tab_shapes.back()));
      ps.tab_seam.push_back(other);
      ps.has_tab[s.loop][s.index] = 1;
      plan.tab_of_seam[other] = kept;
    }
    if (!repaired) plan.dropped.push_back(index);
  }
  std::sort(plan.dropped.begin(), plan.dropped.end());
  return plan;
}

}  // namespace foldkit::layout
