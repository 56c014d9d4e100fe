#include "foldkit/layout/tabs.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <numeric>
#include <utility>

#include "foldkit/layout/box_grid.hpp"

namespace foldkit::layout {
namespace {

// How far a tab's collision footprint is pulled off its own edge, mm: touching the face it is glued to,
// or a neighbour tab at a shared corner, must not count as an overlap.
constexpr double kLift_mm = 0.05;
// Smallest sine of a slant the lift is divided by, so that a slant almost along the edge stays bounded.
constexpr double kLeastLiftSine = 0.05;
// Overlap tolerance of the collision tests, mm.
constexpr double kOverlapTolerance_mm = 1e-9;
// Where the neighbour edge will never carry a tab, a corner keeps this much of its free angle anyway,
// so that the tab's end stays visibly apart from the neighbour edge.
constexpr double kCornerMargin_rad = 0.12;
// Slants tried after options.max_slant_rad when a gentle slant leaves the tab too narrow: steeper, still
// within the corner's share.
constexpr std::array<double, 2> kSteeperSlants_rad{std::numbers::pi / 3, kSteepestTabSlant_rad};
// A tab narrowed by its slants to less than this share of the width asked counts as not fitting.
constexpr double kKeptWidthShare = 0.95;
// Each narrower try is this share of the previous width.
constexpr double kNarrowingStep = 0.8;
// Length tolerance in width and parameter comparisons (mm or edge parameter).
constexpr double kTolerance = 1e-9;
// Stretches of an edge tried when no tab fits along all of it: shares of the edge's length, longest
// first, and where each starts (share of the slack: 1 = flush with the edge's end).
constexpr std::array<double, 7> kStretchShares{0.75, 0.6, 0.45, 0.33, 0.25, 0.18, 0.12};
constexpr std::array<double, 5> kStretchStarts{1.0, 0.0, 0.5, 0.25, 0.75};
// A stretch shorter than this many least widths is not worth a tab.
constexpr double kShortestStretchInWidths = 1.5;
// Where along a full tab's outer side it is tested for lying in a bay of its piece (edge parameters).
constexpr std::array<double, 3> kBayProbes{0.25, 0.5, 0.75};
// A tab covering this share of its edge covers the whole edge (rounding of the stretch ends).
constexpr double kWholeEdgeShare = 0.999;
// The partner side's tab replaces a partial tab on the preferred side only when it is this many times
// larger in area: alternation is worth a little area.
constexpr double kOtherSideAreaGain = 1.2;

// Clockwise angle from direction u to direction v, in (0, 2pi]: the free angle outside the piece
// between an edge leaving a vertex (u) and the previous edge coming back to it (v).
double clockwise_angle(Vec2 u, Vec2 v) {
  double a = std::atan2(cross(v, u), dot(u, v));
  if (a <= 1e-12) a += 2 * std::numbers::pi;
  return a;
}

// A tab's footprint for collision tests: pulled a hair off its own edge (kLift_mm).
Polygon test_shape(const Polygon& quad) {
  const Vec2 a = quad[0], b = quad[3];
  const Vec2 dir = normalized(b - a);
  const Vec2 out{dir.y, -dir.x};
  Polygon shape = quad;
  const Vec2 sa = normalized(quad[1] - a), sb = normalized(quad[2] - b);
  shape[0] = a + sa * (kLift_mm / std::max(dot(sa, out), kLeastLiftSine));
  shape[3] = b + sb * (kLift_mm / std::max(dot(sb, out), kLeastLiftSine));
  return shape;
}

const OutlineEdge& edge_of(std::span<const ScaledPiece> pieces, const SeamSide& s) {
  return pieces[s.piece].outline_mm[s.loop][s.index];
}

// The seams in the order they are planned: `order`, or seam order when it is empty.
std::vector<int> planning_order(std::size_t seam_count, std::span<const int> order) {
  std::vector<int> sequence(order.begin(), order.end());
  if (sequence.empty()) {
    sequence.resize(seam_count);
    std::iota(sequence.begin(), sequence.end(), 0);
  }
  return sequence;
}

// tab_trapezoid with the cotangents of its slants at a and b: a tab is tried at many widths with the
// same slants, and the tangents were a tenth of planning the tabs of a large part.
Polygon trapezoid_of_cots(Vec2 a, Vec2 b, double w, std::array<double, 2> cot) {
  // Keep a short outer side: a pointed tab is hard to glue and its tip tears.
  constexpr double kMostSlantShare = 0.9;  // of the edge's length, both slants together
  const double length = norm(b - a);
  const Vec2 dir = (b - a) / length;
  const Vec2 out{dir.y, -dir.x};  // right of a->b: away from the piece
  w = std::min(w, kMostSlantShare * length / (cot[0] + cot[1]));
  return {a, a + out * w + dir * (w * cot[0]), b + out * w - dir * (w * cot[1]), b};
}

// The largest share of the free angle at each end of one side's edge a tab may take (corner_share).
struct EdgeCorners {
  double at_a_rad = 0, at_b_rad = 0;
};

// What one piece holds while tabs are planned: its triangles and the tabs placed so far (their collision
// footprints), each through a grid of their boxes, and per outline edge whether it carries a tab. A tab
// taken away stays in the grid with no seam (kNoSeam).
struct PieceState {
  static constexpr int kNoSeam = -1;
  BoxGrid triangles{Box2{}, 1.0};
  BoxGrid tabs{Box2{}, 1.0};
  std::vector<Polygon> tab_shapes;
  std::vector<int> tab_seam;               // the seam of each tab shape, kNoSeam once taken away
  std::vector<std::vector<char>> has_tab;  // per loop, per outline index

  PieceState(const ScaledPiece& piece, double tab_reach_mm) {
    Box2 region;
    for (const Triangle2& t : piece.triangles_mm)
      region.add(bounds(t));
    // Grids over the triangles and tabs: a tab is tried many times (widths, slants, stretches of its
    // edge), and each try tests only what is near it. Cells of about a triangle's size.
    const double n = std::max<double>(1, static_cast<double>(piece.triangles_mm.size()));
    const double cell_mm = region.empty() ? 1.0 : std::sqrt(region.width() * region.height() / n);
    triangles = BoxGrid(region, cell_mm);
    for (std::size_t k = 0; k < piece.triangles_mm.size(); ++k)
      triangles.insert(static_cast<int>(k), bounds(piece.triangles_mm[k]));
    if (!region.empty()) region = grown(region, tab_reach_mm);
    tabs = BoxGrid(region, cell_mm);
    for (const OutlineLoop& loop : piece.outline_mm)
      has_tab.emplace_back(loop.size(), 0);
  }
};

// Plans the tabs seam by seam: place() puts one seam's tab on the side that keeps alternation and
// area, remove() and record() take a placed tab away and put one back, repair() swaps a blocking
// neighbour's tab to make room for a dropped seam.
class TabPlanner {
 public:
  TabPlanner(std::span<const ScaledPiece> pieces, std::span<const Seam> seams, const TabOptions& options,
             std::span<const int> wanted_sides)
      : pieces_(pieces), seams_(seams), o_(options), wanted_sides_(wanted_sides), seam_at_(pieces.size()) {
    plan_.tab_of_seam.resize(seams.size());
    plan_.second_half_of_seam.resize(seams.size());
    settled_.assign(seams.size(), 0);
    state_.reserve(pieces.size());
    hulls_.reserve(pieces.size());
    for (std::size_t p = 0; p < pieces.size(); ++p) {
      hulls_.push_back(hull_of(pieces[p]));
      state_.emplace_back(pieces[p], options.width_mm);
      for (const OutlineLoop& loop : pieces[p].outline_mm)
        seam_at_[p].emplace_back(loop.size(), -1);
    }
    for (std::size_t i = 0; i < seams.size(); ++i)
      for (const SeamSide& s : seams[i].sides)
        if (s.piece >= 0) seam_at_[s.piece][s.loop][s.index] = static_cast<int>(i);
  }

  // Places the tab of one seam (the preferred side's, or the other side's when that keeps a larger
  // tab) and settles the seam; false when neither side has room.
  bool place(int index) {
    if (wanted_sides_.size() > static_cast<std::size_t>(index) && wanted_sides_[index] == kSplitTab &&
        place_split(index))
      return true;
    const Seam& seam = seams_[index];
    const int first = preferred_side(index, seam);
    std::optional<Tab> tab = try_side(index, first);
    // A full tab on the preferred side is taken as is; otherwise the side that keeps the larger tab.
    if (!is_full(tab, seam.sides[first])) {
      std::optional<Tab> other = try_side(index, 1 - first);
      if (other && (!tab || signed_area(other->quad_mm) > kOtherSideAreaGain * signed_area(tab->quad_mm)))
        tab = std::move(other);
    }
    settled_[index] = 1;
    if (!tab) return false;
    tab->seam = SeamId{index};
    record(std::move(*tab));
    return true;
  }

  // A seam left without a tab is often blocked by one neighbour's tab that would also fit elsewhere
  // (the other side, or narrower). Take that tab away, place this seam's, and put the neighbour's back;
  // keep the swap only when both seams end up with a tab.
  bool repair(int index) {
    for (int other : tabbed_seams_near(index)) {
      // A split tab stays: it was asked for both of its labels.
      if (!plan_.tab_of_seam[other] || plan_.is_split(other)) continue;
      const Tab kept = *plan_.tab_of_seam[other];
      remove(other);
      if (place(index)) {
        if (place(other)) return true;
        remove(index);
      }
      record(kept);  // the neighbour's tab back exactly as it was
    }
    return false;
  }

  TabPlan take_plan(std::span<const int> dropped) {
    for (int index : dropped)
      plan_.dropped.push_back(SeamId{index});
    std::sort(plan_.dropped.begin(), plan_.dropped.end());
    return std::move(plan_);
  }

 private:
  // A side the caller wants (its label fits on the tab, not on its face) comes first. Between two
  // pieces, then, the side whose tab lies in a bay of its piece: a tab out past the piece's convex hull
  // is a spike other pieces must keep their distance from, one in a bay adds nothing to the hull
  // (`bench --layout`: fewer parts and sheets; docs/layout.md). Else alternate: prefer the side whose
  // outline neighbours carry no tab yet, so a zipper of neighbouring seams gets tab, no tab, tab… and
  // every flap has a plain edge to be glued under.
  int preferred_side(int index, const Seam& seam) const {
    if (const int wanted = wanted_side(index); wanted >= 0) return wanted;
    if (o_.into_bays && seam.sides[0].piece >= 0 && seam.sides[1].piece >= 0 &&
        seam.sides[0].piece != seam.sides[1].piece) {
      const int in0 = probes_in_hull(seam.sides[0]), in1 = probes_in_hull(seam.sides[1]);
      if (in0 != in1) return in1 > in0 ? 1 : 0;
    }
    return neighbours_with_tabs(seam.sides[1]) < neighbours_with_tabs(seam.sides[0]) ? 1 : 0;
  }

  // How many points along the outer side of a full tab on `side` lie inside its piece's convex hull.
  int probes_in_hull(const SeamSide& side) const {
    const OutlineEdge& e = edge_of(pieces_, side);
    const Vec2 along = e.b - e.a;
    const double length = norm(along);
    if (!(length > 0)) return 0;
    const double width = std::min(o_.width_mm, o_.width_per_length * length);
    // The piece lies left of its outline edges, so its tabs lie to the right.
    const Vec2 out = perp_ccw(along) * (-width / length);
    return static_cast<int>(std::count_if(kBayProbes.begin(), kBayProbes.end(), [&](double t) {
      return inside_convex(hulls_[side.piece], e.a + along * t + out, 0);
    }));
  }

  static std::vector<Vec2> hull_of(const ScaledPiece& piece) {
    std::vector<Vec2> corners;
    for (const OutlineLoop& loop : piece.outline_mm)
      for (const OutlineEdge& e : loop)
        corners.push_back(e.a);
    return convex_hull(std::move(corners));
  }

  // The side the caller wants for seam `index`, or -1 (also where it wants the tab split).
  int wanted_side(int index) const {
    const int wanted = static_cast<std::size_t>(index) < wanted_sides_.size() ? wanted_sides_[index] : -1;
    return wanted == 0 || wanted == 1 ? wanted : -1;
  }

  // A split tab (kSplitTab): side 0 along the first half of its edge and side 1 along the first half of
  // its own, which is the other half (the sides run opposite ways); failing that both along their second
  // halves. The first half is recorded before the second is tried: in one part they may meet.
  bool place_split(int index) {
    for (bool first_halves : {true, false}) {
      std::optional<Tab> half = half_tab(index, 0, first_halves);
      if (!half) continue;
      half->seam = SeamId{index};
      record(std::move(*half));
      std::optional<Tab> other = half_tab(index, 1, first_halves);
      if (other) {
        other->seam = SeamId{index};
        record(std::move(*other), true);
        settled_[index] = 1;
        return true;
      }
      remove(index);
    }
    return false;
  }

  // Side k's tab along one half of its edge, at least the label's width (label_width_mm) with steep
  // ends; its end at the middle of the edge is free (the other half's tab lies on the other side).
  std::optional<Tab> half_tab(int index, int k, bool first_half) const {
    const SeamSide& s = seams_[index].sides[k];
    if (s.piece < 0) return std::nullopt;
    const OutlineEdge& e = edge_of(pieces_, s);
    const double half_length = 0.5 * norm(e.b - e.a);
    if (!(half_length > 0)) return std::nullopt;
    const EdgeCorners free = corners(s, index);
    const Vec2 mid = (e.a + e.b) * 0.5;
    const Vec2 p = first_half ? e.a : mid, q = first_half ? mid : e.b;
    const double lp = first_half ? free.at_a_rad : std::numbers::pi;
    const double lq = first_half ? std::numbers::pi : free.at_b_rad;
    const double least = std::max(std::min(o_.label_width_mm, o_.width_mm), o_.min_width_mm);
    const auto steep_first = slants(lp, lq, true);
    if (!any_width_may_fit(s.piece, p, q, steep_first, least)) return std::nullopt;
    for (double w : tab_widths_to_try(half_length, o_)) {
      if (w < least - kTolerance) break;
      if (auto tab = fit_trapezoid(s.piece, k, p, q, steep_first, w)) return tab;
    }
    if (auto tab = fit_trapezoid(s.piece, k, p, q, steep_first, least)) return tab;
    return std::nullopt;
  }

  int neighbours_with_tabs(const SeamSide& s) const {
    if (s.piece < 0) return 3;
    const auto& flags = state_[s.piece].has_tab[s.loop];
    const int n = static_cast<int>(flags.size());
    return flags[(s.index + n - 1) % n] + flags[(s.index + 1) % n];
  }

  // Full width (for its edge) along the whole edge of `side`.
  bool is_full(const std::optional<Tab>& tab, const SeamSide& side) const {
    if (!tab) return false;
    const double base = norm(tab->quad_mm[3] - tab->quad_mm[0]);
    return tab->width_mm >= kKeptWidthShare * std::min(o_.width_mm, o_.width_per_length * base) &&
           base >= kWholeEdgeShare * edge_length(side);
  }

  double edge_length(const SeamSide& s) const {
    if (s.piece < 0) return 0.0;
    const OutlineEdge& e = edge_of(pieces_, s);
    return norm(e.b - e.a);
  }

  // The placed tab joins its piece's obstacles and the plan (a split tab's second half apart). place()
  // and repair() both record here.
  void record(Tab tab, bool second_half = false) {
    const int index = tab.seam.index();
    const SeamSide& s = seams_[index].sides[tab.side];
    PieceState& ps = state_[s.piece];
    Polygon shape = test_shape(tab.quad_mm);
    ps.tabs.insert(static_cast<int>(ps.tab_shapes.size()), bounds_of(shape));
    ps.tab_shapes.push_back(std::move(shape));
    ps.tab_seam.push_back(index);
    ps.has_tab[s.loop][s.index] = 1;
    (second_half ? plan_.second_half_of_seam : plan_.tab_of_seam)[index] = std::move(tab);
  }

  // Takes seam `index`'s tab away, both halves of a split one.
  void remove(int index) {
    for (std::optional<Tab>* placed : {&plan_.tab_of_seam[index], &plan_.second_half_of_seam[index]}) {
      if (!*placed) continue;
      const SeamSide& s = seams_[index].sides[(*placed)->side];
      PieceState& ps = state_[s.piece];
      const auto k = std::find(ps.tab_seam.begin(), ps.tab_seam.end(), index);
      if (k != ps.tab_seam.end()) *k = PieceState::kNoSeam;
      ps.has_tab[s.loop][s.index] = 0;
      placed->reset();
    }
  }

  // The seams whose tabs lie within a tab's width of the seam's edges, increasing.
  std::vector<int> tabbed_seams_near(int index) const {
    Box2 reach;
    for (const SeamSide& side : seams_[index].sides) {
      if (side.piece < 0) continue;
      const OutlineEdge& e = edge_of(pieces_, side);
      reach.add(e.a);
      reach.add(e.b);
    }
    reach = grown(reach, o_.width_mm);
    std::vector<int> near;
    for (const SeamSide& side : seams_[index].sides) {
      if (side.piece < 0) continue;
      const PieceState& ps = state_[side.piece];
      ps.tabs.visit(reach, [&](int k) {
        if (ps.tab_seam[k] != PieceState::kNoSeam) near.push_back(ps.tab_seam[k]);
        return true;
      });
    }
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());
    return near;
  }

  // Clear of the piece's triangles and of its tabs placed so far.
  bool fits(int p, const Polygon& shape) const {
    const Box2 box = bounds_of(shape);
    const ScaledPiece& piece = pieces_[p];
    const PieceState& ps = state_[p];
    const bool clear_of_triangles = ps.triangles.visit(
        box, [&](int k) { return !convex_overlap(shape, piece.triangles_mm[k], kOverlapTolerance_mm); });
    if (!clear_of_triangles) return false;
    return ps.tabs.visit(box, [&](int k) {
      return ps.tab_seam[k] == PieceState::kNoSeam ||
             !convex_overlap(shape, ps.tab_shapes[k], kOverlapTolerance_mm);
    });
  }

  // The share of a corner's free angle a tab may take: all of it (less a margin) when the neighbour
  // edge will never carry a tab (it is this seam's partner, a settled seam without a tab here, or no
  // seam at all), else half, so that the neighbour's tab can take the other half.
  double corner_share(const SeamSide& s, int neighbour, int seam, double free_rad) const {
    const int other = seam_at_[s.piece][s.loop][neighbour];
    const bool open =
        other == seam || other < 0 || (settled_[other] && !state_[s.piece].has_tab[s.loop][neighbour]);
    return open ? std::max(0.5 * free_rad, free_rad - kCornerMargin_rad) : 0.5 * free_rad;
  }

  EdgeCorners corners(const SeamSide& s, int seam) const {
    const OutlineLoop& loop = pieces_[s.piece].outline_mm[s.loop];
    const int n = static_cast<int>(loop.size());
    const int before = (s.index + n - 1) % n, after = (s.index + 1) % n;
    const OutlineEdge& e = loop[s.index];
    const OutlineEdge& prev = loop[before];
    const OutlineEdge& next = loop[after];
    return {corner_share(s, before, seam, clockwise_angle(e.b - e.a, prev.a - e.a)),
            corner_share(s, after, seam, clockwise_angle(next.b - e.b, e.a - e.b))};
  }

  // A tab for side k of seam `index`: the largest that fits. The full edge first, full width then
  // narrower; then a stretch of the edge only.
  std::optional<Tab> try_side(int index, int k) const {
    const SeamSide& s = seams_[index].sides[k];
    if (s.piece < 0) return std::nullopt;
    const OutlineEdge& e = edge_of(pieces_, s);
    const double length = norm(e.b - e.a);
    if (length <= 0) return std::nullopt;
    const EdgeCorners free = corners(s, index);
    std::vector<double> widths = tab_widths_to_try(length, o_);
    // A tab wanted for its label keeps its full base up to its outer side (steep ends first) and is
    // first tried wide enough for it.
    const bool steep_first = wanted_side(index) == k;
    const double label_width = std::min(o_.label_width_mm, o_.width_mm);
    if (steep_first && label_width > widths.front()) widths.insert(widths.begin(), label_width);
    const auto edge_slants = slants(free.at_a_rad, free.at_b_rad, steep_first);
    if (auto tab = fit_trapezoid(s.piece, k, e.a, e.b, edge_slants, widths.front())) return tab;
    if (!any_width_may_fit(s.piece, e.a, e.b, edge_slants, widths.back()))
      return best_stretch(s.piece, k, e, free, widths);
    for (double w : std::span(widths).subspan(1))
      if (auto tab = fit_trapezoid(s.piece, k, e.a, e.b, edge_slants, w)) return tab;
    return best_stretch(s.piece, k, e, free, widths);
  }

  // The slants a tab along p->q may take, as cotangents at p and q: each slant cap (gentle first, or
  // steep first) within the free angles limit_p and limit_q.
  std::array<std::array<double, 2>, 3> slants(double limit_p, double limit_q, bool steep_first) const {
    std::array<double, 3> caps{o_.max_slant_rad, kSteeperSlants_rad[0], kSteeperSlants_rad[1]};
    if (steep_first) std::reverse(caps.begin(), caps.end());
    std::array<std::array<double, 2>, 3> cots;
    for (std::size_t i = 0; i < caps.size(); ++i)
      cots[i] = {1 / std::tan(std::min(caps[i], limit_p)), 1 / std::tan(std::min(caps[i], limit_q))};
    return cots;
  }

  // Whether some tab along p->q with one of `slants` and at least width w could fit. A narrower tab with
  // the same slants lies inside a wider one, so where the narrowest of each slant meets an obstacle,
  // every wider one does: on a slit, which takes no tab, the widths of 35 stretches were nine tenths
  // of planning a large part's tabs.
  bool any_width_may_fit(int piece, Vec2 p, Vec2 q, const std::array<std::array<double, 2>, 3>& slants,
                         double w) const {
    return std::any_of(slants.begin(), slants.end(), [&](const std::array<double, 2>& cot) {
      return fits(piece, test_shape(trapezoid_of_cots(p, q, w, cot)));
    });
  }

  // A tab along p->q (the edge or a stretch of it) of width w with one of `slants` (slants()): gentle
  // slants first; steeper ones (still within the corner's share) when the edge is short.
  std::optional<Tab> fit_trapezoid(int piece, int k, Vec2 p, Vec2 q,
                                   const std::array<std::array<double, 2>, 3>& slants, double w) const {
    for (const std::array<double, 2>& cot : slants) {
      Polygon quad = trapezoid_of_cots(p, q, w, cot);
      const double actual = std::fabs(cross(normalized(q - p), quad[1] - p));
      if (actual < std::max(kKeptWidthShare * w, o_.min_width_mm - kTolerance)) continue;
      if (fits(piece, test_shape(quad))) return Tab{SeamId{}, k, piece, std::move(quad), actual};
    }
    return std::nullopt;
  }

  // A stretch of the edge (its inner ends are mid-edge, free 180°), slid along the edge so that it finds
  // the edge's widest free part, e.g. the mouth of a narrow notch: the largest in area, the longest
  // stretches first, stopping at one of nearly full width.
  std::optional<Tab> best_stretch(int piece, int k, const OutlineEdge& e, const EdgeCorners& free,
                                  const std::vector<double>& widths) const {
    const double length = norm(e.b - e.a);
    std::optional<Tab> best;
    double best_area = 0;
    for (double part : kStretchShares) {
      const double stretch = part * length;
      if (stretch < kShortestStretchInWidths * o_.min_width_mm) break;
      for (double start : kStretchStarts) {
        const double t0 = start * (1 - part), t1 = t0 + part;
        const Vec2 p = e.a + (e.b - e.a) * t0, q = e.a + (e.b - e.a) * t1;
        const double lp = t0 < kTolerance ? free.at_a_rad : std::numbers::pi,
                     lq = t1 > 1 - kTolerance ? free.at_b_rad : std::numbers::pi;
        const auto stretch_slants = slants(lp, lq, false);
        const double narrowest = std::min(widths.back(), o_.width_per_length * stretch + o_.min_width_mm);
        if (!any_width_may_fit(piece, p, q, stretch_slants, narrowest)) continue;
        for (double w : widths) {
          if (w * stretch <= best_area) break;
          const double narrowed = std::min(w, o_.width_per_length * stretch + o_.min_width_mm);
          if (auto tab = fit_trapezoid(piece, k, p, q, stretch_slants, narrowed)) {
            const double area = signed_area(tab->quad_mm);
            if (area > best_area) {
              best_area = area;
              best = std::move(tab);
            }
            break;
          }
        }
      }
      if (best && best->width_mm >= kKeptWidthShare * widths.front()) break;
    }
    return best;
  }

  std::span<const ScaledPiece> pieces_;
  std::span<const Seam> seams_;
  const TabOptions& o_;
  std::span<const int> wanted_sides_;  // per seam: the side to try first, or -1
  std::vector<PieceState> state_;
  std::vector<std::vector<Vec2>> hulls_;                // per piece: its outline's convex hull
  std::vector<std::vector<std::vector<int>>> seam_at_;  // per piece, loop, outline index: its seam or -1
  std::vector<char> settled_;                           // per seam: tab placed or dropped
  TabPlan plan_;
};

}  // namespace

const Tab* TabPlan::on_side(std::size_t seam, int side) const {
  for (const auto* placed : {&tab_of_seam, &second_half_of_seam})
    if (seam < placed->size() && (*placed)[seam] && (*placed)[seam]->side == side) return &*(*placed)[seam];
  return nullptr;
}

bool TabPlan::is_split(std::size_t seam) const {
  return seam < second_half_of_seam.size() && second_half_of_seam[seam].has_value();
}

std::vector<const Tab*> TabPlan::all() const {
  std::vector<const Tab*> tabs;
  for (std::size_t s = 0; s < tab_of_seam.size(); ++s) {
    if (tab_of_seam[s]) tabs.push_back(&*tab_of_seam[s]);
    if (is_split(s)) tabs.push_back(&*second_half_of_seam[s]);
  }
  return tabs;
}

Polygon tab_trapezoid(Vec2 a, Vec2 b, double w, double slant_a, double slant_b) {
  return trapezoid_of_cots(a, b, w, {1 / std::tan(slant_a), 1 / std::tan(slant_b)});
}

std::vector<double> tab_widths_to_try(double edge_length_mm, const TabOptions& o) {
  const double top = std::min(o.width_mm, std::max(o.width_per_length * edge_length_mm, o.min_width_mm));
  std::vector<double> widths;
  for (double w = top; w >= o.min_width_mm - kTolerance; w *= kNarrowingStep)
    widths.push_back(w);
  if (widths.empty() || widths.back() > o.min_width_mm + kTolerance) widths.push_back(o.min_width_mm);
  return widths;
}

double narrow_slit_gap_mm(const TabOptions& o) {
  // A mouth this much wider than the narrowest tab still takes none once the slants are cut.
  constexpr double kSlitMouthSpare_mm = 0.5;
  return o.min_width_mm + kSlitMouthSpare_mm;
}

bool is_narrow_slit(std::span<const ScaledPiece> pieces, const Seam& seam, const TabOptions& o) {
  const SeamSide& a = seam.sides[0];
  const SeamSide& b = seam.sides[1];
  if (a.piece < 0 || a.piece != b.piece) return false;
  const OutlineEdge& on_a = edge_of(pieces, a);
  const OutlineEdge& on_b = edge_of(pieces, b);
  // Each side runs along the outline with the piece on its left, so the mate runs the other way: a's
  // start and b's end are the two copies of one end of the edge. Closer than a tab needs at both ends
  // (at a slit's tip one pair coincides), the two sides are that close all along, and no tab fits
  // between them.
  const double limit = narrow_slit_gap_mm(o);
  return norm(on_a.a - on_b.b) < limit && norm(on_a.b - on_b.a) < limit;
}

TabPlan plan_tabs(std::span<const ScaledPiece> pieces, std::span<const Seam> seams, const TabOptions& options,
                  std::span<const int> order, std::span<const int> wanted_sides) {
  TabPlanner planner(pieces, seams, options, wanted_sides);
  std::vector<int> blocked;
  for (int index : planning_order(seams.size(), order))
    if (!planner.place(index)) blocked.push_back(index);
  std::vector<int> dropped;
  for (int index : blocked)
    if (!planner.repair(index)) dropped.push_back(index);
  return planner.take_plan(dropped);
}

}  // namespace foldkit::layout
