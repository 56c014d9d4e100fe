#include "foldkit/layout/edge_numbers.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "foldkit/layout/box_grid.hpp"
#include "foldkit/layout/label_text.hpp"

namespace foldkit::layout {
namespace {

struct Segment {
  Vec2 a, b;
  Box2 box;
  bool fold = false;  // fold lines may be crossed when nothing else is left; outlines never
};

// Grid cells of about a label's size: a query looks at a handful of cells.
constexpr double kGridCell_mm = 4;
// Labels may sit on tabs or stick out of tiny faces: the grid covers that much around the piece.
constexpr double kGridBorder_mm = 20;

// What a label in one piece must keep clear of, found through grids so that a query costs what is
// near it, not the whole piece.
struct PieceObstacles {
  std::vector<Segment> lines;
  std::vector<Polygon> labels;
  std::vector<bool> label_active;  // retracted labels stay in the grid, switched off
  BoxGrid line_grid, label_grid, triangle_grid;
  explicit PieceObstacles(const Box2& region)
      : line_grid(region, kGridCell_mm),
        label_grid(region, kGridCell_mm),
        triangle_grid(region, kGridCell_mm) {}
};

Box2 piece_region(const ScaledPiece& piece) {
  Box2 b;
  for (const Triangle2& t : piece.triangles_mm)
    for (Vec2 v : t)
      b.add(v);
  return Box2{b.min - Vec2{kGridBorder_mm, kGridBorder_mm}, b.max + Vec2{kGridBorder_mm, kGridBorder_mm}};
}

Box2 grown(Box2 b, double d) {
  return Box2{b.min - Vec2{d, d}, b.max + Vec2{d, d}};
}

Polygon label_box(Vec2 at, Vec2 dir, double width, double height) {
  const Vec2 up = perp_ccw(dir);
  return {at, at + dir * width, at + dir * width + up * height, at + up * height};
}

}  // namespace

double label_width_mm(const std::string& text, double height_mm, const LabelOptions& options) {
  // Advances in digit widths, the larger of DejaVu Sans (print) and Hershey futural (pen): a period is
  // under half a digit, a space 0.8 (Hershey's is wide), capitals about one (I narrow, M and W wide).
  double digits = 0;
  for (char c : text) {
    if (c == '.') {
      digits += 0.47;
    } else if (c == ' ') {
      digits += 0.8;
    } else if (c == '(' || c == ')') {
      digits += 0.71;
    } else if (c == 'I') {
      digits += 0.5;
    } else if (c == 'M' || c == 'W') {
      digits += 1.45;
    } else if (c >= 'A' && c <= 'Z') {
      digits += 1.1;
    } else {
      digits += 1;
    }
  }
  return digits * options.char_width * height_mm;
}

std::vector<int> number_seams(std::span<const ScaledPiece> pieces, std::span<const Seam> seams) {
  std::vector<int> seam_at_edge;
  for (std::size_t s = 0; s < seams.size(); ++s) {
    if (seams[s].edge >= static_cast<int>(seam_at_edge.size())) seam_at_edge.resize(seams[s].edge + 1, -1);
    seam_at_edge[seams[s].edge] = static_cast<int>(s);
  }
  std::vector<int> number(seams.size(), 0);
  int next = 1;
  for (const ScaledPiece& piece : pieces)
    for (const OutlineLoop& loop : piece.outline_mm)
      for (const OutlineEdge& e : loop) {
        if (e.edge >= static_cast<int>(seam_at_edge.size())) continue;
        const int s = seam_at_edge[e.edge];
        if (s >= 0 && number[s] == 0) number[s] = next++;
      }
  // Seams missing from every outline cannot happen for a valid unfolding; number them anyway.
  for (int& n : number)
    if (n == 0) n = next++;
  return number;
}

std::vector<Label> place_labels(std::span<const ScaledPiece> pieces, std::span<const Seam> seams,
                                std::span<const int> numbers, const TabPlan& tabs,
                                std::span<const std::vector<FoldLine>> fold_lines,
                                std::span<const std::string> hints, const LabelOptions& o,
                                std::span<const std::array<std::string, 2>> texts,
                                std::span<const std::vector<Polygon>> taken) {
  std::vector<PieceObstacles> obstacles;
  obstacles.reserve(pieces.size());
  for (std::size_t p = 0; p < pieces.size(); ++p) {
    obstacles.emplace_back(piece_region(pieces[p]));
    PieceObstacles& ob = obstacles.back();
    auto add = [&](Vec2 a, Vec2 b, bool fold) {
      Box2 box;
      box.add(a);
      box.add(b);
      ob.line_grid.insert(static_cast<int>(ob.lines.size()), box);
      ob.lines.push_back({a, b, box, fold});
    };
    for (const OutlineLoop& loop : pieces[p].outline_mm)
      for (const OutlineEdge& e : loop)
        add(e.a, e.b, false);
    if (p < fold_lines.size())
      for (const FoldLine& f : fold_lines[p])
        add(f.a, f.b, true);
    for (std::size_t t = 0; t < pieces[p].triangles_mm.size(); ++t)
      ob.triangle_grid.insert(static_cast<int>(t), bounds_of(pieces[p].triangles_mm[t]));
    if (p < taken.size())
      for (const Polygon& area : taken[p]) {
        ob.label_grid.insert(static_cast<int>(ob.labels.size()), bounds_of(area));
        ob.labels.push_back(area);
        ob.label_active.push_back(true);
      }
  }

  // level 0: clear of every line and label; 1: may cross fold lines; 2: may touch the outline too.
  auto clear_of_everything = [&](int p, const Polygon& box, int level) {
    const Box2 reach = grown(bounds_of(box), o.clearance_mm);
    const PieceObstacles& ob = obstacles[p];
    if (level < 2) {
      const bool clear_of_lines = ob.line_grid.visit(reach, [&](int i) {
        const Segment& s = ob.lines[i];
        if (level >= 1 && s.fold) return true;
        const std::array<Vec2, 2> seg{s.a, s.b};
        return !convex_overlap(box, seg, -o.clearance_mm);
      });
      if (!clear_of_lines) return false;
    }
    return ob.label_grid.visit(reach, [&](int k) {
      return !ob.label_active[k] || !convex_overlap(box, ob.labels[k], -o.clearance_mm);
    });
  };
  auto inside_piece = [&](int p, Vec2 point) {
    const Box2 at{point, point};
    return !obstacles[p].triangle_grid.visit(
        at, [&](int t) { return !inside_convex(pieces[p].triangles_mm[t], point, 0); });
  };

  std::vector<Label> labels;
  for (std::size_t s = 0; s < seams.size(); ++s) {
    const std::string number = number_text(numbers[s]);
    const std::string hint = s < hints.size() ? hints[s] : std::string();
    // The side with a tab first: its label has room there for the hint. The hint may be dropped on a
    // crowded side, but every seam keeps its step on one side at least.
    const auto& seam_tab = tabs.tab_of_seam.size() > s ? tabs.tab_of_seam[s] : std::nullopt;
    const int first = seam_tab && seam_tab->side == 1 ? 1 : 0;
    auto place = [&](int k, bool may_drop_hint) -> std::optional<Label> {
      const SeamSide& side = seams[s].sides[k];
      if (side.piece < 0) return std::nullopt;
      const OutlineEdge& e = pieces[side.piece].outline_mm[side.loop][side.index];
      const double length = norm(e.b - e.a);
      if (length <= 0) return std::nullopt;
      Label label;
      label.seam = static_cast<int>(s);
      label.side = k;
      label.piece = side.piece;
      const std::string& text = s < texts.size() ? texts[s][k] : number;
      label.text = text;
      label.hint = hint;
      // With an assembly hint, the hint goes first when the side is crowded: the step is also in the
      // assembly list, and a number clear of every line matters more.
      auto full_width = [&](double h, bool with_hint) {
        double w = label_width_mm(text, h, o);
        if (with_hint && !hint.empty()) w += 0.3 * h + label_width_mm(hint, 0.75 * h, o);
        return w;
      };
      std::vector<bool> hint_choices{true};
      if (may_drop_hint) hint_choices.push_back(false);
      const double preferred = std::clamp(o.per_length * length, o.min_mm, o.max_mm);
      // Largest first: a label as big as its edge allows is the easiest to find.
      std::vector<double> heights;
      for (double h = preferred; h > o.min_mm + 1e-9; h *= 0.85)
        heights.push_back(h);
      heights.push_back(o.min_mm);
      bool placed = false;

      const auto& tab = tabs.tab_of_seam.size() > s ? tabs.tab_of_seam[s] : std::nullopt;
      if (tab && tab->side == k) {
        // On the tab: read from the outside, foot on the edge.
        // The tab may cover only part of the edge: centre on its base.
        const Vec2 dir = normalized(e.a - e.b);
        const Vec2 mid = 0.5 * (tab->quad_mm[0] + tab->quad_mm[3]);
        const double tallest = tab->width_mm - o.gap_mm - o.clearance_mm;
        for (bool with_hint : hint_choices)
          for (double h : heights) {
            if (h > tallest || placed) continue;
            const double w = full_width(h, with_hint);
            const Vec2 at = mid - dir * (0.5 * w) + perp_ccw(dir) * o.gap_mm;
            Polygon box = label_box(at, dir, w, h);
            bool inside = true;
            for (Vec2 c : box)
              inside = inside && inside_convex(tab->quad_mm, c, o.clearance_mm * 0.5);
            if (!inside) continue;
            label = Label{label.seam, k, side.piece, text,  at,
                          dir,        h, true,       false, with_hint ? hint : std::string(),
                          box};
            placed = true;
          }
      }
      if (!placed) {
        const Vec2 dir = normalized(e.b - e.a), up = perp_ccw(dir);
        static constexpr std::array<double, 9> kAlong{0.5, 0.4, 0.6, 0.3, 0.7, 0.2, 0.8, 0.12, 0.88};
        // Clear of every line first (with the hint, then without it); then, rather than shrink below the
        // legible minimum or pile onto another label, across a fold line; then touching the outline.
        struct Try {
          int level;
          bool with_hint;
        };
        std::vector<Try> tries{{0, true}};
        if (may_drop_hint) tries.push_back({0, false});
        const bool hint_last = !may_drop_hint;
        tries.push_back({1, hint_last});
        tries.push_back({2, hint_last});
        for (const Try& attempt : tries) {
          const int level = attempt.level;
          for (double h : heights) {
            if (placed) break;
            const double w = full_width(h, attempt.with_hint);
            for (double lift : {o.gap_mm, o.gap_mm + 0.4 * h, o.gap_mm + 0.9 * h}) {
              for (double t : kAlong) {
                const Vec2 at = e.a + dir * (t * length - 0.5 * w) + up * lift;
                Polygon box = label_box(at, dir, w, h);
                const Vec2 centre = at + dir * (0.5 * w) + up * (0.5 * h);
                if (!inside_piece(side.piece, centre) || !clear_of_everything(side.piece, box, level))
                  continue;
                label = Label{label.seam, k, side.piece, text,  at,
                              dir,        h, false,      false, attempt.with_hint ? hint : std::string(),
                              box};
                label.over_fold = level == 1;
                label.crowded = level == 2;
                placed = true;
                break;
              }
              if (placed) break;
            }
          }
        }
        if (!placed) {
          const double h = o.min_mm, w = full_width(h, hint_last);
          const Vec2 at = 0.5 * (e.a + e.b) - dir * (0.5 * w) + up * o.gap_mm;
          label = Label{label.seam,
                        k,
                        side.piece,
                        text,
                        at,
                        dir,
                        h,
                        false,
                        true,
                        hint_last ? hint : std::string(),
                        label_box(at, dir, w, h)};
        }
      }
      return label;
    };
    // How far a label is from clear: on the tab or clear of every line, across a fold, touching.
    auto cost = [](const std::optional<Label>& l) { return !l ? 0 : l->crowded ? 2 : l->over_fold ? 1 : 0; };
    auto shows_hint = [](const std::optional<Label>& l) { return l && !l->hint.empty(); };
    auto commit = [&](const std::optional<Label>& l) {
      if (!l) return;
      PieceObstacles& ob = obstacles[l->piece];
      ob.label_grid.insert(static_cast<int>(ob.labels.size()), bounds_of(l->box_mm));
      ob.labels.push_back(l->box_mm);
      ob.label_active.push_back(true);
      labels.push_back(*l);
    };
    auto retract = [&](const std::optional<Label>& l) {
      if (!l) return;
      // The grid cannot forget an item: the retracted label is switched off instead.
      obstacles[l->piece].label_active[obstacles[l->piece].labels.size() - 1] = false;
      labels.pop_back();
    };
    const int second = 1 - first;
    std::optional<Label> a = place(first, !hint.empty());
    commit(a);
    std::optional<Label> b = place(second, !hint.empty() && shows_hint(a));
    if (!hint.empty() && !shows_hint(a) && cost(b) > 0) {
      // The first side dropped the step and the second is crowded with it: keep the step on whichever
      // side suffers least from it (crossing a fold line is fine), or, when a number would touch the
      // outline or another label either way, on neither (the assembly list still has it).
      std::optional<Label> b_free = place(second, true);
      retract(a);
      std::optional<Label> a2 = place(first, false);
      commit(a2);
      std::optional<Label> b2 = place(second, true);
      const int with_a = cost(a) + cost(b), with_a2 = cost(a2) + cost(b2), with_none = cost(a) + cost(b_free);
      if (with_a2 < with_a && with_a2 <= with_none) {
        a = std::move(a2);
        b = std::move(b2);
      } else {
        retract(a2);
        commit(a);
        if (std::min(with_a, with_a2) >= 2 && with_none < std::min(with_a, with_a2)) b = std::move(b_free);
      }
    }
    commit(b);
  }
  return labels;
}

}  // namespace foldkit::layout
