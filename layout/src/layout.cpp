#include "foldkit/layout/layout.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <numeric>
#include <span>
#include <utility>

#include "foldkit/error.hpp"
#include "foldkit/layout/arrows.hpp"
#include "foldkit/layout/edge_numbers.hpp"
#include "foldkit/layout/furniture.hpp"
#include "foldkit/layout/hints.hpp"
#include "foldkit/layout/label_audit.hpp"
#include "foldkit/layout/label_text.hpp"
#include "foldkit/layout/outline.hpp"
#include "foldkit/layout/pack.hpp"
#include "foldkit/layout/piece_letters.hpp"
#include "foldkit/layout/scale.hpp"
#include "foldkit/layout/tabs.hpp"
#include "foldkit/layout/tabs_in_place.hpp"
#include "foldkit/unfold/disjoint_sets.hpp"

namespace foldkit::layout {
namespace {

std::string format_mm(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.0f", v);
  return buf;
}

}  // namespace

std::string PieceTooLarge::message(int piece, Vec2 area_mm, double asked_mm, double largest_mm,
                                   const std::string& size_name) {
  return "piece " + std::to_string(piece + 1) + " does not fit the " + format_mm(area_mm.x) + "x" +
         format_mm(area_mm.y) + " mm printable area at " + size_name + " " + format_mm(asked_mm) +
         "mm; the largest " + size_name + " that fits is " + format_mm(largest_mm) + "mm";
}

void check_options(const LayoutOptions& o) {
  auto positive = [](double v) { return std::isfinite(v) && v > 0; };
  if (!positive(o.paper_mm.x) || !positive(o.paper_mm.y)) throw LayoutError("paper size must be positive");
  if (!(std::isfinite(o.margin_mm) && o.margin_mm >= 0)) throw LayoutError("margin must be zero or positive");
  if (o.size_mm && !positive(*o.size_mm)) throw LayoutError("the model size must be positive");
  if (o.tabs && (!positive(o.tab.width_mm) || !positive(o.tab.min_width_mm)))
    throw LayoutError("tab width must be positive");
  if (!positive(o.label.min_mm) || o.label.max_mm < o.label.min_mm) throw LayoutError("bad label sizes");
  if (!(o.pack.spacing_mm >= 0) || !positive(o.pack.cell_mm)) throw LayoutError("bad packing spacing");
  const Box2 area = printable_area(o);
  if (area.empty() || area.width() < 10 || area.height() < 10)
    throw LayoutError("the margins leave no printable area on a " + format_mm(o.paper_mm.x) + "x" +
                      format_mm(o.paper_mm.y) + " mm sheet");
  // Every part keeps a border for its tabs and the gap to the next part, and clear of the registration
  // marks: where that leaves a sliver, --fit scaled the model to 0 mm and wrote an empty sheet.
  const Vec2 room = piece_room_mm(o);
  if (!(room.x >= kLeastPartRoom_mm && room.y >= kLeastPartRoom_mm))
    throw LayoutError("no room for a part in the " + format_mm(area.width()) + "x" +
                      format_mm(area.height()) + " mm printable area of a " + format_mm(o.paper_mm.x) + "x" +
                      format_mm(o.paper_mm.y) + " mm sheet: a part keeps " + format_mm(piece_border_mm(o)) +
                      " mm on every side for its tabs and the gap between parts" +
                      (o.regmarks ? ", and clear of the registration marks" : ""));
}

namespace {

// The label options as placed: arrows sit along the edges, so the labels are lifted above them.
LabelOptions label_options_in_use(const LayoutOptions& o) {
  LabelOptions l = o.label;
  if (o.arrows) l.gap_mm = kArrowLabelGap_mm;
  return l;
}

// The tab options as planned: the least width never above the width asked.
TabOptions tab_options_in_use(const LayoutOptions& o) {
  TabOptions t = o.tab;
  t.min_width_mm = std::min(t.min_width_mm, t.width_mm);
  // A tab wanted for its label holds one at the least size, its gap from the fold and its clearance
  // from the tab's outer side (place_labels' on_tab), with a hair to spare.
  constexpr double kLabelTabSpare_mm = 0.05;
  const LabelOptions label = label_options_in_use(o);
  t.label_width_mm = label.min_mm + label.gap_mm + label.clearance_mm + kLabelTabSpare_mm;
  return t;
}

void report(const LayoutOptions& o, const char* stage, long done, long total) {
  if (o.progress) o.progress({stage, done, total});
}

// Sheet frame (y down, from the top-left) <-> packing frame (y up, from the bottom-left).
Box2 flip_box(const Box2& b, double paper_h) {
  return Box2{{b.min.x, paper_h - b.max.y}, {b.max.x, paper_h - b.min.y}};
}

// The printable area in the packing frame (y up): what the pieces are packed into and measured against.
Box2 packing_area(const LayoutOptions& o) {
  return flip_box(printable_area(o), o.paper_mm.y);
}

// Everything drawn for one piece, in the piece's frame (mm, y up), before packing.
struct Draft {
  std::vector<ScaledPiece> pieces;
  std::vector<Seam> seams;
  std::vector<int> numbers;  // per seam, its rank in outline order (tabs alternate along it)
  std::vector<int> printed;  // per seam, the number its labels print (number_seams_by_part)
  std::vector<int> order;    // assembly order (seam indices), empty without hints
  std::vector<std::vector<FoldLine>> folds;
  TabPlan tabs;
  std::vector<int> tab_sides;  // per seam, the tab side plan_tabs was asked for (-1: its choice), or empty
  std::vector<Label> labels;
  std::vector<Arrow> arrows;
  std::vector<std::string> letters;  // per piece
  std::vector<PieceLetter> piece_letters;
  // What label placement was given, kept to place the labels again once the sheets are known.
  std::vector<std::vector<FoldLine>> label_avoid;  // per piece: fold lines and arrows
  std::vector<std::string> hints;                  // per seam
  LabelOptions label_options;
  std::vector<std::vector<Polygon>> label_taken;  // per piece: the part letter's footprint
};

// What each side of each seam prints: the mate's letter when it is another part, and in the full text
// the mate's sheet (1-based) when `sheet_of_piece` is given and puts the mate on another sheet.
SeamTexts seam_texts(const Draft& d, std::span<const int> sheet_of_piece = {}) {
  SeamTexts texts;
  texts.full.resize(d.seams.size());
  texts.brief.resize(d.seams.size());
  for (std::size_t s = 0; s < d.seams.size(); ++s)
    for (int k = 0; k < 2; ++k) {
      const int own = d.seams[s].sides[k].piece, mate = d.seams[s].sides[1 - k].piece;
      const bool other = mate >= 0 && own >= 0 && mate != own;
      const bool elsewhere = other && !sheet_of_piece.empty() && sheet_of_piece[mate] != sheet_of_piece[own];
      const std::string& letter = other ? d.letters[mate] : std::string();
      texts.full[s][k] = seam_label_text(d.printed[s], letter, elsewhere ? sheet_of_piece[mate] + 1 : 0);
      texts.brief[s][k] = seam_label_text(d.printed[s], letter, 0);
    }
  return texts;
}

// A seam as a list names it: by its parts' letters and number ("A-B 3"), or by its number alone when the
// model is one part.
std::string listed_seam_name(const Draft& d, int s) {
  if (d.pieces.size() <= 1) return number_text(d.printed[s]);
  const auto letter = [&](int k) {
    const int piece = d.seams[s].sides[k].piece;
    return piece >= 0 && piece < static_cast<int>(d.letters.size()) ? d.letters[piece] : std::string();
  };
  return seam_name(d.printed[s], letter(0), letter(1));
}

std::vector<Label> place_draft_labels(const Draft& d, const SeamTexts& texts) {
  return place_labels(d.pieces, d.seams, d.printed, d.tabs, d.label_avoid, d.hints, d.label_options, texts,
                      d.label_taken);
}

// The labels of the pieces `changed` marks placed again, the others' taken from `kept`, in the order
// place_draft_labels gives them (the seams', the side with the tab first), so that every later step sees
// what a placement of all would have given. With hints everything is placed again: a seam's step mark
// goes on one side, which may be in another piece.
std::vector<Label> place_draft_labels_again(const Draft& d, const SeamTexts& texts, std::vector<Label> kept,
                                            const std::vector<bool>& changed) {
  std::vector<int> pieces;
  for (std::size_t p = 0; p < changed.size(); ++p)
    if (changed[p]) pieces.push_back(static_cast<int>(p));
  if (!d.hints.empty() || pieces.size() == d.pieces.size()) return place_draft_labels(d, texts);
  if (pieces.empty()) return kept;
  std::vector<Label> placed = place_labels(d.pieces, d.seams, d.printed, d.tabs, d.label_avoid, d.hints,
                                           d.label_options, texts, d.label_taken, pieces);
  std::vector<std::array<std::optional<Label>, 2>> by_side(d.seams.size());
  for (std::vector<Label>* from : {&kept, &placed})
    for (Label& l : *from)
      if (from == &placed || !changed[l.piece]) by_side[l.seam.index()][l.side] = std::move(l);
  std::vector<Label> labels;
  for (std::size_t s = 0; s < d.seams.size(); ++s) {
    const int first = first_labelled_side(d.tabs, s);
    for (int k : {first, 1 - first})
      if (by_side[s][k]) labels.push_back(std::move(*by_side[s][k]));
  }
  return labels;
}

// Per piece, whether one of its seam sides carries another tab in `b` than in `a` (none, or another
// shape): only those pieces' labels can change when the tabs are planned again.
std::vector<bool> pieces_with_other_tabs(const Draft& d, const TabPlan& a, const TabPlan& b) {
  std::vector<bool> changed(d.pieces.size(), false);
  for (std::size_t s = 0; s < d.seams.size(); ++s)
    for (int k : {0, 1}) {
      const int piece = d.seams[s].sides[k].piece;
      if (piece < 0) continue;
      const Tab *x = a.on_side(s, k), *y = b.on_side(s, k);
      const bool same = x == nullptr ? y == nullptr : y != nullptr && x->quad_mm == y->quad_mm;
      if (!same) changed[piece] = true;
    }
  return changed;
}

// Per seam, the side whose tab should carry the label (tab_sides_for_labels), for the brief label: the
// number, after a letter when the mate is another part (the letters come later; one stands for all).
std::vector<int> tab_sides_wanted(const Draft& d, const LayoutOptions& o) {
  if (!o.numbers) return {};
  const LabelOptions label = label_options_in_use(o);
  std::vector<double> widths(d.seams.size());
  for (std::size_t s = 0; s < d.seams.size(); ++s) {
    const bool cross = d.seams[s].sides[0].piece != d.seams[s].sides[1].piece;
    std::string text = cross ? "B" : "";
    text += number_text(d.printed[s]);
    widths[s] = label_width_mm(text, label.min_mm, label);
  }
  return tab_sides_for_labels(d.pieces, d.seams, widths, label);
}

// Tabs in number order: numbers follow the outlines, so alternation works along each outline.
// `wanted` (per seam, may be empty) as plan_tabs takes it.
TabPlan plan_draft_tabs(const Draft& d, const LayoutOptions& o, std::span<const int> wanted) {
  std::vector<int> by_number(d.seams.size());
  std::iota(by_number.begin(), by_number.end(), 0);
  std::sort(by_number.begin(), by_number.end(), [&](int a, int b) { return d.numbers[a] < d.numbers[b]; });
  return plan_tabs(d.pieces, d.seams, tab_options_in_use(o), by_number, wanted);
}

bool has_clear_spot(const Label& l) {
  return !l.over_fold && !l.crowded;
}

// Per seam, its labels by side (nullptr where a side has none).
std::vector<std::array<const Label*, 2>> labels_by_seam(const Draft& d) {
  std::vector<std::array<const Label*, 2>> of_seam(d.seams.size(), {nullptr, nullptr});
  for (const Label& l : d.labels)
    of_seam[l.seam.index()][l.side] = &l;
  return of_seam;
}

// Marks in `wanted` the tab side of each seam with a label that finds no clear spot on its face
// (open_tabs_for_crowded_labels): its own side, where the seam's tab is already there or the mate's
// label has a clear spot (on its face, or on the tab it gives up: it had not tried its face); false when
// none is new.
bool want_tabs_for_crowded_labels(const Draft& d, std::vector<int>& wanted) {
  const std::vector<std::array<const Label*, 2>> of_seam = labels_by_seam(d);
  bool any = false;
  for (const Label& l : d.labels) {
    const std::size_t s = l.seam.index();
    const std::optional<Tab>& tab = d.tabs.tab_of_seam[s];
    if (has_clear_spot(l) || !tab || wanted[s] == l.side) continue;
    const Label* mate = of_seam[s][1 - l.side];
    if (tab->side != l.side && !(mate && has_clear_spot(*mate))) continue;
    wanted[s] = l.side;
    any = true;
  }
  return any;
}

int labels_without_clear_spot(std::span<const Label> labels) {
  return static_cast<int>(
      std::count_if(labels.begin(), labels.end(), [](const Label& l) { return !has_clear_spot(l); }));
}

// Plans the tabs again with `wanted` and places the labels again; keeps both when no seam loses its tab
// and fewer labels are left without a clear spot, else leaves the draft as it was.
void keep_tabs_if_labels_gain(Draft& d, const LayoutOptions& o, std::vector<int> wanted) {
  TabPlan replanned = plan_draft_tabs(d, o, wanted);
  if (replanned.dropped.size() > d.tabs.dropped.size()) return;
  TabPlan kept = std::exchange(d.tabs, std::move(replanned));
  std::vector<Label> again =
      place_draft_labels_again(d, seam_texts(d), d.labels, pieces_with_other_tabs(d, kept, d.tabs));
  if (labels_without_clear_spot(again) < labels_without_clear_spot(d.labels)) {
    d.labels = std::move(again);
    d.tab_sides = std::move(wanted);
  } else {
    d.tabs = std::move(kept);
  }
}

// Tabs are planned before the labels, with gentle ends: a tab on a short edge is then nearly a triangle,
// with no room for a label. Where a label finds no clear spot on its face, the seam's tab is wanted on
// its side (want_tabs_for_crowded_labels) and for its label: steep ends, its whole base up to its outer
// side, the label's height. The tabs are planned again and the
// labels placed again, kept when no seam loses its tab and fewer labels are left without a clear spot.
// (A second round gains next to nothing: 431 to 430 such labels over ten 350-500-face meshes.)
void open_tabs_for_crowded_labels(Draft& d, const LayoutOptions& o) {
  std::vector<int> wanted = tab_sides_wanted(d, o);
  if (want_tabs_for_crowded_labels(d, wanted)) keep_tabs_if_labels_gain(d, o, std::move(wanted));
}

// Whether an edge of `length_mm` holds two labels of `texts` at the least size, each on a tab along
// its half of the edge: the label, its clearance at both ends, and the steepest ends of a tab as high as
// the label needs (TabOptions::label_width_mm).
bool halves_hold_labels(double length_mm, const std::array<std::string, 2>& texts, const LayoutOptions& o) {
  const LabelOptions label = label_options_in_use(o);
  const double tab_height_mm = tab_options_in_use(o).label_width_mm;
  const double ends_mm = 2 * tab_height_mm / std::tan(kSteepestTabSlant_rad);
  double widest_mm = 0;
  for (const std::string& text : texts)
    widest_mm = std::max(widest_mm, label_width_mm(text, label.min_mm, label));
  return length_mm / 2 >= widest_mm + 2 * label.clearance_mm + ends_mm;
}

// Marks kSplitTab in `wanted` for each seam with a label left without a clear spot whose one tab is on
// the mate's side and carries the mate's label (or the mate has no clear spot either): moving the tab
// would only move the problem, two halves give each label its own tab. Only where the edge holds both
// labels on halves (halves_hold_labels); false when no seam qualifies.
bool want_split_tabs(const Draft& d, const LayoutOptions& o, std::vector<int>& wanted) {
  const std::vector<std::array<const Label*, 2>> of_seam = labels_by_seam(d);
  const SeamTexts texts = seam_texts(d);
  bool any = false;
  for (const Label& l : d.labels) {
    const std::size_t s = l.seam.index();
    const Label* mate = of_seam[s][1 - l.side];
    const Tab* tab = d.tabs.on_side(s, 1 - l.side);
    if (has_clear_spot(l) || !mate || !tab || d.tabs.is_split(s) || wanted[s] == kSplitTab) continue;
    if (!mate->on_tab && has_clear_spot(*mate)) continue;
    const SeamSide& at = d.seams[s].sides[l.side];
    const OutlineEdge& e = d.pieces[at.piece].outline_mm[at.loop][at.index];
    if (!halves_hold_labels(norm(e.b - e.a), texts.brief[s], o)) continue;
    wanted[s] = kSplitTab;
    any = true;
  }
  return any;
}

// A long edge between two faces too narrow for a label beside it: its one tab holds one label and the
// other crosses the face's lines. Such tabs are split in two halves (want_split_tabs), the tabs planned
// again and the labels placed again; kept when no seam loses its tab and fewer labels are left without
// a clear spot.
void split_tabs_for_crowded_labels(Draft& d, const LayoutOptions& o) {
  std::vector<int> wanted = d.tab_sides;
  wanted.resize(d.seams.size(), -1);
  if (want_split_tabs(d, o, wanted)) keep_tabs_if_labels_gain(d, o, std::move(wanted));
}

// The draft's tabs as `o` asks: for its labels (tab_sides_for_labels) or as if there were none.
void plan_tabs_of_draft(Draft& d, const LayoutOptions& o) {
  d.tab_sides.clear();
  if (!o.tabs) {
    d.tabs = TabPlan{};
    d.tabs.tab_of_seam.resize(d.seams.size());
    return;
  }
  if (o.numbers && o.tab_sides_for_labels) d.tab_sides = tab_sides_wanted(d, o);
  d.tabs = plan_draft_tabs(d, o, d.tab_sides);
}

// The labels of a drawn draft, and the tabs that open for those without a clear spot. The sheets are
// not known yet: the labels are placed without the mate's sheet, and placed again where packing puts a
// mate on another sheet (settle_labels).
void label_draft(Draft& d, const LayoutOptions& o) {
  d.labels = place_draft_labels(d, seam_texts(d));
  if (o.tabs && o.tabs_for_labels) {
    open_tabs_for_crowded_labels(d, o);
    if (o.split_tabs_for_labels) split_tabs_for_crowded_labels(d, o);
  }
}

Draft draw_pieces(const unfold::Unfolding& u, const LayoutOptions& o, double scale) {
  constexpr long kSteps = 5;  // pieces, seams, folds, tabs, letters and labels
  report(o, "drawing", 0, kSteps);
  Draft d;
  d.pieces = scaled_pieces(u, scale);
  report(o, "drawing", 1, kSteps);
  d.seams = find_seams(u, d.pieces);
  d.numbers = number_seams(d.pieces, d.seams);
  d.printed = number_seams_by_part(d.seams, d.numbers,
                                   seam_label_room_mm(d.pieces, d.seams, label_options_in_use(o)));
  if (o.hints) d.order = assembly_order(seam_loops(d.pieces, d.seams), d.seams);
  report(o, "drawing", 2, kSteps);
  for (const ScaledPiece& p : d.pieces)
    d.folds.push_back(fold_lines(u, p, o.fold));
  report(o, "drawing", 3, kSteps);

  plan_tabs_of_draft(d, o);
  if (o.arrows) d.arrows = seam_arrows(d.pieces, d.seams);

  report(o, "drawing", 4, kSteps);
  const std::vector<int> rank = letter_ranks(static_cast<int>(d.pieces.size()), d.seams, d.order);
  for (int r : rank)
    d.letters.push_back(piece_letter(r));
  std::vector<std::vector<Polygon>>& taken = d.label_taken;
  taken.resize(d.pieces.size());
  if (o.piece_letters) {
    PieceLetterOptions letter_options;
    letter_options.min_mm = o.label.min_mm;
    d.piece_letters = place_piece_letters(d.pieces, d.folds, d.letters, letter_options);
    for (const PieceLetter& l : d.piece_letters)
      taken[l.piece].push_back(l.footprint_mm);
  }

  if (o.numbers) {
    std::vector<std::vector<FoldLine>>& avoid = d.label_avoid;
    avoid = d.folds;
    for (const Arrow& a : d.arrows)
      avoid[a.piece].push_back({PathRole::Hint, a.tail_mm, a.tip_mm, -1});
    std::vector<std::string>& hints = d.hints;
    if (o.hints) {
      hints.resize(d.seams.size());
      for (std::size_t step = 0; step < d.order.size(); ++step) {
        // Appending piecewise: GCC 12 warns (-Wrestrict, a known false positive) on "(" + s + ")".
        std::string& hint = hints[d.order[step]];
        hint = number_text(static_cast<int>(step) + 1);
        hint.insert(hint.begin(), '(');
        hint.push_back(')');
      }
    }
    d.label_options = label_options_in_use(o);
    label_draft(d, o);
  }
  report(o, "drawing", kSteps, kSteps);
  return d;
}

// Per piece, the convex shapes packing keeps apart besides its tabs: its triangles and the labels
// squeezed onto tiny faces that stick out of them (they must still stay clear of the neighbours and
// inside the printable area).
std::vector<std::vector<Polygon>> piece_bodies(const Draft& d) {
  std::vector<std::vector<Polygon>> bodies(d.pieces.size());
  for (std::size_t p = 0; p < d.pieces.size(); ++p)
    for (const Triangle2& t : d.pieces[p].triangles_mm)
      bodies[p].push_back({t[0], t[1], t[2]});
  for (const Label& label : d.labels)
    if (label.crowded) bodies[label.piece].push_back(label.box_mm);
  return bodies;
}

// The outline packing keeps apart for piece p: its body with its tabs.
std::vector<Polygon> packed_shape(const Draft& d, std::size_t p, std::vector<Polygon> body) {
  for (const Tab* tab : d.tabs.all())
    if (tab->piece == static_cast<int>(p)) body.push_back(tab->quad_mm);
  return polygon_union(body);
}

std::vector<PackItem> pack_items_of(const Draft& d, Vec2 room) {
  std::vector<std::vector<Polygon>> bodies = piece_bodies(d);
  std::vector<PackItem> items(d.pieces.size());
  for (std::size_t p = 0; p < d.pieces.size(); ++p) {
    items[p].shape_mm = packed_shape(d, p, std::move(bodies[p]));
    std::vector<Vec2> points;
    for (const Polygon& poly : items[p].shape_mm)
      points.insert(points.end(), poly.begin(), poly.end());
    items[p].extra_angles_rad.push_back(best_fit_angle(points, room));
  }
  return items;
}

// The largest --size at which every piece (with room for tabs) fits the printable area.
double largest_fitting_size(const unfold::Unfolding& u, const LayoutOptions& o) {
  const Vec2 room = piece_room_mm(o);
  double scale = 1e300;
  for (const ScaledPiece& piece : scaled_pieces(u, 1.0)) {
    std::vector<Vec2> points;
    for (const Triangle2& t : piece.triangles_mm)
      points.insert(points.end(), t.begin(), t.end());
    scale = std::min(scale, max_fit_scale(points, room));
  }
  return scale * u.model_extent;
}

Vec2 to_sheet(Vec2 p, const Rigid2& t, double paper_h) {
  Vec2 q = t.apply(p);
  return {q.x, paper_h - q.y};
}

Text make_text(const std::string& s, Vec2 at, Vec2 dir, double h, PathRole role, int piece, const Rigid2& t,
               double paper_h) {
  const Vec2 d = t.apply_dir(dir);
  // y flips, so the direction's angle on the page (clockwise positive) is atan2(-d.y, d.x).
  return Text{s, to_sheet(at, t, paper_h), h, std::atan2(-d.y, d.x), role, piece};
}

// The texts of a label as printed: `text` (the number, with the mate's letter and sheet) and its hint,
// centred in the box the label reserved, turned half a turn when the piece's rotation would put them
// more than 90 degrees from upright. The box stays the same, so what it keeps clear of still holds.
std::vector<Text> upright_label_texts(const Label& label, const std::string& text,
                                      const LabelOptions& metrics, const Rigid2& t, double paper_h) {
  const double reserved = label.box_mm.size() >= 2 ? norm(label.box_mm[1] - label.box_mm[0]) : 0;
  // A mate on a sheet with more digits than reserved: shrink into the box rather than overflow it.
  const double h = std::min(label.height_mm,
                            label.height_mm * reserved /
                                std::max(label_width_mm(text, label.hint, label.height_mm, metrics), 1e-9));
  const double hint_h = metrics.hint_height_share * h, hint_gap = metrics.hint_gap_share * h;
  const double text_w = label_width_mm(text, h, metrics);
  const double total = label_width_mm(text, label.hint, h, metrics);
  const Vec2 up = perp_ccw(label.dir);
  const Vec2 d = t.apply_dir(label.dir);
  // Page angle, clockwise positive (y down); upright means within [-90, 90) degrees: vertical text
  // reads from the right, bottom to top.
  const double page_angle = std::atan2(-d.y, d.x);
  const bool turn =
      page_angle >= 0.5 * std::numbers::pi - 1e-9 || page_angle < -0.5 * std::numbers::pi - 1e-9;
  const double lead = std::max(0.0, 0.5 * (reserved - total));
  Vec2 start = label.at_mm + label.dir * lead;
  Vec2 dir = label.dir;
  if (turn) {
    // Read from the box's other end, glyphs growing towards the edge, descenders away from it: the same
    // rectangle, from the descent below the baseline (at_mm) to the cap height.
    const double box_height =
        label.box_mm.size() >= 4 ? norm(label.box_mm[3] - label.box_mm[0]) : label.height_mm;
    const double descent = box_height - label.height_mm;
    start = label.at_mm + label.dir * (lead + total) + up * (h - descent);
    dir = -1.0 * label.dir;
  }
  std::vector<Text> out{make_text(text, start, dir, h, PathRole::Label, label.piece, t, paper_h)};
  out.back().width_mm = text_w;
  if (!label.hint.empty()) {
    out.push_back(make_text(label.hint, start + dir * (text_w + hint_gap), dir, hint_h, PathRole::Hint,
                            label.piece, t, paper_h));
    out.back().width_mm = label_width_mm(label.hint, hint_h, metrics);
  }
  return out;
}

// A part letter, upright on the page, centred on its spot.
Text letter_text(const PieceLetter& letter, const Rigid2& t, double paper_h) {
  const double w = letter_width_mm(letter.text, letter.height_mm, PieceLetterOptions{});
  const Vec2 centre = to_sheet(letter.centre_mm, t, paper_h);
  return Text{letter.text,      centre + Vec2{-0.5 * w, 0.5 * letter.height_mm},
              letter.height_mm, 0,
              PathRole::Piece,  letter.piece};
}

// The assembly-order list as text blocks (sheet frame is applied later), each at most `max_h` tall.
constexpr double kListLine_mm = 3.6;  // line pitch of the list

struct ListBlock {
  std::vector<std::string> lines;
  Vec2 size_mm;
};

std::vector<ListBlock> assembly_blocks(const Draft& d, Vec2 area_size) {
  constexpr double kColumn_mm = 16;
  std::vector<std::string> entries;
  for (std::size_t step = 0; step < d.order.size(); ++step)
    entries.push_back(std::to_string(step + 1) + ". " + listed_seam_name(d, d.order[step]));
  std::vector<ListBlock> blocks;
  const int columns = std::max(1, static_cast<int>((area_size.x - 4) / kColumn_mm));
  const int rows_max = std::max(4, static_cast<int>((area_size.y - 4) / kListLine_mm) - 2);
  std::size_t at = 0;
  while (at < entries.size()) {
    ListBlock block;
    block.lines.push_back(blocks.empty() ? "Glue in this order (step. seam):" : "Glue order, continued:");
    const std::size_t left = entries.size() - at;
    const int cols = static_cast<int>(std::min<std::size_t>(columns, (left + 9) / 10));
    const int rows = static_cast<int>(std::min<std::size_t>(rows_max, (left + cols - 1) / cols));
    for (int r = 0; r < rows; ++r) {
      std::string line;
      for (int c = 0; c < cols; ++c) {
        const std::size_t i = at + static_cast<std::size_t>(c) * rows + r;
        if (i >= entries.size() || i >= at + static_cast<std::size_t>(rows) * cols) continue;
        std::string cell = entries[i];
        cell.resize(std::max<std::size_t>(cell.size(), 9), ' ');
        line += cell;
      }
      block.lines.push_back(line);
    }
    const double width = std::max(cols * kColumn_mm, 60.0);
    block.size_mm = {width, (rows + 1) * kListLine_mm + 1};
    at += static_cast<std::size_t>(rows) * cols;
    blocks.push_back(std::move(block));
  }
  return blocks;
}

// Without a glue order, parts are lettered in sheet order (A, B, C on sheet 1, D, E on sheet 2), so
// that the part list on each sheet says where a mate is even where a label has no room for "p2". Only
// while every letter is one character: then letters swap without changing any label's width class.
void letter_by_sheet(Draft& d, const LayoutOptions& o, std::span<const int> sheet_of_piece) {
  const int count = static_cast<int>(d.pieces.size());
  if (o.hints || count < 2 || piece_letter(count - 1).size() > 1) return;
  std::vector<int> by_sheet(d.pieces.size());
  std::iota(by_sheet.begin(), by_sheet.end(), 0);
  std::stable_sort(by_sheet.begin(), by_sheet.end(),
                   [&](int a, int b) { return sheet_of_piece[a] < sheet_of_piece[b]; });
  for (int r = 0; r < count; ++r) {
    d.letters[by_sheet[r]] = piece_letter(r);
    if (static_cast<std::size_t>(by_sheet[r]) < d.piece_letters.size())
      d.piece_letters[by_sheet[r]].text = d.letters[by_sheet[r]];
  }
}

// Once packing has put the parts on sheets: letters in sheet order, and the labels placed again with
// the mate's sheet where it is another ("B12 p2"). Packing kept room for the first labels that stick
// out of tiny faces, so a piece takes its new labels only when every one that sticks out stays inside
// the packed shape; otherwise it keeps the first ones with their texts brought up to date (shrunk into
// their boxes when printed, should a letter be wider).
void settle_labels(Draft& d, const LayoutOptions& o, std::span<const PackItem> items,
                   const PackResult& packed) {
  std::vector<int> sheet_of_piece;
  for (std::size_t p = 0; p < d.pieces.size(); ++p)
    sheet_of_piece.push_back(packed.placements[p].sheet);
  letter_by_sheet(d, o, sheet_of_piece);
  if (d.labels.empty()) return;
  const SeamTexts texts = seam_texts(d, sheet_of_piece);
  std::vector<bool> changed(d.pieces.size(), false);
  bool any = false;
  for (const Label& l : d.labels)
    if (l.text != texts.full[l.seam.index()][l.side]) changed[l.piece] = any = true;
  if (!any) return;
  std::vector<Label> again = place_draft_labels_again(d, texts, d.labels, changed);
  // A new label that sticks out where packing kept no room gives way to the first label of its side
  // (packed, so inside the shape) when that one is clear of the piece's new labels; else the piece
  // keeps all its first labels.
  std::map<std::pair<SeamId, int>, const Label*> first_of;
  for (const Label& l : d.labels)
    first_of[{l.seam, l.side}] = &l;
  std::vector<bool> take = changed;
  std::vector<std::vector<std::size_t>> again_of(d.pieces.size());
  for (std::size_t i = 0; i < again.size(); ++i)
    again_of[again[i].piece].push_back(i);
  for (std::size_t p = 0; p < d.pieces.size(); ++p) {
    if (!take[p]) continue;
    for (std::size_t i : again_of[p]) {
      const Label& l = again[i];
      const std::array<Polygon, 1> box{l.box_mm};
      if (!l.crowded || intersection_area(box, items[p].shape_mm) >= signed_area(l.box_mm) - 1e-6) continue;
      const Label* first = first_of[{l.seam, l.side}];
      bool clear = first != nullptr;
      for (std::size_t j : again_of[p])
        clear = clear && (j == i || !convex_overlap(first->box_mm, again[j].box_mm, 0));
      if (!clear) {
        take[p] = false;
        break;
      }
      again[i] = *first;
      again[i].text = texts.brief[l.seam.index()][l.side];
    }
  }
  std::vector<Label> labels;
  for (Label& l : d.labels)
    if (!take[l.piece]) {
      l.text = texts.brief[l.seam.index()][l.side];
      labels.push_back(std::move(l));
    }
  for (Label& l : again)
    if (take[l.piece]) labels.push_back(std::move(l));
  d.labels = std::move(labels);
}

// The flat face each triangle belongs to (its root): no fold line crosses a flat face, so a label
// beside one of its edges may use all of it, not only the triangle on that edge.
std::vector<int> flat_face_roots(const unfold::Unfolding& u) {
  unfold::DisjointSets sets(u.num_faces());
  for (const unfold::UnfoldEdge& e : u.edges)
    if (e.inside_face && !e.boundary()) sets.join(e.face[0], e.face[1]);
  std::vector<int> root(static_cast<std::size_t>(u.num_faces()));
  for (int f = 0; f < u.num_faces(); ++f)
    root[static_cast<std::size_t>(f)] = sets.find(f);
  return root;
}

// How far the flat face of `face` reaches from the line of edge `e` into the piece: the height of the
// triangle on the edge for a triangle, the farthest corner of the polygon for a quad or n-gon.
double flat_face_height_mm(const ScaledPiece& piece, const OutlineEdge& e, std::span<const int> root) {
  const double length = norm(e.b - e.a);
  const Vec2 up = perp_ccw((e.b - e.a) / length);
  double height = 0;
  for (std::size_t k = 0; k < piece.faces.size(); ++k) {
    if (root[static_cast<std::size_t>(piece.faces[k])] != root[static_cast<std::size_t>(e.face)]) continue;
    for (Vec2 c : piece.triangles_mm[k])
      height = std::max(height, dot(c - e.a, up));
  }
  return height;
}

// What the labels of a draft say about the model's size: how many found no clear spot, and how much
// larger the model must be for them to find one. Per label, the scale at which its flat face is wide
// enough for the label's box at its lift above the edge (a triangle narrows linearly towards its apex),
// then the factor that leaves at most 2% of the labels without room (a sliver face needs absurd sizes
// and should not decide the advice); 1 when at most 2% lack room. Edges shorter than a label is high do
// not count either: a 0.2 mm edge would ask for a model 30 times larger, and its seam is found by its
// neighbours' numbers.
struct LabelRoom {
  int without_room = 0;
  double factor = 1;
};

LabelRoom label_room(const Draft& d, const unfold::Unfolding& u) {
  constexpr double kTolerated = 0.02;
  const LabelOptions& metrics = d.label_options;  // as placed
  const std::vector<int> root = flat_face_roots(u);
  std::vector<double> factors;
  LabelRoom room;
  for (const Label& label : d.labels) {
    if (has_clear_spot(label)) continue;
    ++room.without_room;
    const SeamSide& side = d.seams[label.seam.index()].sides[label.side];
    const ScaledPiece& piece = d.pieces[side.piece];
    const OutlineEdge& e = piece.outline_mm[side.loop][side.index];
    const double length = norm(e.b - e.a);
    if (!(length >= metrics.min_mm) || e.face < 0 || e.face >= u.num_faces()) continue;
    const double height = flat_face_height_mm(piece, e, root);
    const double h = metrics.min_mm;
    const double width =
        norm(label.box_mm[1] - label.box_mm[0]) * h / label.height_mm + 2 * metrics.clearance_mm;
    const double lift = metrics.gap_mm + h + metrics.clearance_mm;
    factors.push_back((width + lift * length / std::max(height, 1e-9)) / length);
  }
  const auto allowed = static_cast<std::size_t>(kTolerated * static_cast<double>(d.labels.size()));
  if (room.without_room <= static_cast<int>(allowed) || factors.size() <= allowed) return room;
  std::sort(factors.begin(), factors.end(), std::greater<>());
  room.factor = std::max(1.05, factors[allowed]);
  return room;
}

// The remedy a maker can trust: the estimate sees each label alone, so the pieces are drawn again at
// the advised size (tabs and labels, no packing), and the advice grows by what is still missing there,
// for a few rounds. The same pieces at the larger size: parts the pipeline would cut smaller there
// are not foreseen.
void measure_label_room(const Draft& d, const unfold::Unfolding& u, const LayoutOptions& o, LayoutResult& r) {
  constexpr int kRemedyRounds = 5;
  // Labels that compete for one face are not in the estimate: where they still lack room at the
  // advised size, the next round asks for at least this much more.
  constexpr double kLeastGrowth = 1.2;
  const LabelRoom asked = label_room(d, u);
  r.labels_without_room = asked.without_room;
  for (const Label& l : d.labels)
    if (!has_clear_spot(l))
      r.crowded_labels.push_back({l.text, listed_seam_name(d, static_cast<int>(l.seam.index())), l.piece});
  double factor = asked.factor;
  LayoutOptions quiet = o;
  quiet.progress = nullptr;
  for (int round = 0; round < kRemedyRounds && factor > 1; ++round) {
    const LabelRoom there = label_room(draw_pieces(u, quiet, r.scale_mm_per_unit * factor), u);
    if (!(there.factor > 1)) break;
    factor *= std::max(there.factor, kLeastGrowth);
  }
  r.label_room_factor = factor;
}

struct Attempt {
  LayoutResult result;
  bool complete = false;
  long packed_sheets = 0;  ///< the sheets the packing took (0 when it left pieces over)
};

// What packing was given and what it made of it: the pieces (with their tabs) first, then the blocks of
// the assembly list.
struct Packing {
  std::vector<PackItem> items;
  std::size_t piece_items = 0;
  std::vector<ListBlock> blocks;
  PackResult packed;
};

// The pack options in use: the stage's own (spacing, rotations, cell, engine) with where to pack.
PackOptions pack_options_in_use(const LayoutOptions& o, const Box2& area, std::optional<int> max_sheets) {
  PackOptions p = o.pack;
  p.area_mm = area;
  p.keep_out_mm.clear();
  p.max_sheets = max_sheets;
  p.deadline = o.deadline;
  p.progress = nullptr;
  if (o.progress) p.progress = [&o](long done, long total) { report(o, "packing", done, total); };
  if (o.regmarks)
    for (const Box2& b : regmark_keep_out(o.paper_mm, o.regmark))
      p.keep_out_mm.push_back(flip_box(b, o.paper_mm.y));
  return p;
}

// Packs the pieces with their tabs and, with hints, the assembly list's blocks (upright).
Packing pack_draft(const Draft& d, const LayoutOptions& o, const Box2& area, std::optional<int> max_sheets) {
  Packing k;
  k.items = pack_items_of(d, piece_room_mm(o));
  k.piece_items = k.items.size();
  if (o.hints) {
    k.blocks = assembly_blocks(d, Vec2{area.width(), area.height()});
    for (const ListBlock& b : k.blocks) {
      PackItem item;
      item.rotate = false;  // text reads upright
      item.shape_mm = {{{0, 0}, {b.size_mm.x, 0}, b.size_mm, {0, b.size_mm.y}}};
      k.items.push_back(std::move(item));
    }
  }
  k.packed = pack_items(k.items, pack_options_in_use(o, area, max_sheets));
  return k;
}

// The labels of the pieces `changed` marks that stick out of their tiny faces, each with its piece.
std::vector<std::pair<int, Polygon>> crowded_labels_of(const Draft& d, const std::vector<bool>& changed) {
  std::vector<std::pair<int, Polygon>> boxes;
  for (const Label& l : d.labels)
    if (l.crowded && changed[l.piece]) boxes.emplace_back(l.piece, l.box_mm);
  return boxes;
}

// A draft packed with plainer tabs than its labels want (the part chooser's layout again with fewer
// tabs for labels, when those cost a sheet) takes the tabs planned for its labels seam by seam wherever
// the packed sheets have room for them (tabs_in_place), and its labels placed again; kept when fewer
// labels are left without a clear spot. No piece moves; the packed shapes grow by the tabs taken.
void take_label_tabs_in_place(const unfold::Unfolding& u, Draft& d, const LayoutOptions& o, Packing& k) {
  // The tabs wanted take a second drawing with its labels: on a 2,000-face mesh up to 0.8 s of the 3 s
  // a layout may take (koala_2000 at 250 mm 2.9 -> 3.6 s).
  constexpr int kMostFaces = 1500;
  if (u.num_faces() > kMostFaces) return;
  if (!o.label_tabs_in_place || !o.numbers || !o.tabs || labels_without_clear_spot(d.labels) == 0) return;
  if (o.tab_sides_for_labels && o.tabs_for_labels && o.split_tabs_for_labels) return;
  LayoutOptions full = o;
  full.tab_sides_for_labels = full.tabs_for_labels = full.split_tabs_for_labels = true;
  Draft wanted = d;
  plan_tabs_of_draft(wanted, full);
  label_draft(wanted, full);
  std::vector<std::pair<int, Polygon>> others;
  for (std::size_t i = k.piece_items; i < k.items.size(); ++i) {
    const PackPlacement& at = k.packed.placements[i];
    for (const Polygon& shape : k.items[i].shape_mm)
      others.emplace_back(at.sheet, at.transform.apply(shape));
  }
  const PackOptions packing = pack_options_in_use(o, packing_area(o), std::nullopt);
  const auto room_with = [&](const std::vector<std::vector<Polygon>>& bodies) {
    return PackedRoom{std::span(k.packed.placements).first(k.piece_items),
                      bodies,
                      others,
                      packing.area_mm,
                      packing.keep_out_mm,
                      packing.spacing_mm};
  };
  TabPlan kept =
      std::exchange(d.tabs, tabs_in_place(d.seams, d.tabs, wanted.tabs, room_with(piece_bodies(d))));
  const std::vector<bool> changed = pieces_with_other_tabs(d, kept, d.tabs);
  std::vector<Label> again = place_draft_labels_again(d, seam_texts(d), d.labels, changed);
  std::swap(again, d.labels);
  if (labels_without_clear_spot(d.labels) >= labels_without_clear_spot(again) ||
      !clear_in_place(crowded_labels_of(d, changed), d.seams, d.tabs, room_with(piece_bodies(d)))) {
    d.labels = std::move(again);
    d.tabs = std::move(kept);
    return;
  }
  std::vector<std::vector<Polygon>> bodies = piece_bodies(d);
  for (std::size_t p = 0; p < d.pieces.size(); ++p)
    if (changed[p]) k.items[p].shape_mm = packed_shape(d, p, std::move(bodies[p]));
}

// The refusal when a piece fits no sheet at the asked size, naming the largest size that fits.
PieceTooLarge piece_too_large(const unfold::Unfolding& u, const LayoutOptions& o, int piece, double size_mm) {
  const Box2 area = packing_area(o);
  const double largest = std::floor(std::min(largest_fitting_size(u, o), size_mm * 0.99));
  return PieceTooLarge(piece, {area.width(), area.height()}, size_mm, largest);
}

std::vector<Sheet> blank_sheets(const LayoutOptions& o, int count) {
  std::vector<Sheet> sheets(static_cast<std::size_t>(count));
  for (Sheet& s : sheets) {
    s.size_mm = o.paper_mm;
    s.printable_mm = printable_area(o);
    if (o.regmarks) {
      auto marks = regmark_paths(o.paper_mm, o.regmark);
      s.paths.insert(s.paths.end(), marks.begin(), marks.end());
    }
  }
  return sheets;
}

// Where one piece goes on its sheet: the packing's motion, then the flip to the sheet's y-down frame.
struct SheetFrame {
  const Rigid2& t;
  double paper_h = 0;
  Vec2 operator()(Vec2 p) const { return to_sheet(p, t, paper_h); }
};

// What the draft keeps per seam, looked up per piece and outline edge when the sheets are emitted.
struct DraftIndex {
  std::vector<std::vector<std::vector<const Tab*>>> tab_at;  // per piece, loop, outline index
  std::vector<std::vector<const Tab*>> tabs_of;              // per piece
  std::vector<std::vector<int>> labels_of;                   // per piece: indices into Draft::labels
};

DraftIndex index_draft(const Draft& d) {
  DraftIndex x;
  x.tab_at.resize(d.pieces.size());
  for (std::size_t p = 0; p < d.pieces.size(); ++p)
    for (const OutlineLoop& loop : d.pieces[p].outline_mm)
      x.tab_at[p].emplace_back(loop.size(), nullptr);
  for (const Tab* tab : d.tabs.all()) {
    const SeamSide& side = d.seams[tab->seam.index()].sides[tab->side];
    x.tab_at[side.piece][side.loop][side.index] = tab;
  }
  // Labels by piece: emitting them piece by piece must not scan every label for every piece.
  x.labels_of.resize(d.pieces.size());
  for (std::size_t i = 0; i < d.labels.size(); ++i)
    x.labels_of[d.labels[i].piece].push_back(static_cast<int>(i));
  x.tabs_of.resize(d.pieces.size());
  for (const Tab* tab : d.tabs.all())
    x.tabs_of[tab->piece].push_back(tab);
  return x;
}

// The piece's outline loops as cut paths, with the tab corners spliced in: the cutter follows the tab
// instead of the edge.
void emit_cuts(const ScaledPiece& scaled, int piece, const std::vector<std::vector<const Tab*>>& tab_at,
               const SheetFrame& f, Sheet& sheet) {
  for (std::size_t l = 0; l < scaled.outline_mm.size(); ++l) {
    Path cut{PathRole::Cut, {}, true, piece};
    const OutlineLoop& loop = scaled.outline_mm[l];
    for (std::size_t i = 0; i < loop.size(); ++i) {
      cut.points_mm.push_back(f(loop[i].a));
      if (const Tab* tab = tab_at[l][i]) {
        // A tab may cover only part of its edge: then the cut runs along the edge to the tab first.
        if (norm(tab->quad_mm[0] - loop[i].a) > 1e-9) cut.points_mm.push_back(f(tab->quad_mm[0]));
        cut.points_mm.push_back(f(tab->quad_mm[1]));
        cut.points_mm.push_back(f(tab->quad_mm[2]));
        if (norm(tab->quad_mm[3] - loop[i].b) > 1e-9) cut.points_mm.push_back(f(tab->quad_mm[3]));
      }
    }
    sheet.paths.push_back(std::move(cut));
  }
}

void emit_tabs(std::span<const Tab* const> tabs, int piece, const SheetFrame& f, Sheet& sheet,
               SheetStats& st) {
  for (const Tab* tab : tabs) {
    Path area{PathRole::Tab, {}, true, piece};
    for (Vec2 v : tab->quad_mm)
      area.points_mm.push_back(f(v));
    sheet.paths.push_back(std::move(area));
    // The tab folds away from the printed side, behind its partner: a mountain fold seen from here.
    sheet.paths.push_back({PathRole::Mountain, {f(tab->quad_mm[0]), f(tab->quad_mm[3])}, false, piece});
    st.tabs += 1;
    st.tab_area_mm2 += signed_area(tab->quad_mm);
  }
}

// Everything one piece prints, in drawing order: its cuts, folds, tabs, arrows, labels and letter.
void emit_piece(const Draft& d, const DraftIndex& x, std::size_t p, const SheetFrame& f, Sheet& sheet,
                SheetStats& st) {
  const int piece = static_cast<int>(p);
  st.pieces += 1;
  st.piece_area_mm2 += d.pieces[p].area_mm2;
  emit_cuts(d.pieces[p], piece, x.tab_at[p], f, sheet);
  for (const FoldLine& fold : d.folds[p])
    sheet.paths.push_back({fold.role, {f(fold.a), f(fold.b)}, false, piece});
  emit_tabs(x.tabs_of[p], piece, f, sheet, st);
  for (const Arrow& a : d.arrows) {
    if (a.piece != piece) continue;
    Path arrow{PathRole::Hint, {}, false, piece};
    for (Vec2 v : a.points_mm)
      arrow.points_mm.push_back(f(v));
    arrow.tint = d.numbers[a.seam.index()] - 1;
    sheet.paths.push_back(std::move(arrow));
  }
  for (int li : x.labels_of[p]) {
    const Label& label = d.labels[li];
    for (Text& out : upright_label_texts(label, label.text, d.label_options, f.t, f.paper_h))
      sheet.texts.push_back(std::move(out));
    for (const std::array<Vec2, 2>& segment : label.leader_mm)
      sheet.paths.push_back({PathRole::Label, {f(segment[0]), f(segment[1])}, false, piece});
    st.leaders += !label.leader_mm.empty();
    st.labels += 1;
    st.min_label_mm = st.min_label_mm == 0 ? label.height_mm : std::min(st.min_label_mm, label.height_mm);
  }
  if (p < d.piece_letters.size()) sheet.texts.push_back(letter_text(d.piece_letters[p], f.t, f.paper_h));
}

// The assembly list's blocks where packing put them; lines top-down inside each block's own frame (y up).
void emit_assembly_blocks(const Packing& k, double paper_h, std::vector<Sheet>& sheets) {
  constexpr double kText_mm = 2.4, kIndent_mm = 1;
  for (std::size_t b = 0; b < k.blocks.size(); ++b) {
    const PackPlacement& place = k.packed.placements[k.piece_items + b];
    const ListBlock& block = k.blocks[b];
    for (std::size_t i = 0; i < block.lines.size(); ++i) {
      const Vec2 at{kIndent_mm, block.size_mm.y - kListLine_mm * (static_cast<double>(i) + 1)};
      sheets[place.sheet].texts.push_back(
          make_text(block.lines[i], at, {1, 0}, kText_mm, PathRole::Hint, -1, place.transform, paper_h));
    }
  }
}

FurnitureOptions furniture_options_of(const LayoutOptions& o) {
  FurnitureOptions furniture;
  furniture.model_name = o.model_name;
  furniture.spacing_mm = o.pack.spacing_mm;
  return furniture;
}

// The area an item's shape takes grown by half the spacing (SheetStats::spaced_area_mm2).
double spaced_area_mm2(const PackItem& item, double spacing_mm) {
  constexpr double kArcTolerance_mm = 0.01;
  return std::fabs(total_area(polygon_offset(item.shape_mm, 0.5 * spacing_mm, kArcTolerance_mm)));
}

// Returns the sheets that got no 1 in square.
std::vector<int> emit_furniture(const LayoutOptions& o, LayoutResult& r) {
  std::vector<Box2> keep_out;
  if (o.regmarks) keep_out = regmark_keep_out(o.paper_mm, o.regmark);
  const std::vector<int> crowded = add_sheet_furniture(r.sheets, keep_out, furniture_options_of(o));
  if (!crowded.empty())
    r.notes.push_back(std::to_string(crowded.size()) +
                      " sheet(s) without the 1 in scale square: no free spot, and a corner kept for it would "
                      "cost a sheet (the 50 mm bar is in the margin)");
  return crowded;
}

// Each sheet's coverage, and the sums over all sheets.
void total_stats(double printable_mm2, LayoutResult& r) {
  for (SheetStats& st : r.sheet_stats) {
    st.coverage = (st.piece_area_mm2 + st.tab_area_mm2) / printable_mm2;
    r.overall.pieces += st.pieces;
    r.overall.tabs += st.tabs;
    r.overall.dropped_tabs += st.dropped_tabs;
    r.overall.split_tabs += st.split_tabs;
    r.overall.leaders += st.leaders;
    r.overall.labels += st.labels;
    r.overall.piece_area_mm2 += st.piece_area_mm2;
    r.overall.tab_area_mm2 += st.tab_area_mm2;
    r.overall.spaced_area_mm2 += st.spaced_area_mm2;
    if (st.min_label_mm > 0)
      r.overall.min_label_mm =
          r.overall.min_label_mm == 0 ? st.min_label_mm : std::min(r.overall.min_label_mm, st.min_label_mm);
  }
  if (!r.sheets.empty())
    r.overall.coverage =
        (r.overall.piece_area_mm2 + r.overall.tab_area_mm2) / (printable_mm2 * r.sheets.size());
}

// The seams without a tab: a note with how many (and how many are slits: no tab fits there; the maker
// closes them edge to edge, tape behind), and their printed numbers (JSON: a list of hundreds is no note).
void note_dropped_tabs(const Draft& d, const LayoutOptions& o, LayoutResult& r) {
  if (d.tabs.dropped.empty()) return;
  int slits = 0;
  for (SeamId s : d.tabs.dropped)
    slits += is_narrow_slit(d.pieces, d.seams[s.index()], tab_options_in_use(o));
  r.notes.push_back(
      std::to_string(d.tabs.dropped.size()) + " seam(s) without a glue tab (no room on either side" +
      (slits > 0 ? "; " + std::to_string(slits) + " of them narrow slits to close edge to edge" : "") + ")");
  for (SeamId s : d.tabs.dropped)
    r.dropped_tab_seams.push_back(listed_seam_name(d, static_cast<int>(s.index())));
}

// The sheets of a complete packing: pieces, assembly list, furniture, then the figures and notes.
// Returns the sheets that got no 1 in square.
std::vector<int> emit_sheets(const unfold::Unfolding& u, const LayoutOptions& o, Draft& d, const Packing& k,
                             LayoutResult& r) {
  const double paper_h = o.paper_mm.y;
  r.paper_height_mm = paper_h;
  report(o, "labelling", 0, 1);
  settle_labels(d, o, k.items, k.packed);
  report(o, "labelling", 1, 1);
  for (std::size_t p = 0; p < d.pieces.size(); ++p) {
    const PackPlacement& place = k.packed.placements[p];
    r.placements.push_back({place.sheet, place.transform.angle_rad, place.transform.offset_mm});
  }
  r.sheets = blank_sheets(o, k.packed.sheet_count);
  r.sheet_stats.resize(k.packed.sheet_count);
  const DraftIndex x = index_draft(d);
  const long piece_count = static_cast<long>(d.pieces.size());
  for (std::size_t p = 0; p < d.pieces.size(); ++p) {
    report(o, "sheets", static_cast<long>(p), piece_count);
    const PackPlacement& place = k.packed.placements[p];
    emit_piece(d, x, p, SheetFrame{place.transform, paper_h}, r.sheets[place.sheet],
               r.sheet_stats[place.sheet]);
    r.sheet_stats[place.sheet].spaced_area_mm2 += spaced_area_mm2(k.items[p], o.pack.spacing_mm);
  }
  report(o, "sheets", piece_count, piece_count);
  for (SeamId s : d.tabs.dropped) {
    const SeamSide& side = d.seams[s.index()].sides[0];
    if (side.piece >= 0) r.sheet_stats[k.packed.placements[side.piece].sheet].dropped_tabs += 1;
  }
  for (std::size_t s = 0; s < d.seams.size(); ++s)
    if (d.tabs.is_split(s))
      r.sheet_stats[k.packed.placements[d.seams[s].sides[0].piece].sheet].split_tabs += 1;
  emit_assembly_blocks(k, paper_h, r.sheets);
  const std::vector<int> without_square = o.furniture ? emit_furniture(o, r) : std::vector<int>{};
  const Box2 area = packing_area(o);
  total_stats(area.width() * area.height(), r);
  note_dropped_tabs(d, o, r);
  measure_label_room(d, u, o, r);
  r.piece_letters = d.letters;
  for (const Sheet& sheet : r.sheets)
    r.label_audit += audit_labels(sheet);
  r.seam_number.assign(u.edges.size(), 0);
  for (std::size_t s = 0; s < d.seams.size(); ++s)
    r.seam_number[d.seams[s].edge] = d.printed[s];
  for (std::size_t step = 0; step < d.order.size(); ++step) {
    const int s = d.order[step];
    r.assembly.push_back({static_cast<int>(step) + 1, d.printed[s], d.seams[s].fold_angle_rad,
                          d.seams[s].edge, listed_seam_name(d, s)});
  }
  return without_square;
}

// The packing options with the bottom-right corner of every sheet kept free for the least furniture
// block (the 1 in square), in the packing frame (y up: the paper's bottom is the area's min.y).
PackOptions with_corner_kept(PackOptions p, const LayoutOptions& o) {
  const Box2 printable = printable_area(o);
  // The furniture finds its spot with its own spacing test: a millimetre more keeps the two from
  // disagreeing over a part that just touches the corner's edge.
  constexpr double kSlack_mm = 1;
  const Vec2 block = least_furniture_block_mm(o.paper_mm.y - printable.max.y, furniture_options_of(o)) +
                     Vec2{kSlack_mm, kSlack_mm};
  const Box2 area = p.area_mm;
  p.keep_out_mm.push_back(Box2{{area.max.x - block.x, area.min.y}, {area.max.x, area.min.y + block.y}});
  return p;
}

// An empty result at the scale of `r`, for a layout of the same pieces.
LayoutResult scaled_like(const LayoutResult& r) {
  LayoutResult again;
  again.scale_mm_per_unit = r.scale_mm_per_unit;
  again.spacing_mm = r.spacing_mm;
  again.size_mm = r.size_mm;
  return again;
}

// The options of a layout again with a corner kept for the square, its stages named after `prefix`: a
// stage's counts only rise.
LayoutOptions corner_stages(const LayoutOptions& o, const char* prefix) {
  LayoutOptions second = o;
  if (o.progress)
    second.progress = [report = o.progress, prefix](const LayoutProgress& p) {
      report({prefix + p.stage, p.done, p.total});
    };
  return second;
}

// A packing the layout can do without: past the deadline it gives up (nullopt) instead of throwing, so a
// complete layout is never lost to a late extra.
std::optional<PackResult> pack_if_in_time(std::span<const PackItem> items, const PackOptions& p) {
  try {
    return pack_items(items, p);
  } catch (const LayoutError&) {
    return std::nullopt;
  }
}

// The pieces of each sheet without its square packed again onto that sheet alone, with a corner kept for
// it. No piece changes sheet, so the letters and the labels' texts stay. False when no sheet's pieces fit.
bool keep_corners_on_their_sheets(const LayoutOptions& o, const std::vector<int>& without_square,
                                  Packing& k) {
  PackOptions one_sheet = with_corner_kept(pack_options_in_use(o, packing_area(o), 1), o);
  one_sheet.progress = nullptr;  // a sheet's pieces pack in a moment
  bool moved = false;
  for (int sheet : without_square) {
    std::vector<std::size_t> on_sheet;
    std::vector<PackItem> items;
    for (std::size_t i = 0; i < k.items.size(); ++i) {
      if (k.packed.placements[i].sheet != sheet) continue;
      on_sheet.push_back(i);
      items.push_back(k.items[i]);
    }
    const std::optional<PackResult> alone = pack_if_in_time(items, one_sheet);
    if (!alone) break;
    if (!alone->unplaced.empty() || alone->sheet_count != 1) continue;
    for (std::size_t j = 0; j < on_sheet.size(); ++j)
      k.packed.placements[on_sheet[j]].transform = alone->placements[j].transform;
    moved = true;
  }
  return moved;
}

// Pieces may move from sheet to sheet: letters change, and so do the labels that name a mate.
constexpr int kMostFacesToRelabel = 1500;

// A complete layout left some sheets without their scale check: each such sheet is packed again with a
// corner kept for the square (its own pieces, onto it alone; then, where that left a sheet without and
// the model has at most kMostFacesToRelabel faces, all pieces onto no more sheets), and the layout with
// the new placements replaces `r` when fewer sheets go without. A square is not worth a sheet of paper.
// `drawn` is the draft as drawn, `settled` with its letters and labels for the first packing.
void keep_corner_for_square(const unfold::Unfolding& u, const LayoutOptions& o, const Draft& drawn,
                            const Draft& settled, const Packing& first, std::vector<int> without_square,
                            LayoutResult& r) {
  if (without_square.empty() || (o.deadline && std::chrono::steady_clock::now() > *o.deadline)) return;
  const LayoutOptions second = corner_stages(o, kCornerStage);
  Packing k = first;
  if (keep_corners_on_their_sheets(second, without_square, k)) {
    Draft d = settled;
    LayoutResult again = scaled_like(r);
    std::vector<int> still = emit_sheets(u, second, d, k, again);
    if (still.size() < without_square.size()) {
      r = std::move(again);
      without_square = std::move(still);
    }
  }
  if (without_square.empty() || u.num_faces() > kMostFacesToRelabel) return;
  const LayoutOptions third = corner_stages(o, kCornersStage);
  k = first;
  std::optional<PackResult> again_packed = pack_if_in_time(
      k.items, with_corner_kept(pack_options_in_use(third, packing_area(o), first.packed.sheet_count), o));
  if (!again_packed || !again_packed->unplaced.empty() ||
      again_packed->sheet_count > first.packed.sheet_count)
    return;
  k.packed = std::move(*again_packed);
  Draft d = drawn;
  LayoutResult again = scaled_like(r);
  if (emit_sheets(u, third, d, k, again).size() < without_square.size()) r = std::move(again);
}

// One layout at `scale`: drawn, packed (on at most max_sheets when set) and emitted. Incomplete when
// pieces are left over with max_sheets; without it, a piece that fits no sheet is a LayoutError. Also
// incomplete, and not emitted, when the packing takes more than `finish_within` sheets.
Attempt build(const unfold::Unfolding& u, const LayoutOptions& o, double scale, std::optional<int> max_sheets,
              std::optional<long> finish_within = std::nullopt) {
  Attempt attempt;
  LayoutResult& r = attempt.result;
  r.scale_mm_per_unit = scale;
  r.size_mm = scale * u.model_extent;
  r.spacing_mm = o.pack.spacing_mm;
  Draft d = draw_pieces(u, o, scale);
  if (o.deadline && std::chrono::steady_clock::now() > *o.deadline)
    throw LayoutError("stopped at the time limit after drawing " + std::to_string(d.pieces.size()) +
                      " pieces, before packing them");
  Packing k = pack_draft(d, o, packing_area(o), max_sheets);
  if (!k.packed.unplaced.empty()) {
    if (!max_sheets) throw piece_too_large(u, o, k.packed.unplaced.front(), r.size_mm);
    return attempt;
  }
  attempt.packed_sheets = k.packed.sheet_count;
  if (finish_within && attempt.packed_sheets > *finish_within) return attempt;
  attempt.complete = true;
  take_label_tabs_in_place(u, d, o, k);
  std::optional<Draft> drawn;
  if (o.furniture) drawn = d;  // emitting settles the letters and labels on the draft
  std::vector<int> without_square = emit_sheets(u, o, d, k, r);
  if (drawn) keep_corner_for_square(u, o, *drawn, d, k, std::move(without_square), r);
  return attempt;
}

double total_model_area(const unfold::Unfolding& u) {
  double a = 0;
  for (const Triangle2& t : u.flat)
    a += std::fabs(signed_area(t));
  return a;
}

}  // namespace

Box2 printable_area(const LayoutOptions& o) {
  Box2 area{{o.margin_mm, o.margin_mm}, {o.paper_mm.x - o.margin_mm, o.paper_mm.y - o.margin_mm}};
  if (o.regmarks) {
    const Box2 reach = regmark_cut_area(o.paper_mm, o.regmark);
    area = Box2{{std::max(area.min.x, reach.min.x), std::max(area.min.y, reach.min.y)},
                {std::min(area.max.x, reach.max.x), std::min(area.max.y, reach.max.y)}};
  }
  return area;
}

long spaced_sheet_bound(const LayoutResult& r, const LayoutOptions& o) {
  const Box2 area = printable_area(o);
  const double half_gap = 0.5 * r.spacing_mm;
  // The rectangle grown by half a gap: its sides pushed out, its corners rounded.
  const double room_mm2 = (area.width() + 2 * half_gap) * (area.height() + 2 * half_gap) -
                          (4 - std::numbers::pi) * half_gap * half_gap;
  if (!(room_mm2 > 0) || !(r.overall.spaced_area_mm2 > 0)) return 0;
  constexpr double kRounding = 1e-9;  // a share that fills whole sheets exactly is not one more
  return static_cast<long>(std::ceil(r.overall.spaced_area_mm2 / room_mm2 - kRounding));
}

double narrow_slit_gap_mm(const LayoutOptions& o) {
  return o.tabs ? narrow_slit_gap_mm(tab_options_in_use(o)) : 0;
}

double piece_border_mm(const LayoutOptions& o) {
  return (o.tabs ? o.tab.width_mm : 0) + o.pack.spacing_mm + 2 * o.pack.cell_mm;
}

Vec2 piece_room_mm(const LayoutOptions& o) {
  const Box2 area = printable_area(o);
  const double border = piece_border_mm(o);
  Vec2 room{area.width() - 2 * border, area.height() - 2 * border};
  if (o.regmarks) {
    // The marks' keep-out zones take corners of the area: the band between them across the longer
    // side is a rectangle free of them.
    double top = 0, bottom = 0, left = 0, right = 0;
    for (const Box2& z : regmark_keep_out(o.paper_mm, o.regmark)) {
      if (z.min.y <= area.min.y) top = std::max(top, z.max.y - area.min.y);
      if (z.max.y >= area.max.y) bottom = std::max(bottom, area.max.y - z.min.y);
      if (z.min.x <= area.min.x) left = std::max(left, z.max.x - area.min.x);
      if (z.max.x >= area.max.x) right = std::max(right, area.max.x - z.min.x);
    }
    const double spacing = o.pack.spacing_mm;
    if (area.height() >= area.width()) {
      room.y = area.height() - top - bottom - 2 * spacing - 2 * border;
    } else {
      room.x = area.width() - left - right - 2 * spacing - 2 * border;
    }
  }
  return {std::max(room.x, 0.0), std::max(room.y, 0.0)};
}

namespace {

void check_layout_input(const unfold::Unfolding& u, const LayoutOptions& o) {
  check_options(o);
  if (u.num_faces() == 0 || u.piece_count == 0)
    throw LayoutError("nothing to lay out: the unfolding has no faces");
  if (!(u.model_extent > 0)) throw LayoutError("the model has no extent to scale");
}

}  // namespace

BoundedLayout layout_sheets_within(const unfold::Unfolding& u, const LayoutOptions& o, long most_sheets) {
  if (!o.size_mm || o.fit) {
    LayoutResult r = layout_sheets(u, o);
    const long sheets = static_cast<long>(r.sheets.size());
    return {std::move(r), sheets};
  }
  check_layout_input(u, o);
  Attempt a = build(u, o, *o.size_mm / u.model_extent, std::nullopt, most_sheets);
  if (!a.complete) return {std::nullopt, a.packed_sheets};
  return {std::move(a.result), a.packed_sheets};
}

LayoutResult layout_sheets(const unfold::Unfolding& u, const LayoutOptions& o) {
  check_layout_input(u, o);

  if (o.size_mm && !o.fit) return build(u, o, *o.size_mm / u.model_extent, std::nullopt).result;

  // --fit (the default without --size): the largest scale at which everything packs onto one sheet.
  // The scale that lets the largest piece fit and the one that fills the sheet's area bound it above;
  // a bisection on packing runs finds it to within 1%.
  const Box2 area = printable_area(o);
  const double by_piece = largest_fitting_size(u, o) / u.model_extent;
  const double by_area = std::sqrt(area.width() * area.height() / std::max(total_model_area(u), 1e-300));
  double hi = std::min(by_piece, by_area);
  Attempt best = build(u, o, hi, 1);
  if (best.complete) return best.result;
  double lo = hi * 0.5;
  for (Attempt a = build(u, o, lo, 1);; a = build(u, o, lo, 1)) {
    if (a.complete) {
      best = std::move(a);
      break;
    }
    hi = lo;
    lo *= 0.5;
    if (lo < by_area * 1e-3) throw LayoutError("the model does not fit one sheet at any scale");
  }
  while (hi / lo > 1.01) {
    const double mid = std::sqrt(lo * hi);
    Attempt a = build(u, o, mid, 1);
    if (a.complete) {
      lo = mid;
      best = std::move(a);
    } else {
      hi = mid;
    }
  }
  return best.result;
}

}  // namespace foldkit::layout
