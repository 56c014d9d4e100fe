#include "foldkit/layout/edge_numbers.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <utility>

#include "foldkit/geom/parallel.hpp"
#include "foldkit/layout/box_grid.hpp"
#include "foldkit/layout/label_text.hpp"

namespace foldkit::layout {
namespace {

// Grid cells of about a label's size: a query looks at a handful of cells.
constexpr double kGridCell_mm = 4;
// Labels may sit on tabs or stick out of tiny faces: the grid covers that much around the piece.
constexpr double kGridBorder_mm = 20;
// Each smaller label size tried is this share of the previous one.
constexpr double kShrinkStep = 0.85;
// How far a label may be lifted off its edge, in label heights: a small label (up to kSmallLabel times
// the least size) a little farther, since it stays close to its edge in absolute terms.
constexpr double kSmallLabel = 1.2;
constexpr double kHighestLiftSmall = 1.5, kHighestLift = 0.9;
// The lifts tried between the edge and the highest, in label heights (above the gap); the highest
// last. Finer steps find the spot between a neighbour's label and the apex of a small face.
constexpr double kMiddleLift = 0.4;
constexpr std::array<double, 6> kLifts{0, 0.2, kMiddleLift, 0.65, kHighestLift, kHighestLiftSmall};
constexpr std::array<double, 4> kCoarseLifts{0, kMiddleLift, kHighestLift, kHighestLiftSmall};
// Across a needle's short edge: at the gap, and lifted by half a label height past a neighbour's label.
constexpr std::array<double, 2> kAcrossLifts{0, 0.5};
// A leader's spots: rings this far apart around the edge's middle, each tried in these directions
// (turned from straight into the face, alternately either way); its bar along the edge this long, at
// most this share of the edge.
constexpr double kLeaderStep_mm = 1.0;
// A gap between two lines that meet at a small face's apex is often narrower than the next turn: the
// turns come a quarter radian apart up to the edge's direction.
constexpr std::array<double, 15> kLeaderTurns_rad{0,    0.25, -0.25, 0.5,  -0.5,  0.75, -0.75, 1.0,
                                                  -1.0, 1.3,  -1.3,  1.57, -1.57, 2.1,  -2.1};
constexpr double kLeaderBar_mm = 1.6, kLeaderBarShare = 0.4;
// Rounds over the labels that find no clear spot, each moving to where it runs into the least.
constexpr int kCrowdedRounds = 2;
// A label with no clear spot may take one where at most this many labels stand, each moving elsewhere,
// trying this many such spots at most.
constexpr std::size_t kMostLabelsMoved = 2;
constexpr std::size_t kMostSpotsFreed = 6;
// Spots on leaders freed the same way: more of them, since a leader reaches farther than the edge. At 16
// the worst 8 meshes at 150 mm left 349 labels unclear, at 6 358; 32 and 64 gained nothing more.
constexpr std::size_t kMostLeaderSpotsFreed = 16;

Box2 piece_region(const ScaledPiece& piece) {
  Box2 b;
  for (const Triangle2& t : piece.triangles_mm)
    for (Vec2 v : t)
      b.add(v);
  return grown(b, kGridBorder_mm);
}

// The width the face beside `edge` leaves next to a label of `width` at the minimum height: a triangle
// narrows linearly from the edge towards its apex.
double face_room_mm(const ScaledPiece& piece, const OutlineEdge& edge, double width, const LabelOptions& o) {
  const double length = norm(edge.b - edge.a);
  const auto k = std::lower_bound(piece.faces.begin(), piece.faces.end(), edge.face) - piece.faces.begin();
  if (k >= static_cast<std::ptrdiff_t>(piece.faces.size()) || !(length > 0)) return 0;
  const double height = 2 * std::fabs(signed_area(piece.triangles_mm[k])) / length;
  const double top = o.gap_mm + o.min_mm + o.clearance_mm;
  return length * (1 - top / std::max(height, 1e-9)) - width;
}

Polygon label_box(Vec2 at, Vec2 dir, double width, double height) {
  const Vec2 up = perp_ccw(dir);
  return {at, at + dir * width, at + dir * width + up * height, at + up * height};
}

}  // namespace

double label_width_mm(const std::string& text, double height_mm, const LabelOptions& options) {
  // Advances in digit widths of Liberation Sans Narrow: a period and a space are half a digit,
  // brackets 0.6, capitals 1.2 (I 0.5, M 1.5, W 1.7), lower case as a digit.
  double digits = 0;
  for (char c : text) {
    if (c == '.' || c == ' ') {
      digits += 0.5;
    } else if (c == '(' || c == ')') {
      digits += 0.6;
    } else if (c == 'I') {
      digits += 0.5;
    } else if (c == 'M') {
      digits += 1.5;
    } else if (c == 'W') {
      digits += 1.7;
    } else if (c >= 'A' && c <= 'Z') {
      digits += 1.2;
    } else {
      digits += 1;
    }
  }
  return digits * options.char_width * height_mm;
}

double label_width_mm(const std::string& text, const std::string& hint, double height_mm,
                      const LabelOptions& options) {
  double w = label_width_mm(text, height_mm, options);
  if (!hint.empty())
    w += options.hint_gap_share * height_mm +
         label_width_mm(hint, options.hint_height_share * height_mm, options);
  return w;
}

double label_descent_mm(const std::string& text, double height_mm) {
  // Below the baseline: DejaVu Sans "p" 0.21 em (0.29 of its 0.73 em cap height), Hershey futural 7 of
  // 21 units; brackets 0.13 em (0.18) and 4 of 21.
  constexpr double kDescender = 0.34, kBracket = 0.2;
  if (text.find('p') != std::string::npos) return kDescender * height_mm;
  if (text.find_first_of("()") != std::string::npos) return kBracket * height_mm;
  return 0;
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

namespace {

// How wide number `n` prints, in mm per mm of cap height: a marked "6." is narrower than "12", wider
// than "5".
double printed_width(int n) {
  return label_width_mm(number_text(n), 1, LabelOptions{});
}

}  // namespace

std::vector<int> number_seams_by_part(std::span<const Seam> seams, std::span<const int> outline_numbers,
                                      std::span<const double> room_mm) {
  std::map<std::pair<int, int>, std::vector<std::size_t>> of_pair;
  for (std::size_t s = 0; s < seams.size(); ++s) {
    const int a = seams[s].sides[0].piece, b = seams[s].sides[1].piece;
    of_pair[{std::min(a, b), std::max(a, b)}].push_back(s);
  }
  std::vector<int> number(seams.size(), 0);
  std::vector<double> width(seams.size(), 0);
  for (auto& [pair, group] : of_pair) {
    // The count's numbers, narrowest print first; the k-th tightest seam takes the k-th one's width.
    std::vector<int> narrowest_first(group.size());
    std::iota(narrowest_first.begin(), narrowest_first.end(), 1);
    if (room_mm.size() == seams.size()) {
      std::stable_sort(narrowest_first.begin(), narrowest_first.end(),
                       [](int a, int b) { return printed_width(a) < printed_width(b) - 1e-9; });
      std::vector<std::size_t> tightest_first = group;
      std::stable_sort(tightest_first.begin(), tightest_first.end(),
                       [&](std::size_t a, std::size_t b) { return room_mm[a] < room_mm[b]; });
      for (std::size_t k = 0; k < tightest_first.size(); ++k)
        width[tightest_first[k]] = printed_width(narrowest_first[k]);
    }
    // Within one width, the numbers rise along the outline.
    std::stable_sort(group.begin(), group.end(), [&](std::size_t a, std::size_t b) {
      if (std::fabs(width[a] - width[b]) > 1e-9) return width[a] < width[b];
      return outline_numbers[a] < outline_numbers[b];
    });
    for (std::size_t k = 0; k < group.size(); ++k)
      number[group[k]] = narrowest_first[k];
  }
  return number;
}

std::vector<double> seam_label_room_mm(std::span<const ScaledPiece> pieces, std::span<const Seam> seams,
                                       const LabelOptions& options) {
  std::vector<double> room(seams.size(), std::numeric_limits<double>::infinity());
  for (std::size_t s = 0; s < seams.size(); ++s)
    for (const SeamSide& at : seams[s].sides) {
      if (at.piece < 0) continue;
      const ScaledPiece& piece = pieces[at.piece];
      room[s] = std::min(room[s], face_room_mm(piece, piece.outline_mm[at.loop][at.index], 0, options));
    }
  return room;
}

std::vector<int> tab_sides_for_labels(std::span<const ScaledPiece> pieces, std::span<const Seam> seams,
                                      std::span<const double> widths_mm, const LabelOptions& options) {
  std::vector<int> side(seams.size(), -1);
  for (std::size_t s = 0; s < seams.size() && s < widths_mm.size(); ++s) {
    std::array<bool, 2> room{};
    bool both_sides = true;
    for (int k = 0; k < 2; ++k) {
      const SeamSide& at = seams[s].sides[k];
      both_sides = both_sides && at.piece >= 0;
      if (at.piece < 0) break;
      const ScaledPiece& piece = pieces[at.piece];
      room[k] = face_room_mm(piece, piece.outline_mm[at.loop][at.index], widths_mm[s], options) >= 0;
    }
    if (both_sides && room[0] != room[1]) side[s] = room[0] ? 1 : 0;
  }
  return side;
}

namespace {

// How far a label is from clear, in the order placement gives in: clear of every line and label; clear
// of them by less (the tight clearance: the ink still keeps off the text); clear but away from its edge,
// tied to it by a leader; across a fold line; touching the outline too; nowhere clear (where it runs
// into the least).
enum class Clearance { Clear, Tight, Leader, OverFold, OverOutline, Nowhere };

// What a label says, most informative first: the full text (with the mate's sheet) or the short one,
// each with the step mark or without it.
struct Form {
  bool full_text = true;
  bool with_hint = true;
};
constexpr std::array<Form, 4> kForms{{{true, true}, {true, false}, {false, true}, {false, false}}};

// One side of a seam to label, and what it has got so far.
struct SideTask {
  int seam = -1, side = 0, piece = -1;
  const OutlineEdge* edge = nullptr;
  const Tab* tab = nullptr;  // the seam's tab when this side carries it
  double length_mm = 0;
  std::string full, brief;  // the texts it may print (equal when there is nothing to leave out)
  double room_mm = 0;       // width left beside the label at the legible minimum: the smaller, the harder
  std::optional<Label> label;
  Clearance clearance = Clearance::Nowhere;
  std::size_t form = kForms.size() - 1;
  bool step_side = false;  // the side that shows the seam's step mark where it can (the one with the tab)
  int slot = -1;           // the label's obstacle in its piece
  std::vector<int> leader_slots;  // its leader's segments among the piece's obstacles (fixed ones)
};

// Places the labels in three rounds, so that no label takes the room another needs to be legible:
// every label at the legible minimum clear of everything, the sides with the least room first; then the
// ones left over at the tight clearance, or by moving labels in their way, or on a leader, or across a
// fold line (beside the edge, then on a leader), or, failing all that, touching the outline (the same);
// then each grows (its full text, its step mark, a larger size) where the room allows. A label that
// stands off across lines is still read: one over another text hides both (plane_500 at 150 mm: labels
// touching another 67 -> 40).
class LabelPlacer {
 public:
  LabelPlacer(std::span<const ScaledPiece> pieces, std::span<const Seam> seams, const TabPlan& tabs,
              std::span<const std::vector<FoldLine>> fold_lines, std::span<const std::string> hints,
              const LabelOptions& options, const SeamTexts& texts,
              std::span<const std::vector<Polygon>> taken, std::span<const int> only_pieces)
      : pieces_(pieces),
        seams_(seams),
        hints_(hints),
        o_(options),
        placing_(pieces.size(), only_pieces.empty()) {
    for (int p : only_pieces)
      placing_.at(static_cast<std::size_t>(p)) = true;
    build_obstacles(fold_lines, taken);
    collect_sides(tabs, texts);
  }

  std::vector<Label> run() {
    std::vector<std::size_t> hardest_first(sides_.size());
    std::iota(hardest_first.begin(), hardest_first.end(), 0);
    std::stable_sort(hardest_first.begin(), hardest_first.end(),
                     [&](std::size_t a, std::size_t b) { return sides_[a].room_mm < sides_[b].room_mm; });
    for (std::size_t i : hardest_first)
      try_at_minimum(sides_[i], Clearance::Clear);
    for (std::size_t i : hardest_first)
      if (!sides_[i].label) try_at_minimum(sides_[i], Clearance::Tight);
    for (std::size_t i : hardest_first)
      if (!sides_[i].label) place_by_moving_others(sides_[i]);
    for (Clearance level : {Clearance::Clear, Clearance::Tight})
      place_on_leaders(hardest_first, level, Clearance::Leader);
    if (o_.leader_search == LeaderSearch::Thorough)
      for (std::size_t i : hardest_first)
        if (!sides_[i].label) place_on_leader_by_moving_others(sides_[i]);
    for (Clearance level : {Clearance::OverFold, Clearance::OverOutline}) {
      for (std::size_t i : hardest_first)
        if (!sides_[i].label) try_at_minimum(sides_[i], level);
      place_on_leaders(hardest_first, level, level);
    }
    std::vector<std::size_t> crowded;
    for (std::size_t i = 0; i < sides_.size(); ++i)
      if (!sides_[i].label) crowded.push_back(i);
    // Each spot is chosen seeing only the labels placed before it: a second round lets the earlier
    // ones move away from the later.
    for (int round = 0; round < kCrowdedRounds; ++round)
      for (std::size_t i : crowded)
        place_least_crowded(sides_[i]);
    for (SideTask& side : sides_)
      grow(side);
    if (!hints_.empty()) show_every_step();
    std::vector<Label> labels;
    for (SideTask& side : sides_)
      labels.push_back(std::move(*side.label));
    return labels;
  }

 private:
  struct Segment {
    Vec2 a, b;
    bool fold = false;  // fold lines may be crossed when nothing else is left; outlines never
  };
  // What a label in one piece must keep clear of, found through grids so that a query costs what is
  // near it, not the whole piece.
  struct PieceObstacles {
    std::vector<Segment> lines;
    std::vector<Polygon> labels;
    std::vector<bool> label_active;  // moved labels stay in the grid, switched off
    std::vector<int> side_of_label;  // the SideTask (index) a label belongs to, -1 for taken areas
    BoxGrid line_grid, label_grid, triangle_grid;
    explicit PieceObstacles(const Box2& region)
        : line_grid(region, kGridCell_mm),
          label_grid(region, kGridCell_mm),
          triangle_grid(region, kGridCell_mm) {}
  };

  void build_obstacles(std::span<const std::vector<FoldLine>> fold_lines,
                       std::span<const std::vector<Polygon>> taken) {
    obstacles_.reserve(pieces_.size());
    for (std::size_t p = 0; p < pieces_.size(); ++p) {
      obstacles_.emplace_back(placing_[p] ? piece_region(pieces_[p]) : Box2{});
      if (!placing_[p]) continue;
      PieceObstacles& ob = obstacles_.back();
      auto add = [&](Vec2 a, Vec2 b, bool fold) {
        Box2 box;
        box.add(a);
        box.add(b);
        ob.line_grid.insert(static_cast<int>(ob.lines.size()), box);
        ob.lines.push_back({a, b, fold});
      };
      for (const OutlineLoop& loop : pieces_[p].outline_mm)
        for (const OutlineEdge& e : loop)
          add(e.a, e.b, false);
      if (p < fold_lines.size())
        for (const FoldLine& f : fold_lines[p])
          add(f.a, f.b, true);
      for (std::size_t t = 0; t < pieces_[p].triangles_mm.size(); ++t)
        ob.triangle_grid.insert(static_cast<int>(t), bounds_of(pieces_[p].triangles_mm[t]));
      if (p < taken.size())
        for (const Polygon& area : taken[p])
          add_label_obstacle(static_cast<int>(p), area);
    }
  }

  void collect_sides(const TabPlan& tabs, const SeamTexts& texts) {
    for (std::size_t s = 0; s < seams_.size(); ++s) {
      // The side with a tab first: its label has room there for the step mark.
      const int first = first_labelled_side(tabs, s);
      for (int k : {first, 1 - first}) {
        const SeamSide& at = seams_[s].sides[k];
        if (at.piece < 0 || !placing_[at.piece]) continue;
        SideTask side;
        side.seam = static_cast<int>(s);
        side.side = k;
        side.piece = at.piece;
        side.edge = &pieces_[at.piece].outline_mm[at.loop][at.index];
        side.length_mm = norm(side.edge->b - side.edge->a);
        if (!(side.length_mm > 0)) continue;
        side.tab = tabs.on_side(s, k);
        side.step_side = k == first;
        side.full = texts.full[s][k];
        side.brief = s < texts.brief.size() ? texts.brief[s][k] : side.full;
        side.room_mm =
            face_room_mm(pieces_[side.piece], *side.edge, label_width_mm(side.brief, o_.min_mm, o_), o_);
        sides_.push_back(std::move(side));
      }
    }
  }

  const std::string& hint_of(const SideTask& side) const {
    static const std::string none;
    return static_cast<std::size_t>(side.seam) < hints_.size() ? hints_[side.seam] : none;
  }
  const std::string& text_of(const SideTask& side, const Form& f) const {
    return f.full_text ? side.full : side.brief;
  }
  // Whether forms print the same (no step mark to leave out, no sheet to drop): each is tried once.
  bool prints_alike(const SideTask& side, std::size_t a, std::size_t b) const {
    const Form &f = kForms[a], &g = kForms[b];
    const bool same_text = f.full_text == g.full_text || side.brief == side.full;
    const bool same_hint = f.with_hint == g.with_hint || hint_of(side).empty();
    return same_text && same_hint;
  }
  bool tried_before(const SideTask& side, std::span<const std::size_t> forms, std::size_t i) const {
    for (std::size_t j = 0; j < i; ++j)
      if (prints_alike(side, forms[i], forms[j])) return true;
    return false;
  }

  double full_width(const SideTask& side, double h, const Form& f) const {
    static const std::string none;
    return label_width_mm(text_of(side, f), f.with_hint ? hint_of(side) : none, h, o_);
  }

  // Largest first: a label as big as its edge allows is the easiest to find.
  std::vector<double> heights_down_to(const SideTask& side, double lowest) const {
    const double preferred = std::clamp(o_.per_length * side.length_mm, o_.min_mm, o_.max_mm);
    std::vector<double> heights;
    for (double h = preferred; h > lowest + 1e-9; h *= kShrinkStep)
      heights.push_back(h);
    heights.push_back(lowest);
    return heights;
  }

  double clearance_at(Clearance level) const {
    return level == Clearance::Tight ? o_.tight_clearance_mm : o_.clearance_mm;
  }

  // level Clear: clear of every line and label; Tight: the same by the tight clearance; OverFold: may
  // cross fold lines; OverOutline: may touch the outline too, but never another label.
  bool clear_of_everything(int p, const Polygon& box, Clearance level) const {
    const double clearance = clearance_at(level);
    if (level < Clearance::OverOutline && !clear_of_lines(p, box, clearance, level >= Clearance::OverFold))
      return false;
    return clear_of_labels(p, box, clearance);
  }
  // Clear of the outline and, unless `over_folds`, of the fold lines.
  bool clear_of_lines(int p, const Polygon& box, double clearance, bool over_folds = false) const {
    const PieceObstacles& ob = obstacles_[p];
    return ob.line_grid.visit(grown(bounds_of(box), clearance), [&](int i) {
      const Segment& s = ob.lines[i];
      if (over_folds && s.fold) return true;
      const std::array<Vec2, 2> seg{s.a, s.b};
      return !convex_overlap(box, seg, -clearance);
    });
  }
  bool clear_of_labels(int p, const Polygon& box, double clearance) const {
    const Box2 reach = grown(bounds_of(box), clearance);
    const PieceObstacles& ob = obstacles_[p];
    return ob.label_grid.visit(
        reach, [&](int k) { return !ob.label_active[k] || !convex_overlap(box, ob.labels[k], -clearance); });
  }
  bool inside_piece(int p, Vec2 point) const {
    const Box2 at{point, point};
    return !obstacles_[p].triangle_grid.visit(
        at, [&](int t) { return !inside_convex(pieces_[p].triangles_mm[t], point, 0); });
  }

  // The box a label of form `f` at cap height `h` covers: its length, and its height with the
  // descenders ("p2") below the baseline.
  struct Extent {
    double width_mm = 0, height_mm = 0;
  };
  Extent extent(const SideTask& side, double h, const Form& f) const {
    static const std::string none;
    const std::string& hint = f.with_hint ? hint_of(side) : none;
    const double descent =
        std::max(label_descent_mm(text_of(side, f), h), label_descent_mm(hint, o_.hint_height_share * h));
    return {full_width(side, h, f), h + descent};
  }

  // The label whose box has its foot at `at`.
  Label make_label(const SideTask& side, Vec2 at, Vec2 dir, double h, const Form& f, bool on_tab) const {
    Label label;
    label.seam = SeamId{side.seam};
    label.side = side.side;
    label.piece = side.piece;
    label.text = text_of(side, f);
    label.dir = dir;
    label.height_mm = h;
    label.on_tab = on_tab;
    if (f.with_hint) label.hint = hint_of(side);
    const Extent e = extent(side, h, f);
    label.at_mm = at + perp_ccw(dir) * (e.height_mm - h);
    label.box_mm = label_box(at, dir, e.width_mm, e.height_mm);
    return label;
  }

  // On the tab: read from the outside, foot on the fold. The tab may cover only part of the edge, and
  // its slanted ends leave most room at its middle: centred on its base first.
  std::optional<Label> on_tab(const SideTask& side, double h, const Form& f, Clearance level) const {
    const Tab& tab = *side.tab;
    if (h > tab.width_mm - o_.gap_mm - o_.clearance_mm) return std::nullopt;
    const Vec2 dir = normalized(side.edge->a - side.edge->b);
    const Vec2 base_a = tab.quad_mm[3], base_b = tab.quad_mm[0];  // along dir
    const double base = norm(base_b - base_a), w = full_width(side, h, f);
    if (w > base) return std::nullopt;
    for (double t : {0.5, 0.4, 0.6, 0.3, 0.7}) {
      const Vec2 at = base_a + dir * (t * base - 0.5 * w) + perp_ccw(dir) * o_.gap_mm;
      Label label = make_label(side, at, dir, h, f, true);
      bool inside = true;
      for (Vec2 c : label.box_mm)
        inside = inside && inside_convex(tab.quad_mm, c, o_.clearance_mm * 0.5);
      if (inside && clear_of_labels(side.piece, label.box_mm, clearance_at(level))) return label;
    }
    return std::nullopt;
  }

  // Inside the piece along the edge, foot towards it: slid along the edge and lifted off it.
  std::optional<Label> on_face(const SideTask& side, double h, const Form& f, Clearance level) const {
    static constexpr std::array<double, 21> kAlong{0.5,  0.45, 0.55, 0.4,  0.6,  0.35, 0.65,
                                                   0.3,  0.7,  0.25, 0.75, 0.2,  0.8,  0.16,
                                                   0.84, 0.12, 0.88, 0.08, 0.92, 0.04, 0.96};
    const OutlineEdge& e = *side.edge;
    const Vec2 dir = normalized(e.b - e.a), up = perp_ccw(dir);
    const Extent ext = extent(side, h, f);
    const double w = ext.width_mm;
    // Lifted off the edge by up to a label's height (a small one a little more): farther, it would not
    // read as the edge's.
    const double highest = o_.gap_mm + (h <= kSmallLabel * o_.min_mm ? kHighestLiftSmall : kHighestLift) * h;
    // At the legible minimum, where a label has no smaller size to fall back on, every lift; larger, the
    // coarse ones (growing tries each size).
    const std::span<const double> lifts =
        h <= o_.min_mm + 1e-9 ? std::span<const double>(kLifts) : std::span<const double>(kCoarseLifts);
    for (double lift : lifts) {
      lift = std::min(o_.gap_mm + lift * h, highest);
      for (double t : kAlong) {
        const Vec2 at = e.a + dir * (t * side.length_mm - 0.5 * w) + up * lift;
        const Vec2 centre = at + dir * (0.5 * w) + up * (0.5 * h);
        if (!inside_piece(side.piece, centre)) continue;
        if (clear_of_everything(side.piece, label_box(at, dir, w, ext.height_mm), level))
          return make_label(side, at, dir, h, f, false);
      }
    }
    return std::nullopt;
  }

  // Across the edge, reading away from it into the face: where the face is a needle on a short edge,
  // the only way a label fits clear of its lines. Tried after every spot along the edge.
  std::optional<Label> across_face(const SideTask& side, double h, const Form& f, Clearance level) const {
    static constexpr std::array<double, 9> kAt{0.5, 0.35, 0.65, 0.2, 0.8, 0.1, 0.9, 0.05, 0.95};
    const OutlineEdge& e = *side.edge;
    const Vec2 dir = normalized(e.b - e.a), into = perp_ccw(dir);
    const Extent ext = extent(side, h, f);
    const double w = ext.width_mm;
    for (double lift : kAcrossLifts)
      for (double t : kAt) {
        // Glyphs grow towards perp_ccw(into) = -dir: the foot at +h/2 puts the text astride the point.
        const Vec2 at = e.a + dir * (t * side.length_mm + 0.5 * h) + into * (o_.gap_mm + lift * h);
        const Vec2 centre = at + into * (0.5 * w) - dir * (0.5 * h);
        if (!inside_piece(side.piece, centre)) continue;
        if (clear_of_everything(side.piece, label_box(at, into, w, ext.height_mm), level))
          return make_label(side, at, into, h, f, false);
      }
    return std::nullopt;
  }

  // On the tab where the side has one (the face keeps its room for the other labels), else on the face.
  // A label that has its tab keeps it: it grows only there.
  std::optional<Label> find(const SideTask& side, double h, const Form& f, Clearance level) const {
    if (side.tab)
      if (auto label = on_tab(side, h, f, level)) return label;
    if (side.label && side.label->on_tab) return std::nullopt;
    return on_face(side, h, f, level);
  }

  // Away from the edge, tied to it by a leader: the label at the legible minimum, parallel to its edge,
  // its box's nearest point up to leader_reach_mm from just inside the edge's middle, the nearest spot
  // first and into the face before away from it. The leader keeps inside the piece (clear of the
  // outline) and off every label; it may cross fold lines, thin and dotted across them.
  std::optional<Label> with_leader(const SideTask& side, Clearance level) const {
    std::optional<Label> found;
    for_each_leader_spot(side, level, Past::Nothing, [&](Label label) {
      found = std::move(label);
      return true;
    });
    return found;
  }
  // What a leader's spot may have in its way: nothing but fold lines, or other labels too (which would
  // have to move).
  enum class Past { Nothing, Labels };
  // The spots of with_leader in its order, each whose label and leader keep clear of the outline and of
  // the lines `level` keeps clear of (and, unless `past` is Labels, of every label): `consider(label)`,
  // the leader set, until it returns true.
  template <class Consider>
  void for_each_leader_spot(const SideTask& side, Clearance level, Past past, Consider&& consider) const {
    if (!(o_.leader_reach_mm > 0)) return;
    const auto way_clear = [&](const std::array<Vec2, 2>& segment) {
      if (past == Past::Nothing) return leader_clear(side.piece, segment);
      return clear_of_lines(side.piece, Polygon(segment.begin(), segment.end()), o_.tight_clearance_mm, true);
    };
    const auto box_clear = [&](const Polygon& box) {
      if (past == Past::Nothing) return clear_of_everything(side.piece, box, level);
      return clear_of_lines(side.piece, box, clearance_at(level), level >= Clearance::OverFold);
    };
    const OutlineEdge& e = *side.edge;
    const Vec2 dir = normalized(e.b - e.a), up = perp_ccw(dir);
    const Vec2 anchor = (e.a + e.b) * 0.5 + up * o_.gap_mm;
    const double half_bar = 0.5 * std::min(kLeaderBar_mm, kLeaderBarShare * side.length_mm);
    const std::array<Vec2, 2> bar{anchor - dir * half_bar, anchor + dir * half_bar};
    if (!inside_piece(side.piece, anchor) || !way_clear(bar)) return;
    const Form& brief = kForms.back();
    const Extent ext = extent(side, o_.min_mm, brief);
    const double half_w = 0.5 * ext.width_mm, half_h = 0.5 * ext.height_mm;
    // The label parallel to its edge, else across it (a narrow gap between lines often runs the other
    // way), else along its leader or across it, else at 45 degrees to its edge: between the slivers of a
    // fan the gaps run every way. Turned straight into the face, the leader runs across the edge.
    const Vec2 slant_up = normalized(dir + up), slant_down = normalized(dir - up);
    const std::size_t readings = o_.leader_search == LeaderSearch::Thorough ? 6 : 2;
    // A leader that runs into a line or label does so at every longer reach: that way is closed.
    std::array<bool, kLeaderTurns_rad.size()> closed{};
    for (double r = kLeaderStep_mm; r <= o_.leader_reach_mm + 1e-9; r += kLeaderStep_mm)
      for (std::size_t k = 0; k < kLeaderTurns_rad.size(); ++k) {
        if (closed[k]) continue;
        const Vec2 towards = rotated(up, kLeaderTurns_rad[k]);
        const std::array<Vec2, 2> leader{anchor, anchor + towards * (r - o_.clearance_mm)};
        if (!way_clear(leader)) {
          closed[k] = true;
          continue;
        }
        const std::array<Vec2, 6> reading{dir, up, towards, perp_ccw(towards), slant_up, slant_down};
        for (std::size_t w = 0; w < readings; ++w) {
          if (k == 0 && (w == 2 || w == 3)) continue;
          const Vec2 d = reading[w];
          const Vec2 n = perp_ccw(d);
          // From the box's centre, the way back to the anchor leaves the box after `exit`.
          const double along = std::fabs(dot(towards, d)), across = std::fabs(dot(towards, n));
          const double exit =
              std::min(along > 1e-9 ? half_w / along : 1e300, across > 1e-9 ? half_h / across : 1e300);
          const Vec2 centre = anchor + towards * (r + exit);
          if (!inside_piece(side.piece, centre)) continue;
          const Vec2 foot = centre - d * half_w - n * half_h;
          if (!box_clear(label_box(foot, d, ext.width_mm, ext.height_mm))) continue;
          Label label = make_label(side, foot, d, o_.min_mm, brief, false);
          label.leader_mm = {leader, bar};
          if (consider(std::move(label))) return;
        }
      }
  }
  // The sides still without a label that find a spot on a leader at `level`, committed as `as`.
  void place_on_leaders(std::span<const std::size_t> sides, Clearance level, Clearance as) {
    for (std::size_t i : sides)
      if (!sides_[i].label)
        if (auto label = with_leader(sides_[i], level))
          commit(sides_[i], std::move(*label), as, kForms.size() - 1);
  }
  // A leader's segment: clear of the outline (folds it may cross) and of every label by the tight
  // clearance.
  bool leader_clear(int p, const std::array<Vec2, 2>& segment) const {
    const Polygon line(segment.begin(), segment.end());
    return clear_of_lines(p, line, o_.tight_clearance_mm, true) &&
           clear_of_labels(p, line, o_.tight_clearance_mm);
  }

  void add_label_obstacle(int p, const Polygon& box, int side = -1) {
    PieceObstacles& ob = obstacles_[p];
    ob.label_grid.insert(static_cast<int>(ob.labels.size()), bounds_of(box));
    ob.labels.push_back(box);
    ob.label_active.push_back(true);
    ob.side_of_label.push_back(side);
  }

  void commit(SideTask& side, Label label, Clearance level, std::size_t form) {
    if (side.slot >= 0) obstacles_[side.piece].label_active[side.slot] = false;
    for (int k : std::exchange(side.leader_slots, {}))
      obstacles_[side.piece].label_active[k] = false;
    // A leader is a fixed obstacle, like a part letter: no label moves it away.
    for (const std::array<Vec2, 2>& segment : label.leader_mm) {
      side.leader_slots.push_back(static_cast<int>(obstacles_[side.piece].labels.size()));
      add_label_obstacle(side.piece, Polygon(segment.begin(), segment.end()));
    }
    label.over_fold = level == Clearance::OverFold && !label.on_tab;
    label.crowded = level >= Clearance::OverOutline && !label.on_tab;
    side.clearance = label.on_tab ? Clearance::Clear : level;
    side.form = form;
    side.slot = static_cast<int>(obstacles_[side.piece].labels.size());
    add_label_obstacle(side.piece, label.box_mm, static_cast<int>(&side - sides_.data()));
    side.label = std::move(label);
  }

  struct Spot {
    Label label;
    std::size_t form = kForms.size() - 1;
  };
  // The short text first, everywhere: the mate's sheet, like a larger size, comes where room is left
  // over (grow), and the sheets list their parts. The step mark too, except on the seam's first side:
  // one side at least shows it if it fits there at all.
  std::optional<Spot> spot_at_minimum(const SideTask& side, Clearance level) const {
    const bool step_first = level == Clearance::Clear && side.step_side && !hint_of(side).empty();
    const std::vector<std::size_t> forms =
        step_first ? std::vector<std::size_t>{2, 3} : std::vector<std::size_t>{3};
    for (std::size_t i = 0; i < forms.size(); ++i) {
      if (tried_before(side, forms, i)) continue;
      if (auto label = find(side, o_.min_mm, kForms[forms[i]], level))
        return Spot{std::move(*label), forms[i]};
    }
    if (level == Clearance::OverOutline) return std::nullopt;
    if (auto label = across_face(side, o_.min_mm, kForms[3], level)) return Spot{std::move(*label), 3};
    return std::nullopt;
  }
  void try_at_minimum(SideTask& side, Clearance level) {
    if (auto spot = spot_at_minimum(side, level)) commit(side, std::move(spot->label), level, spot->form);
  }

  // The spots beside the edge (along it, then across it) that keep the tight clearance from every line
  // but not from some labels, with those labels' sides, fewest first; none where a part letter is in
  // the way or more than kMostLabelsMoved labels are.
  struct BlockedSpot {
    Label label;
    std::vector<int> blockers;
  };
  std::vector<BlockedSpot> spots_blocked_by_labels(const SideTask& side) const {
    std::vector<BlockedSpot> spots;
    for_each_spot_at_minimum(side, [&](Label label, Vec2 centre) {
      if (!inside_piece(side.piece, centre)) return;
      if (!clear_of_lines(side.piece, label.box_mm, o_.tight_clearance_mm)) return;
      if (auto blockers = labels_in_the_way(side.piece, label.box_mm))
        spots.push_back({std::move(label), std::move(*blockers)});
    });
    std::stable_sort(spots.begin(), spots.end(), [](const BlockedSpot& a, const BlockedSpot& b) {
      return a.blockers.size() < b.blockers.size();
    });
    if (spots.size() > kMostSpotsFreed) spots.resize(kMostSpotsFreed);
    return spots;
  }
  // The sides of the labels within the tight clearance of `box`, or nullopt where there are none, one of
  // them is a part letter or a leader, or there are more than kMostLabelsMoved.
  std::optional<std::vector<int>> labels_in_the_way(int p, const Polygon& box) const {
    std::vector<int> sides;
    if (!add_labels_in_the_way(p, box, sides) || sides.empty()) return std::nullopt;
    return sides;
  }
  // Adds to `sides` those of the labels within the tight clearance of `area` not in it yet; false where one
  // of them cannot move (a part letter, a leader) or they come to more than kMostLabelsMoved.
  bool add_labels_in_the_way(int p, const Polygon& area, std::vector<int>& sides) const {
    const PieceObstacles& ob = obstacles_[p];
    return ob.label_grid.visit(grown(bounds_of(area), o_.tight_clearance_mm), [&](int k) {
      if (!ob.label_active[k] || !convex_overlap(area, ob.labels[k], -o_.tight_clearance_mm)) return true;
      const int side = ob.side_of_label[k];
      if (side < 0) return false;
      if (std::find(sides.begin(), sides.end(), side) == sides.end()) sides.push_back(side);
      return sides.size() <= kMostLabelsMoved;
    });
  }

  // A label with no spot at the tight clearance takes one where only other labels stand in its way,
  // when each of them finds another spot at least that clear: a label beside a small face has one or
  // two spots, its neighbours on larger faces have many. Tried before any label crosses a line.
  void place_by_moving_others(SideTask& side) {
    int unmoved = -1;
    for (BlockedSpot& spot : spots_blocked_by_labels(side))
      if (take_by_moving(side, std::move(spot), Moves::BesideEdges, unmoved)) return;
  }

  // The same for a leader's spot, where no spot beside the edge was freed: in a cluster of small faces
  // the labels with room beside their own edges took the larger faces, the only ones a label without
  // room could reach. Those may move beside their edges or onto leaders of their own.
  void place_on_leader_by_moving_others(SideTask& side) {
    std::vector<BlockedSpot> spots;
    for_each_leader_spot(side, Clearance::Tight, Past::Labels, [&](Label label) {
      std::vector<int> blockers;
      bool movable = add_labels_in_the_way(side.piece, label.box_mm, blockers);
      for (const std::array<Vec2, 2>& segment : label.leader_mm)
        movable =
            movable && add_labels_in_the_way(side.piece, Polygon(segment.begin(), segment.end()), blockers);
      if (movable && !blockers.empty()) spots.push_back({std::move(label), std::move(blockers)});
      return spots.size() >= kMostLeaderSpotsFreed;
    });
    // A label that found no other spot for one of them rarely finds one for the next: its own
    // surroundings are full (homer_2000 at 250 mm, laid out with this search: 5.5 s with every spot
    // tried, 1.9 s skipping; such meshes now use LeaderSearch::Quick).
    std::vector<int> stuck;
    for (BlockedSpot& spot : spots) {
      if (std::any_of(spot.blockers.begin(), spot.blockers.end(),
                      [&](int b) { return std::find(stuck.begin(), stuck.end(), b) != stuck.end(); }))
        continue;
      int unmoved = -1;
      if (take_by_moving(side, std::move(spot), Moves::AlsoOnLeaders, unmoved)) return;
      stuck.push_back(unmoved);
    }
  }

  // Where labels moved out of the way may go: beside their edges (or on their tabs), or on leaders too.
  enum class Moves { BesideEdges, AlsoOnLeaders };
  // `side` takes `spot` and every label in its way moves to its first spot clear at the tight clearance;
  // where one finds none, all is as before and `unmoved` names it. True when kept.
  bool take_by_moving(SideTask& side, BlockedSpot spot, Moves moves, int& unmoved) {
    std::vector<SideTask*> touched{&side};
    for (int b : spot.blockers)
      touched.push_back(&sides_[b]);
    std::vector<SideTask> saved;
    for (SideTask* t : touched)
      saved.push_back(*t);
    for (int b : spot.blockers)
      obstacles_[sides_[b].piece].label_active[sides_[b].slot] = false;
    const Clearance own = !spot.label.leader_mm.empty() ? Clearance::Leader
                          : clear_of_everything(side.piece, spot.label.box_mm, Clearance::Clear)
                              ? Clearance::Clear
                              : Clearance::Tight;
    commit(side, std::move(spot.label), own, kForms.size() - 1);
    for (int b : spot.blockers)
      if (!move_elsewhere(sides_[b], moves)) {
        undo(touched, saved);
        unmoved = b;
        return false;
      }
    return true;
  }
  bool move_elsewhere(SideTask& side, Moves moves) {
    for (Clearance level : {Clearance::Clear, Clearance::Tight})
      if (auto other = spot_at_minimum(side, level)) {
        commit(side, std::move(other->label), level, other->form);
        return true;
      }
    if (moves == Moves::BesideEdges) return false;
    for (Clearance level : {Clearance::Clear, Clearance::Tight})
      if (auto label = with_leader(side, level)) {
        commit(side, std::move(*label), Clearance::Leader, kForms.size() - 1);
        return true;
      }
    return false;
  }
  // Each touched side back as saved, its label and leader the obstacles again instead of the new ones.
  void undo(std::span<SideTask* const> touched, std::vector<SideTask>& saved) {
    const auto set_active = [&](const SideTask& t, bool active) {
      std::vector<bool>& on = obstacles_[t.piece].label_active;
      if (t.slot >= 0) on[t.slot] = active;
      for (int k : t.leader_slots)
        on[k] = active;
    };
    for (SideTask* t : touched)
      set_active(*t, false);
    for (std::size_t i = 0; i < touched.size(); ++i) {
      *touched[i] = std::move(saved[i]);
      set_active(*touched[i], true);
    }
  }

  // What a label with no clear spot runs into, worst first: another label (the two become unreadable),
  // the outline (cutting takes part of the text away), fold lines; each counted where it comes closer
  // than the tight clearance. Last, what comes within the full clearance: nearer is harder to read.
  struct Crowding {
    int labels = 0, outlines = 0, folds = 0, near = 0;
    auto operator<=>(const Crowding&) const = default;
  };
  Crowding crowding(int p, const Polygon& box) const {
    const Box2 reach = grown(bounds_of(box), o_.clearance_mm);
    const PieceObstacles& ob = obstacles_[p];
    Crowding c;
    ob.line_grid.visit(reach, [&](int i) {
      const Segment& s = ob.lines[i];
      const std::array<Vec2, 2> seg{s.a, s.b};
      if (convex_overlap(box, seg, -o_.tight_clearance_mm))
        ++(s.fold ? c.folds : c.outlines);
      else
        c.near += convex_overlap(box, seg, -o_.clearance_mm);
      return true;
    });
    ob.label_grid.visit(reach, [&](int k) {
      if (!ob.label_active[k]) return true;
      if (convex_overlap(box, ob.labels[k], -o_.tight_clearance_mm))
        ++c.labels;
      else
        c.near += convex_overlap(box, ob.labels[k], -o_.clearance_mm);
      return true;
    });
    return c;
  }

  // A label no spot is clear for still prints beside its edge, at the legible minimum, where it runs
  // into the least: over fold lines or the outline rather than over another label, so that each stays
  // readable. Among equals the spot nearest the edge's middle (the first tried).
  void place_least_crowded(SideTask& side) {
    if (side.slot >= 0) obstacles_[side.piece].label_active[side.slot] = false;
    std::optional<Label> best;
    Crowding least;
    for_each_spot_at_minimum(side, [&](Label label, Vec2 centre) {
      if (best && !inside_piece(side.piece, centre)) return;
      const Crowding c = crowding(side.piece, label.box_mm);
      if (!best || c < least) {
        least = c;
        best = std::move(label);
      }
    });
    commit(side, std::move(*best), Clearance::Nowhere, kForms.size() - 1);
  }

  // The short label at the legible minimum at a coarse set of spots beside its edge, whatever is there:
  // along the edge at four lifts, the middle first, then across it. `consider(label, centre)`.
  template <class Consider>
  void for_each_spot_at_minimum(const SideTask& side, Consider&& consider) const {
    static constexpr std::array<double, 9> kAlong{0.5, 0.35, 0.65, 0.2, 0.8, 0.1, 0.9, 0, 1};
    const OutlineEdge& e = *side.edge;
    const Vec2 dir = normalized(e.b - e.a), up = perp_ccw(dir);
    const Form& brief = kForms.back();
    const double h = o_.min_mm, w = full_width(side, h, brief);
    for (double lift : {o_.gap_mm, o_.gap_mm + kMiddleLift * h, o_.gap_mm + kHighestLift * h,
                        o_.gap_mm + kHighestLiftSmall * h})
      for (double t : kAlong) {
        const Vec2 at = e.a + dir * (t * side.length_mm - 0.5 * w) + up * lift;
        consider(make_label(side, at, dir, h, brief, false), at + dir * (0.5 * w) + up * (0.5 * h));
      }
    for (double t : kAlong) {
      const Vec2 at = e.a + dir * (t * side.length_mm + 0.5 * h) + up * o_.gap_mm;
      consider(make_label(side, at, up, h, brief, false), at + up * (0.5 * w) - dir * (0.5 * h));
    }
  }

  // A more informative form (the full text, the step mark) where the room allows, then a larger size;
  // only for labels clear of every line (one that crosses a line would cross more).
  void grow(SideTask& side) {
    if (side.clearance != Clearance::Clear) return;
    const int own = side.slot;
    obstacles_[side.piece].label_active[own] = false;
    std::optional<Label> better;
    std::size_t better_form = side.form;
    for (std::size_t form = 0; form <= side.form && !better; ++form) {
      if (form != side.form && prints_alike(side, form, side.form)) continue;
      const double current = side.label->height_mm;
      for (double h : heights_down_to(side, o_.min_mm)) {
        if (form == side.form && h <= current + 1e-9) break;
        if ((better = find(side, h, kForms[form], Clearance::Clear))) {
          better_form = form;
          break;
        }
      }
    }
    obstacles_[side.piece].label_active[own] = true;
    if (better) commit(side, std::move(*better), side.clearance, better_form);
  }

  // A seam whose step mark found room on neither side shows it anyway on the side that suffers least,
  // across a fold line if need be (never touching the outline or a label): the builder asked for it.
  void show_every_step() {
    std::vector<std::vector<std::size_t>> sides_of(seams_.size());
    for (std::size_t i = 0; i < sides_.size(); ++i)
      sides_of[sides_[i].seam].push_back(i);
    for (const std::vector<std::size_t>& seam_sides : sides_of) {
      bool shown = seam_sides.empty() || hint_of(sides_[seam_sides.front()]).empty();
      for (std::size_t i : seam_sides)
        shown = shown || !sides_[i].label->hint.empty();
      for (std::size_t i : seam_sides) {
        if (shown) break;
        SideTask& side = sides_[i];
        if (side.clearance == Clearance::Leader || side.clearance > Clearance::OverFold) continue;
        const int own = side.slot;
        obstacles_[side.piece].label_active[own] = false;
        std::optional<Label> with_step = find(side, o_.min_mm, kForms[2], Clearance::OverFold);
        const bool clear =
            with_step &&
            (with_step->on_tab || clear_of_everything(side.piece, with_step->box_mm, Clearance::Clear));
        obstacles_[side.piece].label_active[own] = true;
        if (!with_step) continue;
        const Clearance level = clear ? Clearance::Clear : Clearance::OverFold;
        commit(side, std::move(*with_step), level, 2);
        shown = true;
      }
    }
  }

  std::span<const ScaledPiece> pieces_;
  std::span<const Seam> seams_;
  std::span<const std::string> hints_;
  const LabelOptions& o_;
  std::vector<bool> placing_;  // per piece, whether its labels are placed (only_pieces)
  std::vector<PieceObstacles> obstacles_;
  std::vector<SideTask> sides_;
};

}  // namespace

int first_labelled_side(const TabPlan& tabs, std::size_t seam) {
  return !tabs.on_side(seam, 0) && tabs.on_side(seam, 1) ? 1 : 0;
}

namespace {

// The pieces whose labels a call places, in groups for `threads` threads: a few groups per thread, of
// about the same number of outline edges (the largest piece first into the lightest group), so that one
// large piece does not leave the other threads idle. Few groups, not one per piece: each placer is
// given every piece, so a model of thousands of pieces would cost their square.
std::vector<std::vector<int>> piece_groups(std::span<const ScaledPiece> pieces,
                                           std::span<const int> only_pieces, int threads) {
  constexpr int kGroupsPerThread = 4;
  std::vector<int> placed(only_pieces.begin(), only_pieces.end());
  if (only_pieces.empty()) {
    placed.resize(pieces.size());
    std::iota(placed.begin(), placed.end(), 0);
  }
  const auto edges = [&](int p) {
    std::size_t n = 0;
    for (const OutlineLoop& loop : pieces[static_cast<std::size_t>(p)].outline_mm)
      n += loop.size();
    return n;
  };
  std::stable_sort(placed.begin(), placed.end(), [&](int a, int b) { return edges(a) > edges(b); });
  const std::size_t count = std::min(placed.size(), static_cast<std::size_t>(kGroupsPerThread) * threads);
  std::vector<std::vector<int>> groups(count);
  std::vector<std::size_t> load(count, 0);
  for (int p : placed) {
    const std::size_t lightest = std::min_element(load.begin(), load.end()) - load.begin();
    groups[lightest].push_back(p);
    load[lightest] += edges(p);
  }
  return groups;
}

}  // namespace

std::vector<Label> place_labels(std::span<const ScaledPiece> pieces, std::span<const Seam> seams,
                                std::span<const int> numbers, const TabPlan& tabs,
                                std::span<const std::vector<FoldLine>> fold_lines,
                                std::span<const std::string> hints, const LabelOptions& o,
                                const SeamTexts& texts, std::span<const std::vector<Polygon>> taken,
                                std::span<const int> only_pieces) {
  if (texts.full.size() < seams.size()) {
    SeamTexts numbers_only;
    for (int n : numbers)
      numbers_only.full.push_back({number_text(n), number_text(n)});
    return place_labels(pieces, seams, numbers, tabs, fold_lines, hints, o, numbers_only, taken, only_pieces);
  }
  const auto place = [&](std::span<const int> these) {
    return LabelPlacer(pieces, seams, tabs, fold_lines, hints, o, texts, taken, these).run();
  };
  const int threads = resolve_threads(o.threads);
  // With hints a seam's step mark goes on one of its two sides, which may lie in two pieces.
  if (!hints.empty() || threads < 2) return place(only_pieces);
  const std::vector<std::vector<int>> groups = piece_groups(pieces, only_pieces, threads);
  if (groups.size() < 2) return place(only_pieces);
  std::vector<std::vector<Label>> by_group(groups.size());
  run_parallel(static_cast<int>(groups.size()), threads, [&](int k) { by_group[k] = place(groups[k]); });
  // In the order of one placement of all: the seams', the side with the tab first.
  std::vector<Label> labels;
  for (std::vector<Label>& some : by_group)
    std::move(some.begin(), some.end(), std::back_inserter(labels));
  const auto order = [&](const Label& l) {
    return std::make_pair(l.seam.index(), l.side != first_labelled_side(tabs, l.seam.index()));
  };
  std::sort(labels.begin(), labels.end(),
            [&](const Label& a, const Label& b) { return order(a) < order(b); });
  return labels;
}

}  // namespace foldkit::layout
