#include "choose_parts.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "foldkit/geom/hull.hpp"
#include "foldkit/layout/pack.hpp"
#include "foldkit/unfold/parts.hpp"
#include "foldkit/unfold/seams.hpp"
#include "foldkit/unfold/slit_cuts.hpp"
#include "foldkit/unfold/slits.hpp"
#include "length_option.hpp"

namespace foldkit::cli {
namespace {

// unfold::split_into_parts, its refusal worded with the CLI's --size.
unfold::PartsResult split(const unfold::Mesh& mesh, const unfold::Unfolding& u,
                          const unfold::PartOptions& po) {
  try {
    return unfold::split_into_parts(mesh, u, po);
  } catch (const unfold::PartTooLarge& e) {
    throw LayoutError(e.message("--size"));
  }
}

long sheets_with_pieces(const layout::LayoutResult& r) {
  return std::count_if(r.sheet_stats.begin(), r.sheet_stats.end(),
                       [](const layout::SheetStats& s) { return s.pieces > 0; });
}

// Sum of the parts' convex hull areas (model units squared): for the same faces, smaller is rounder.
double hull_area(const unfold::Unfolding& u) {
  double total = 0;
  for (const std::vector<int>& faces : u.piece_faces()) {
    std::vector<Vec2> points;
    for (int f : faces)
      points.insert(points.end(), u.flat[f].begin(), u.flat[f].end());
    const std::vector<Vec2> hull = convex_hull(std::move(points));
    for (std::size_t i = 0; i < hull.size(); ++i)
      total += 0.5 * cross(hull[i], hull[(i + 1) % hull.size()]);
  }
  return total;
}

// The same faces in the same parts (part numbers aside).
bool same_parts(const unfold::Unfolding& a, const unfold::Unfolding& b) {
  if (a.piece_count != b.piece_count || a.num_faces() != b.num_faces()) return false;
  // Parts are the same exactly when the first faces met map one to one onto each other's parts.
  std::vector<int> a_to_b(a.piece_count, -1), b_to_a(b.piece_count, -1);
  for (int f = 0; f < a.num_faces(); ++f) {
    int& x = a_to_b[a.piece_of_face[f]];
    int& y = b_to_a[b.piece_of_face[f]];
    if (x < 0 && y < 0) {
      x = b.piece_of_face[f];
      y = a.piece_of_face[f];
    }
    if (x != b.piece_of_face[f] || y != a.piece_of_face[f]) return false;
  }
  return true;
}

// The sheet each piece of a layout went to.
std::vector<int> sheet_of_each_piece(const layout::LayoutResult& r) {
  std::vector<int> sheets;
  sheets.reserve(r.placements.size());
  for (const layout::PiecePlacement& p : r.placements)
    sheets.push_back(p.sheet);
  return sheets;
}

struct Candidate {
  unfold::PartsResult parts;
  long sheets = 0;                            ///< by the estimate until `layout` is set, then by the layout
  long estimated_sheets = 0;                  ///< by the estimate, 0 before it
  int estimated_without_tab = 0;              ///< seams without a glue tab, by the estimate
  std::vector<int> estimated_sheet_of_piece;  ///< by the estimate, empty before it
  double hull_area = 0;
  bool patches = false;  ///< grown over the surface, not cut from the unfolding's pieces
  std::optional<layout::LayoutResult> layout;

  // Fewer sheets, then fewer parts, then more compact parts.
  auto rank() const { return std::make_tuple(sheets, parts.unfolding.piece_count, hull_area); }
};

// A candidate made from the parts of `from` (cut smaller, joined, seams moved), which keeps its origin.
Candidate derived_from(const Candidate& from, unfold::Unfolding parts) {
  Candidate c;
  c.parts.unfolding = std::move(parts);
  c.parts.split_pieces = from.parts.split_pieces;
  c.parts.new_pieces = from.parts.new_pieces;
  c.patches = from.patches;
  c.hull_area = hull_area(c.parts.unfolding);
  return c;
}

// The layout that judges candidates cheaply: the same parts, tabs and packing, without the labels and
// part letters, which cost as much as the rest and rarely change the sheet count. Where they do (a
// crowded label sticking out of a small face), the full layout of the best candidates below sees it.
layout::LayoutOptions estimate_options(layout::LayoutOptions o) {
  o.numbers = false;
  o.piece_letters = false;
  o.arrows = false;
  o.furniture = false;
  return o;
}

// The options of the `number`th layout tried: its progress stages carry the number, so that a stage
// seen again is seen as another layout's and the counts may start over.
layout::LayoutOptions numbered(const layout::LayoutOptions& o, int number) {
  layout::LayoutOptions n = o;
  if (o.progress)
    n.progress = [report = o.progress, number](const layout::LayoutProgress& p) {
      report({"layout " + std::to_string(number) + ", " + p.stage, p.done, p.total});
    };
  return n;
}

// Makes candidate partitions of one unfolding and lays them out, numbering the layouts it runs.
class PartChooser {
 public:
  // `large`: a layout that needs more sheets than estimated goes straight to plain tabs (lay_out).
  PartChooser(const unfold::Mesh& mesh, const unfold::Unfolding& u, const layout::LayoutOptions& o,
              const unfold::PartOptions& parts, bool large)
      : mesh_(mesh), u_(u), o_(o), rough_(estimate_options(o)), po_(parts), large_(large) {
    po_.room_mm = layout::piece_room_mm(o);
    po_.mm_per_unit = *o.size_mm / u.model_extent;
  }

  const unfold::PartOptions& part_options() const { return po_; }

  // Parts grown into `fraction` of the room, or, with `tiles`, into one tile of the sheet cut in that many.
  Candidate make(double fraction, unfold::PartGrowth growth, int tiles = 0) {
    po_.room_fraction = fraction;
    po_.growth = growth;
    po_.grow_room_mm = tiles > 0 ? tile_room_mm(o_, tiles) : Vec2{0, 0};
    Candidate c;
    c.parts = split(mesh_, u_, po_);
    c.hull_area = hull_area(c.parts.unfolding);
    return c;
  }

  // Patches grown over the surface (unfold::patch_parts) into `fraction` of the room: every piece cut
  // anew, so all of them count as split.
  std::optional<Candidate> patches(double fraction) {
    po_.room_fraction = fraction;
    std::optional<unfold::Unfolding> patches = unfold::patch_parts(mesh_, u_, po_);
    if (!patches) return std::nullopt;
    Candidate c;
    c.parts.unfolding = std::move(*patches);
    c.parts.split_pieces = u_.piece_count;
    c.parts.new_pieces = c.parts.unfolding.piece_count;
    c.patches = true;
    c.hull_area = hull_area(c.parts.unfolding);
    return c;
  }

  // The full layout, with labels and letters. Tabs that grow, split or change sides to hold labels take
  // paper the estimate did not see: where the layout then needs more sheets than estimated, it is laid
  // out again with fewer such tabs, down to the estimate's own tabs, until it needs no more sheets than
  // estimated; the one with fewest sheets is kept: a sheet is worth more than those labels.
  //
  // The full layout stops once packed when that takes more sheets than estimated: its labels would be
  // placed for nothing, as a layout with fewer tabs follows (spot_2000 at 150 mm: 1.8 s for a full layout
  // on 3 sheets, 0.75 s when it stops once packed, then 0.7 s for the 2 sheets kept). Only where no layout
  // with fewer tabs packs onto fewer sheets is it laid out in full after all.
  void lay_out(Candidate& c) {
    const std::vector<layout::LayoutOptions> ladder = fewer_label_tabs();
    const auto in_full = [&] {
      c.layout = layout::layout_sheets(c.parts.unfolding, numbered(o_, ++layouts_));
      c.sheets = sheets_with_pieces(*c.layout);
    };
    if (c.estimated_sheets == 0 || ladder.empty()) return in_full();
    layout::BoundedLayout full =
        layout::layout_sheets_within(c.parts.unfolding, numbered(o_, ++layouts_), c.estimated_sheets);
    c.layout = std::move(full.layout);
    c.sheets = c.layout ? sheets_with_pieces(*c.layout) : full.packed_sheets;
    for (const layout::LayoutOptions& fewer_tabs : ladder) {
      if (c.sheets <= c.estimated_sheets) break;
      layout::LayoutResult r = layout::layout_sheets(c.parts.unfolding, numbered(fewer_tabs, ++layouts_));
      if (sheets_with_pieces(r) >= c.sheets) continue;
      c.sheets = sheets_with_pieces(r);
      c.layout = std::move(r);
    }
    if (!c.layout) in_full();
  }

  // The layouts lay_out tries after the full one, each with fewer tabs for labels: whole tabs (none split),
  // then no tab grown for a crowded label, then tabs planned as if there were no labels. Large meshes try
  // only the last: over `bench --layout` whole tabs saved a sheet on 3 of 55 such layouts for 12 s of the
  // 194 s, and on a 2,000-face mesh each try costs 0.6 s of the 3 s a layout may take.
  std::vector<layout::LayoutOptions> fewer_label_tabs() const {
    std::vector<layout::LayoutOptions> ladder;
    if (!o_.numbers || !o_.tabs) return ladder;
    layout::LayoutOptions o = o_;
    o.split_tabs_for_labels = false;
    if (o_.tabs_for_labels && o_.split_tabs_for_labels && !large_) ladder.push_back(o);
    o.tabs_for_labels = false;
    if (o_.tabs_for_labels && !large_) ladder.push_back(o);
    o.tab_sides_for_labels = false;
    if (o_.tab_sides_for_labels) ladder.push_back(o);
    return ladder;
  }

  // The cheap layout (estimate_options): sets c.sheets, returns the area the pieces and tabs take (mm²).
  double estimate(Candidate& c) {
    const layout::LayoutResult r = layout::layout_sheets(c.parts.unfolding, numbered(rough_, ++layouts_));
    c.sheets = c.estimated_sheets = sheets_with_pieces(r);
    c.estimated_without_tab = r.overall.dropped_tabs;
    c.estimated_sheet_of_piece = sheet_of_each_piece(r);
    return r.overall.piece_area_mm2 + r.overall.tab_area_mm2;
  }

 private:
  const unfold::Mesh& mesh_;
  const unfold::Unfolding& u_;
  const layout::LayoutOptions& o_;
  const layout::LayoutOptions rough_;
  unfold::PartOptions po_;
  bool large_ = false;
  int layouts_ = 0;
};

// Parts and packing together: when the layout leaves more sheets than the area needs, the parts
// alone on the last sheet are cut smaller (half, then a third of the room) and the whole is packed
// again; smaller, rounder parts slip into the gaps of the sheets before. Kept when that saves a sheet.
void resplit_last_sheet(const unfold::Mesh& mesh, const layout::LayoutOptions& o, unfold::PartOptions po,
                        long bound, PartChooser& chooser, Candidate& best) {
  constexpr double kFractions[] = {0.5, 0.35};
  constexpr int kFewMoreParts = 4;
  for (std::size_t t = 0; t < std::size(kFractions); ++t) {
    if (best.sheets <= bound || !best.layout) return;
    if (o.deadline && std::chrono::steady_clock::now() > *o.deadline) return;
    po.also_split.clear();
    int last = 0;
    for (const layout::PiecePlacement& placement : best.layout->placements)
      last = std::max(last, placement.sheet);
    for (std::size_t p = 0; p < best.layout->placements.size(); ++p)
      if (best.layout->placements[p].sheet == last) po.also_split.push_back(static_cast<int>(p));
    po.room_fraction = kFractions[t];
    po.growth = unfold::PartGrowth::Round;
    Candidate c = derived_from(best, split(mesh, best.parts.unfolding, po).unfolding);
    // A sheet is worth a few more parts, not a model in confetti.
    const int most_parts =
        best.parts.unfolding.piece_count + std::max(kFewMoreParts, best.parts.unfolding.piece_count / 4);
    if (c.parts.unfolding.piece_count > most_parts ||
        c.parts.unfolding.piece_count == best.parts.unfolding.piece_count)
      continue;
    chooser.estimate(c);
    if (c.sheets >= best.sheets) continue;
    chooser.lay_out(c);
    if (c.rank() < best.rank()) best = std::move(c);
  }
}

}  // namespace

long area_sheet_bound(const layout::LayoutOptions& o, double used_mm2) {
  const Box2 area = layout::printable_area(o);
  return std::max(1L, static_cast<long>(std::ceil(used_mm2 / (area.width() * area.height()) - 1e-9)));
}

std::vector<layout::Polygon> flat_face_cores_mm(const unfold::Unfolding& u, double mm_per_unit) {
  const std::vector<int> face_of = unfold::flat_face_of(u);
  const int faces = face_of.empty() ? 0 : 1 + *std::max_element(face_of.begin(), face_of.end());
  std::vector<std::vector<int>> triangles(faces);
  for (int t = 0; t < u.num_faces(); ++t)
    triangles[face_of[t]].push_back(t);
  std::vector<layout::Polygon> cores;
  for (const std::vector<int>& face : triangles) {
    std::vector<Vec2> points;
    double area = 0, largest = -1;
    layout::Polygon biggest;
    for (int t : face) {
      const auto& tri = u.flat[t];
      const double a = 0.5 * std::fabs(cross(tri[1] - tri[0], tri[2] - tri[0]));
      area += a;
      if (a > largest) {
        largest = a;
        biggest.assign(tri.begin(), tri.end());
      }
      points.insert(points.end(), tri.begin(), tri.end());
    }
    layout::Polygon hull = convex_hull(std::move(points));
    // A convex face is its hull; a concave one holds at least its largest triangle.
    layout::Polygon core = std::fabs(layout::signed_area(hull)) <= area * (1 + 1e-9) ? hull : biggest;
    for (Vec2& v : core)
      v = v * mm_per_unit;
    cores.push_back(std::move(core));
  }
  return cores;
}

Vec2 tile_room_mm(const layout::LayoutOptions& o, int tiles) {
  const Vec2 room = layout::piece_room_mm(o);
  if (tiles <= 1) return room;
  // What piece_room_mm keeps free on every side of a part (tabs, spacing, raster): each tile keeps it too.
  const Box2 area = layout::printable_area(o);
  const double border = std::max(0.0, 0.5 * std::min(area.width() - room.x, area.height() - room.y));
  const double across_long = tiles % 3 == 0 ? 3 : 2, across_short = tiles >= 4 ? 2 : 1;
  const bool long_x = room.x > room.y;
  const Vec2 cut = long_x ? Vec2{across_long, across_short} : Vec2{across_short, across_long};
  return {std::max(0.0, (room.x + 2 * border) / cut.x - 2 * border),
          std::max(0.0, (room.y + 2 * border) / cut.y - 2 * border)};
}

long flat_face_sheet_bound(const unfold::Unfolding& u, const layout::LayoutOptions& o) {
  if (!o.size_mm || !(u.model_extent > 0)) return 0;
  return layout::shape_sheet_bound(flat_face_cores_mm(u, *o.size_mm / u.model_extent),
                                   layout::printable_area(o));
}

long least_sheets(const unfold::Unfolding& u, const layout::LayoutOptions& o, double used_mm2) {
  return std::max(area_sheet_bound(o, used_mm2), flat_face_sheet_bound(u, o));
}

int flaws(const layout::LayoutResult& r) {
  return r.label_audit.unclear() + kSeamWithoutTabFlaws * r.overall.dropped_tabs;
}

namespace {

// The fractions of the room patches are grown into, in the order tried.
constexpr double kPatchFractions[] = {1.0, 0.5, 0.7, 0.35};

// Parts as large as the sheet allows give the fewest seams but, cut from a spindly net, pack poorly;
// smaller, rounder parts often save a sheet. Packing is a heuristic, so each split is judged by packing
// it (the estimate). Large meshes try the first three only, so their layout stays fast; a count, not a
// clock, so the same input gives the same parts. Under a time limit, another trial must leave room for
// the full layouts (with labels, dearer). The trials end once an estimate takes `stop_at` sheets or
// fewer (0: never).
void try_partitions(PartChooser& chooser, const layout::LayoutOptions& o, long stop_at, bool large,
                    bool patches, std::chrono::steady_clock::duration trial_time,
                    std::vector<Candidate>& candidates) {
  struct Try {
    double fraction;
    unfold::PartGrowth growth;
    int tiles;             ///< > 0: parts grown into one tile of the sheet cut in this many (fraction unused)
    bool patches = false;  ///< patches grown over the surface (growth and tiles unused)
  };
  // Halves of the sheet (two such parts share one) after the fractions: over `bench --layout` the same
  // sheets and fewer parts on 19 runs, more on none (3,194 -> 3,139), for 10-17% more CPU. Then patches
  // grown over the surface, last because they have the most parts: over `bench --layout` (up to 1,000
  // faces) 466 -> 448 sheets, 18 runs a sheet fewer, none more, the same CPU (the bound is reached
  // sooner); 466 -> 459 with the labels' veto (keep_patches_only_if_legible), and 2,758 -> 2,621 parts
  // where patches tie on sheets with fewer parts. Large meshes stop before them.
  // clang-format off
  constexpr Try tries[] = {{1.0, unfold::PartGrowth::Round, 0},
                           {0.7, unfold::PartGrowth::Tree, 0},
                           {0.5, unfold::PartGrowth::Tree, 0},
                           {0.85, unfold::PartGrowth::Tree, 0},
                           {0.7, unfold::PartGrowth::Round, 0},
                           {0.5, unfold::PartGrowth::Round, 0},
                           {0.35, unfold::PartGrowth::Tree, 0},
                           {1.0, unfold::PartGrowth::Round, 2},
                           {1.0, unfold::PartGrowth::Tree, 2},
                           {kPatchFractions[0], {}, 0, true},
                           {kPatchFractions[1], {}, 0, true},
                           {kPatchFractions[2], {}, 0, true},
                           {kPatchFractions[3], {}, 0, true}};
  // clang-format on
  const std::size_t trials = large ? 3 : std::size(tries);
  auto best_estimate = [&] {
    return std::min_element(candidates.begin(), candidates.end(),
                            [](const Candidate& a, const Candidate& b) { return a.rank() < b.rank(); });
  };
  for (std::size_t t = 0; t < trials; ++t) {
    if (best_estimate()->sheets <= stop_at) break;
    if (o.deadline && std::chrono::steady_clock::now() + 4 * trial_time > *o.deadline) break;
    if (tries[t].patches && !patches) continue;
    std::optional<Candidate> made = tries[t].patches
                                        ? chooser.patches(tries[t].fraction)
                                        : chooser.make(tries[t].fraction, tries[t].growth, tries[t].tiles);
    if (!made) continue;
    Candidate c = std::move(*made);
    // Low-poly models often come out the same at several fractions: each partition is packed once.
    if (std::any_of(candidates.begin(), candidates.end(), [&](const Candidate& seen) {
          return same_parts(seen.parts.unfolding, c.parts.unfolding);
        }))
      continue;
    chooser.estimate(c);
    candidates.push_back(std::move(c));
  }
}

// The best estimate gets its full layout; while the next estimate could still beat the best full
// layout so far (the labels can cost a sheet), that one gets a full layout too (at most three in
// all, two for large meshes), and the best full layout wins; the others stay in `candidates`.
Candidate best_full_layout(PartChooser& chooser, std::vector<Candidate>& candidates, bool large) {
  const std::size_t full_layouts = large ? 2 : 3;
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Candidate& a, const Candidate& b) { return a.rank() < b.rank(); });
  chooser.lay_out(candidates[0]);
  for (std::size_t k = 1; k < std::min(candidates.size(), full_layouts); ++k) {
    // Parts do not change between estimate and layout: a candidate can win only on fewer sheets, or
    // as many with fewer parts.
    const Candidate& held = candidates[0];
    const Candidate& next = candidates[k];
    if (!(next.sheets < held.sheets || (next.sheets == held.sheets &&
                                        next.parts.unfolding.piece_count < held.parts.unfolding.piece_count)))
      break;
    chooser.lay_out(candidates[k]);
    if (candidates[k].rank() < candidates[0].rank()) std::swap(candidates[0], candidates[k]);
  }
  Candidate best = std::move(candidates[0]);
  candidates.erase(candidates.begin());
  return best;
}

// Patches save sheets where a net's parts do not fill them, but their seams between parts run through
// regions of small faces too, and packed that densely their tabs have no room to grow for labels: over
// `bench/label_sweep.py` they left 1,115 labels of 17,848 unclear against 889 of 17,678. A sheet is
// worth a few more unclear labels, not many: patches are kept when their labels crossing lines or
// touching are at most kLegibleLabelShare of their labels (legible as issue 12 counts it), or at most
// kPatchLabelShare of them more than the best partition cut from the net leaves.
constexpr double kLegibleLabelShare = 0.02;  // issue 12's bar
constexpr double kPatchLabelShare = 0.01;

// How many of `labels` may be unclear, or `share` of them more than another layout leaves.
int labels_at_share(double share, int labels) {
  return static_cast<int>(std::floor(share * labels));
}

// How many more labels the laid-out `patches` leave unclear than they may (negative: fewer).
int unclear_over_allowed(const Candidate& patches, int net_unclear) {
  const int labels = patches.layout->label_audit.labels;
  const int allowed = std::max(labels_at_share(kLegibleLabelShare, labels),
                               net_unclear + labels_at_share(kPatchLabelShare, labels));
  return patches.layout->label_audit.unclear() - allowed;
}

bool legible_enough(const Candidate& patches, int net_unclear) {
  return unclear_over_allowed(patches, net_unclear) <= 0;
}

// The patches at the fractions the trials did not reach (they stop at the bound), estimated.
std::vector<Candidate> patches_not_tried(PartChooser& chooser, const std::vector<Candidate>& tried) {
  std::vector<Candidate> made;
  for (double fraction : kPatchFractions) {
    std::optional<Candidate> c = chooser.patches(fraction);
    if (!c) continue;
    const auto same = [&](const Candidate& seen) {
      return same_parts(seen.parts.unfolding, c->parts.unfolding);
    };
    if (std::any_of(tried.begin(), tried.end(), same) || std::any_of(made.begin(), made.end(), same))
      continue;
    chooser.estimate(*c);
    made.push_back(std::move(*c));
  }
  return made;
}

// Where the patches laid out just miss the bar, patches grown into other fractions of the room may
// clear it on as many sheets: their seams between parts fall elsewhere (cat_500 at 150 mm: patches into
// the whole room left 11 of 538 labels unclear where 10 may be, into 0.7 of it 9 of 542, both on one
// sheet where the net's parts take two). The estimates on as few sheets as `others[vetoed]` are laid
// out, fewest sheets and parts first, at most kOtherPatchLayouts of them; the first legible enough
// replaces `best` (the net's best). Returns whether one did.
bool other_patches_legible(PartChooser& chooser, const layout::LayoutOptions& o,
                           std::vector<Candidate>& others, std::size_t vetoed, int net_unclear,
                           Candidate& best) {
  constexpr std::size_t kOtherPatchLayouts = 3;
  const long patch_sheets = others[vetoed].sheets;
  std::vector<Candidate> made = patches_not_tried(chooser, others);
  std::move(made.begin(), made.end(), std::back_inserter(others));
  std::vector<Candidate*> tries;
  for (std::size_t i = 0; i < others.size(); ++i)
    if (i != vetoed && others[i].patches && others[i].sheets <= patch_sheets) tries.push_back(&others[i]);
  std::stable_sort(tries.begin(), tries.end(),
                   [](const Candidate* a, const Candidate* b) { return a->rank() < b->rank(); });
  if (tries.size() > kOtherPatchLayouts) tries.resize(kOtherPatchLayouts);
  for (Candidate* c : tries) {
    if (o.deadline && std::chrono::steady_clock::now() > *o.deadline) return false;
    if (!c->layout) chooser.lay_out(*c);
    if (c->sheets < best.sheets && legible_enough(*c, net_unclear)) {
      std::swap(best, *c);
      return true;
    }
  }
  return false;
}

// The veto (above). Where the patches miss the bar by at most kPatchLabelShare of their labels, the
// patches at other fractions of the room are tried; then the patches vetoed are finished (`finish`:
// the re-split, seam and slit steps and the joins on a sheet that every choice gets) and judged again:
// parts joined on their sheet have fewer seams to label (wingnut_350 at 150 mm: 9 of 394 labels
// unclear where 7 may be, 6 of 386 once 22 patches are joined into 18). A larger miss was never made
// up over `bench --layout` (fish_500 at 150 mm: 56 of 552 unclear, the other fractions 20-63,
// finished 51, 11 allowed; homer_1000: 741 of 1,076, the others 708-849, 673 allowed), and trying
// cost homer_1000 at 150 mm 6 s. Returns whether `best` is finished.
bool keep_patches_only_if_legible(PartChooser& chooser, const layout::LayoutOptions& o,
                                  std::vector<Candidate>& others, Candidate& best,
                                  const std::function<void(Candidate&)>& finish) {
  if (!best.patches || !best.layout) return false;
  if (legible_enough(best, 0)) return false;
  auto net = std::find_if(others.begin(), others.end(), [](const Candidate& c) { return !c.patches; });
  if (net == others.end()) return false;  // ranked: the first cut from the net is its best
  if (!net->layout) chooser.lay_out(*net);
  const int net_unclear = net->layout->label_audit.unclear();
  const int miss = unclear_over_allowed(best, net_unclear);
  if (miss <= 0) return false;
  const bool near_miss =
      miss <= static_cast<int>(std::floor(kPatchLabelShare * best.layout->label_audit.labels));
  std::swap(best, *net);
  const std::size_t vetoed = net - others.begin();
  if (!near_miss || best.sheets <= others[vetoed].sheets) return false;
  const auto out_of_time = [&] { return o.deadline && std::chrono::steady_clock::now() > *o.deadline; };
  if (out_of_time() || other_patches_legible(chooser, o, others, vetoed, net_unclear, best)) return false;
  if (out_of_time()) return false;
  Candidate finished = others[vetoed];
  finish(finished);
  if (finished.sheets >= best.sheets || !legible_enough(finished, net_unclear)) return false;
  best = std::move(finished);
  return true;
}

// Partitions often tie on sheets and parts yet differ in seams without a glue tab: a part boundary
// through a slit gives each of its sides room for one. The tied estimate with the fewest replaces
// `best` when its full layout keeps the sheets and parts and leaves fewer seams without a tab. Asked
// after the last sheet's re-split, which packing luck decides from either, so that it never costs a
// sheet.
void fewer_seams_without_tab(PartChooser& chooser, std::vector<Candidate>& others, Candidate& best) {
  const int best_parts = best.parts.unfolding.piece_count;
  const int best_without = best.layout ? best.layout->overall.dropped_tabs : 0;
  Candidate* tie = nullptr;
  for (Candidate& c : others)
    if (c.sheets == best.sheets && c.parts.unfolding.piece_count == best_parts &&
        c.estimated_without_tab < (tie ? tie->estimated_without_tab : best.estimated_without_tab))
      tie = &c;
  if (!tie) return;
  if (!tie->layout) chooser.lay_out(*tie);
  if (tie->sheets == best.sheets && tie->parts.unfolding.piece_count == best_parts &&
      tie->layout->overall.dropped_tabs < best_without)
    best = std::move(*tie);
}

// The slits the parts' own seam moves left, closed across parts (unfold::close_slits_across_parts). The
// parts change shape, so they are laid out again, and kept when they take no more sheets, leave fewer
// seams without a tab and no more labels crossing lines or touching (the cuts through flat regions
// left labels worse on sliver meshes: homer_500, screwdriver_500).
void close_slits_across_parts(const unfold::Mesh& mesh, const layout::LayoutOptions& o, PartChooser& chooser,
                              Candidate& best) {
  if (!best.layout || best.layout->overall.dropped_tabs == 0) return;
  if (o.deadline && std::chrono::steady_clock::now() > *o.deadline) return;
  Candidate c = derived_from(
      best, unfold::close_slits_across_parts(mesh, best.parts.unfolding, chooser.part_options()));
  if (edge_states(c.parts.unfolding) == edge_states(best.parts.unfolding)) return;
  c.estimated_sheets = best.estimated_sheets;
  chooser.lay_out(c);
  if (c.sheets <= best.sheets && c.layout->overall.dropped_tabs < best.layout->overall.dropped_tabs &&
      c.layout->label_audit.unclear() <= best.layout->label_audit.unclear())
    best = std::move(c);
}

// The parts of `u` that hold both sides of a seam too narrow for a glue tab (a slit), increasing.
std::vector<int> parts_holding_slits(const unfold::Unfolding& u, double slit_gap_units) {
  const std::vector<std::vector<int>> partners = unfold::narrow_seam_partners(u, slit_gap_units);
  std::vector<int> parts;
  for (int f = 0; f < u.num_faces(); ++f)
    if (!partners[f].empty()) parts.push_back(u.piece_of_face[f]);
  std::sort(parts.begin(), parts.end());
  parts.erase(std::unique(parts.begin(), parts.end()), parts.end());
  return parts;
}

int flaws(const Candidate& c) {
  return cli::flaws(*c.layout);
}

// Whether `opened`, `best` with its slits parted, is worth it: no more sheets, fewer seams without a
// tab, a part more for each seam that gets a tab at most (fish_350 at 150 mm: 3 more parts for 2 tabs is
// a poor trade; penguin_500: 6 more for 7 a fair one), and fewer flaws in all: a tab gained saves
// kSeamWithoutTabFlaws labels the new seams leave unclear (torus_500 at 150 mm: 15 tabs for one label is
// taken; spot_1000: 41 tabs for 149 labels is not).
bool worth_opening(const Candidate& opened, const Candidate& best) {
  const int more_parts = opened.parts.unfolding.piece_count - best.parts.unfolding.piece_count;
  const int more_tabs = best.layout->overall.dropped_tabs - opened.layout->overall.dropped_tabs;
  return opened.sheets <= best.sheets && more_tabs > 0 && more_parts <= more_tabs &&
         flaws(opened) < flaws(best);
}

// Seams without a tab and labels unclear, then parts: which of two openings that are both worth it wins.
auto opening_rank(const Candidate& c) {
  return std::make_tuple(flaws(c), c.parts.unfolding.piece_count);
}

// The parts of `u` (`before`'s) whose opening in `opened` gains more than it costs: `credit_per_slit`
// for each slit it parts against one for each label left without a clear spot on the pieces cut from
// it. Where the whole opening costs more labels than it gains tabs, it is often a few small parts in a
// region of small faces that cost them.
std::vector<int> parts_worth_opening(const unfold::Unfolding& u, const Candidate& before,
                                     const Candidate& opened, double slit_gap_units, int credit_per_slit) {
  const unfold::Unfolding& after = opened.parts.unfolding;
  std::vector<int> parted(u.piece_count, 0);  // per part of u: its slits that now run between parts
  const std::vector<std::vector<int>> partners = unfold::narrow_seam_partners(u, slit_gap_units);
  for (int f = 0; f < u.num_faces(); ++f)
    for (int g : partners[f])
      if (f < g && after.piece_of_face[f] != after.piece_of_face[g])
        parted[u.piece_of_face[f]] += credit_per_slit;
  std::vector<int> balance = parted;  // less the labels its pieces lost
  for (const layout::LayoutResult::CrowdedLabel& l : before.layout->crowded_labels)
    if (l.piece >= 0) balance[l.piece] += 1;
  std::vector<int> part_of_piece(after.piece_count, -1);  // each piece of `after` lies in one part of u
  for (int f = 0; f < after.num_faces(); ++f)
    part_of_piece[after.piece_of_face[f]] = u.piece_of_face[f];
  for (const layout::LayoutResult::CrowdedLabel& l : opened.layout->crowded_labels)
    if (l.piece >= 0) balance[part_of_piece[l.piece]] -= 1;
  std::vector<int> parts;
  for (int p = 0; p < u.piece_count; ++p)
    if (parted[p] > 0 && balance[p] > 0) parts.push_back(p);
  return parts;
}

// Parts that still hold slits, opened so that each slit runs between two parts and takes a tab, in two
// ways: each such part grown again within itself at the full room but never with both sides of a slit in
// one part, and each cut at one fold at a time (unfold::cut_open_at_slits: a new seam of one edge per
// dart, where the regrowth redraws every boundary of the part). Neither is better everywhere: on the
// 350-1,000-face meshes at 150 mm the cuts pass where the regrowth costs labels (screwdriver_500,
// elephant_500) and the other way round (bob_1000). The better of those worth it is kept.
// Where cutting every part open is not worth it, the parts whose cuts there gain more than they cost
// are cut alone: first those whose tabs gained outweigh their labels lost at the judge's rate
// (kSeamWithoutTabFlaws), then, where that is still not worth it, only those whose tabs gained outnumber
// them (screwdriver_1000 at 150 mm: three parts cut open leave 17 seams without a tab and 139 more labels
// unclear, not worth it; the one part that passes the stricter test leaves 29 and 30).
void open_slits_between_parts(const unfold::Mesh& mesh, const layout::LayoutOptions& o, SlitOpening ways,
                              PartChooser& chooser, Candidate& best) {
  if (ways == SlitOpening::None || !best.layout || best.layout->overall.dropped_tabs == 0) return;
  const unfold::Unfolding& u = best.parts.unfolding;
  unfold::PartOptions po = chooser.part_options();
  po.room_fraction = 1;
  po.grow_room_mm = {0, 0};
  po.growth = unfold::PartGrowth::Fewest;
  po.slit_gap_mm = layout::narrow_slit_gap_mm(o);
  const double slit_gap_units = po.slit_gap_mm / po.mm_per_unit;
  po.also_split = parts_holding_slits(u, slit_gap_units);
  if (po.also_split.empty()) return;
  std::optional<Candidate> kept;
  // Lays `c` out, unless it is the parts before or those kept, or time is out: whether it did.
  const auto lay_out_new = [&](Candidate& c) {
    if (same_parts(c.parts.unfolding, u) || (kept && same_parts(c.parts.unfolding, kept->parts.unfolding)))
      return false;
    if (o.deadline && std::chrono::steady_clock::now() > *o.deadline) return false;
    c.estimated_sheets = best.estimated_sheets;
    chooser.lay_out(c);
    return true;
  };
  const auto keep_if_better = [&](Candidate& c) {
    if (worth_opening(c, best) && (!kept || opening_rank(c) < opening_rank(*kept))) kept = std::move(c);
  };
  if (ways != SlitOpening::Cut) {
    Candidate regrown = derived_from(best, unfold::split_into_parts(mesh, u, po).unfolding);
    if (lay_out_new(regrown)) keep_if_better(regrown);
  }
  if (ways != SlitOpening::Regrown) {
    Candidate all = derived_from(best, unfold::cut_open_at_slits(mesh, u, po));
    if (lay_out_new(all) && worth_opening(all, best)) {
      keep_if_better(all);
    } else if (all.layout) {
      std::vector<int> tried = po.also_split;
      for (int credit_per_slit : {kSeamWithoutTabFlaws, 1}) {
        unfold::PartOptions some = po;
        some.also_split = parts_worth_opening(u, best, all, slit_gap_units, credit_per_slit);
        if (some.also_split.empty() || std::exchange(tried, some.also_split) == some.also_split) continue;
        Candidate narrowed = derived_from(best, unfold::cut_open_at_slits(mesh, u, some));
        if (!lay_out_new(narrowed)) continue;
        const bool worth = worth_opening(narrowed, best);
        keep_if_better(narrowed);
        if (worth) break;
      }
    }
  }
  if (kept) best = std::move(*kept);
}

// Pairs of parts that share a glued seam and, by `sheet_of_piece`, a sheet: the smallest pairs (by faces)
// first, as join_parts takes them.
std::vector<std::array<int, 2>> neighbours_on_a_sheet(const unfold::Unfolding& u,
                                                      const std::vector<int>& sheet_of_piece) {
  std::set<std::array<int, 2>> seen;
  for (const unfold::UnfoldEdge& e : u.edges) {
    if (!e.glued_seam()) continue;
    const int a = u.piece_of_face[e.face[0]], b = u.piece_of_face[e.face[1]];
    if (a == b || sheet_of_piece.at(a) != sheet_of_piece.at(b)) continue;
    seen.insert({std::min(a, b), std::max(a, b)});
  }
  std::vector<int> faces(u.piece_count, 0);
  for (const int p : u.piece_of_face)
    ++faces[p];
  std::vector<std::array<int, 2>> pairs(seen.begin(), seen.end());
  std::stable_sort(pairs.begin(), pairs.end(), [&](const auto& x, const auto& y) {
    return faces[x[0]] + faces[x[1]] < faces[y[0]] + faces[y[1]];
  });
  return pairs;
}

// How many estimates joined_two_at_a_time may spend on a mesh of `faces` faces: an estimate costs about
// as much as the mesh is large. Over `bench --layout` every join kept came within the first 3 estimates
// on 350-500 faces (bob_350, goathead_350 at 250 mm, elephant_500 at 150 mm) and within 11 on 128; the
// later ones on 350 faces cost rocker_arm_350 at 150 mm and plane_350 at 250 mm 2.8 and 4.6 s of CPU
// (3.5 -> 6.3, 7.6 -> 12.2 s) for joins the full layout then refused.
int join_trials_for(int faces) {
  constexpr int kMostJoinTrials = 12;
  constexpr int kJoinTrialFaces = 1600;  // faces times estimates
  return std::clamp(kJoinTrialFaces / std::max(faces, 1), 1, kMostJoinTrials);
}

// Where the joins in join_parts' order cost a sheet from the first, another pair may not: joined two at
// a time, each pair of parts on one sheet in turn (smallest first), the first join whose estimate keeps
// the sheets kept, until none does or join_trials_for(faces) estimates are spent. lowpoly/cube at 80 mm
// fitted one sheet as six loose squares: its first join took a second sheet by the estimate, others do not.
std::optional<Candidate> joined_two_at_a_time(const unfold::Mesh& mesh, const unfold::PartOptions& whole_room,
                                              const layout::LayoutOptions& o, PartChooser& chooser,
                                              const Candidate& best) {
  constexpr int kMostParts = 24;  // beyond, each estimate costs more and the order above finds most joins
  if (best.parts.unfolding.piece_count > kMostParts) return std::nullopt;
  const int most_trials = join_trials_for(mesh.num_faces());
  std::optional<Candidate> kept;
  std::vector<int> sheet_of_piece = sheet_of_each_piece(*best.layout);
  const Candidate* from = &best;
  int trials = 0;
  for (bool joined = true; joined && trials < most_trials;) {
    joined = false;
    for (const auto& [a, b] : neighbours_on_a_sheet(from->parts.unfolding, sheet_of_piece)) {
      if (trials >= most_trials || (o.deadline && std::chrono::steady_clock::now() > *o.deadline)) break;
      const auto only = [a = a, b = b](int x, int y) { return std::min(x, y) == a && std::max(x, y) == b; };
      Candidate c = derived_from(*from, unfold::join_parts(mesh, from->parts.unfolding, whole_room, only, 1));
      if (c.parts.unfolding.piece_count == from->parts.unfolding.piece_count) continue;
      ++trials;
      chooser.estimate(c);
      if (c.sheets > best.sheets) continue;
      sheet_of_piece = c.estimated_sheet_of_piece;
      kept = std::move(c);
      from = &*kept;
      joined = true;
      break;
    }
  }
  return kept;
}

// Parts that share a sheet, joined back along seams between them (unfold::join_parts), the smallest
// pairs first: joined they are fewer seams to match across parts. All the joins the room allows often
// need another sheet; then the most joins that keep the sheets (by the estimate) are searched for by
// halving, and where even the first join costs a sheet, pairs are joined two at a time. Kept when the
// full layout takes no more sheets and leaves no more labels unclear and no more seams without a tab.
void join_parts_on_a_sheet(const unfold::Mesh& mesh, const layout::LayoutOptions& o, PartChooser& chooser,
                           Candidate& best) {
  constexpr int kSearchSteps = 4;  // estimates after the first: joins found within 1/16 of all
  if (!best.layout || best.parts.unfolding.piece_count < 2) return;
  const std::vector<layout::PiecePlacement> placed = best.layout->placements;
  const auto same_sheet = [&](int a, int b) { return placed[a].sheet == placed[b].sheet; };
  const int before = best.parts.unfolding.piece_count;
  unfold::PartOptions whole_room = chooser.part_options();
  whole_room.room_fraction = 1;
  auto joined = [&](int most_joins) {
    return derived_from(best,
                        unfold::join_parts(mesh, best.parts.unfolding, whole_room, same_sheet, most_joins));
  };
  Candidate all = joined(std::numeric_limits<int>::max());
  const int joins = before - all.parts.unfolding.piece_count;
  if (joins == 0) return;
  chooser.estimate(all);
  std::optional<Candidate> kept;  // the most joins found that keep the sheets
  if (all.sheets <= best.sheets) {
    kept = std::move(all);
  } else {
    int fine = 0, costly = joins;  // joins known to keep the sheets, and known to cost one
    for (int step = 0; step < kSearchSteps && costly - fine > 1; ++step) {
      if (o.deadline && std::chrono::steady_clock::now() > *o.deadline) return;
      const int middle = (fine + costly) / 2;
      Candidate c = joined(middle);
      chooser.estimate(c);
      if (c.sheets <= best.sheets) {
        fine = middle;
        kept = std::move(c);
      } else {
        costly = middle;
      }
    }
    if (!kept) kept = joined_two_at_a_time(mesh, whole_room, o, chooser, best);
  }
  if (!kept) return;
  chooser.lay_out(*kept);
  // The estimate packs no tabs grown for labels: where the joined parts fill the sheet, the full layout
  // falls back to plain tabs and leaves more labels unclear (label sweep 923 -> 1,024 of 17,700 without
  // this check; docs/layout.md).
  if (kept->sheets <= best.sheets &&
      kept->layout->label_audit.unclear() <= best.layout->label_audit.unclear() &&
      kept->layout->overall.dropped_tabs <= best.layout->overall.dropped_tabs)
    best = std::move(*kept);
}

}  // namespace

unfold::PartOptions part_options_of(const unfold::Mesh& mesh, const unfold::UnfoldOptions& unfolded) {
  unfold::PartOptions po;
  po.move_seams = unfolded.move_seams;
  po.constraints = unfold::resolve_seams(mesh, unfolded.seams);
  po.cuts = unfolded.cuts;
  return po;
}

namespace {

// Above it: fewer trials and full layouts, no search that empties sheets, no re-split of the last sheet, no
// second choice with other tabs.
constexpr int kManyFaces = 1500;

// choose_parts with the tabs `asked` plans; `least` is set to least_sheets once a piece had to be split.
// `fewer_sheets_than` > 0: only a choice of fewer sheets is wanted, so where no candidate's estimate
// takes fewer, the choice stops before any full layout and returns none (half the cost of a choice).
ChosenParts choose_parts_once(const unfold::Mesh& mesh, const unfold::Unfolding& u,
                              const layout::LayoutOptions& asked, const unfold::PartOptions& parts,
                              const ChooseOptions& choose, long& least, long fewer_sheets_than = 0) {
  if (!asked.size_mm || asked.fit || !asked.split_oversized || !(u.model_extent > 0))
    return {u, 0, 0, std::nullopt};
  // Large meshes pack at all the rotations asked (24: koala_2000 at 250 mm and spot_2000 at 150 mm take a
  // sheet fewer than at 8, and the slowest 2,000-face layout is fish_2000 at 150 mm, 2.4 s), but do not
  // search for sheets to empty once packed: with it no 2,000-face run saved a sheet, and plane_2000 at
  // 250 mm took 2.8 s instead of 2.3 (session 45).
  const bool large = mesh.num_faces() > kManyFaces;
  layout::LayoutOptions o = asked;
  if (large) o.pack.sheet_search_orders = 0;
  // Nor do their tabs go into bays: spot_2000 at 150 mm took 4.3 s with them, 1.8 s without, for the
  // same 3 sheets and 18 parts.
  if (large) o.tab.into_bays = false;
  // Labels look for leader spots thoroughly on meshes up to kMostFacesForThoroughLabels, where it pays
  // (350-500 faces at 150 mm: 417 -> 345 labels unclear). Above, most labels of a crowded layout find
  // no spot either way and every one tried costs: torus_2000 at 150 mm laid out in 2.5 s instead of 1.5,
  // screwdriver_1000 at 250 mm in 30 s instead of 17 with 83 labels unclear instead of 75.
  constexpr int kMostFacesForThoroughLabels = 750;
  if (mesh.num_faces() > kMostFacesForThoroughLabels) o.label.leader_search = layout::LeaderSearch::Quick;
  // Seams move inside the parts of smaller meshes only: on 2,000-face meshes the moves doubled some
  // layouts (threeholes_2000 at 150 mm: 1.2 -> 2.9 s) and left more labels crossing lines at 250 mm
  // (cheburashka_2000: 173 -> 324); up to 1,000 faces they leave fewer (9,729 -> 9,507 of 39,214).
  unfold::PartOptions part_options = parts;
  if (large) part_options.move_seams = false;
  PartChooser chooser(mesh, u, o, part_options, large);
  Candidate first = chooser.make(1.0, unfold::PartGrowth::Tree);
  if (first.parts.split_pieces == 0) {
    chooser.lay_out(first);
    return {std::move(first.parts.unfolding), 0, 0, std::move(first.layout)};
  }
  const int too_large = first.parts.split_pieces;
  const auto first_start = std::chrono::steady_clock::now();
  // Faces larger than half the room can leave the area bound out of reach: the bound counts shapes too.
  // Reaching it ends the trials, except where the shapes set it: a model of such faces takes that many
  // sheets whatever its parts, and the later trials (parts grown into tiles of the sheet) often tie with
  // fewer parts (lowpoly/rhombicuboctahedron at 250 mm: 9 sheets in 16 parts, not 22).
  const double used_mm2 = chooser.estimate(first);
  const long bound = least_sheets(u, o, used_mm2);
  least = bound;
  const long stop_at = bound > area_sheet_bound(o, used_mm2) ? 0 : bound;
  const auto trial_time = std::chrono::steady_clock::now() - first_start;
  std::vector<Candidate> candidates;
  candidates.push_back(std::move(first));
  try_partitions(chooser, o, stop_at, large, choose.patches, trial_time, candidates);
  if (fewer_sheets_than > 0 && std::none_of(candidates.begin(), candidates.end(),
                                            [&](const Candidate& c) { return c.sheets < fewer_sheets_than; }))
    return {u, 0, 0, std::nullopt};
  Candidate best = best_full_layout(chooser, candidates, large);
  const auto finish = [&](Candidate& c) {
    if (large) return;
    resplit_last_sheet(mesh, o, chooser.part_options(), bound, chooser, c);
    fewer_seams_without_tab(chooser, candidates, c);
    if (part_options.move_seams) close_slits_across_parts(mesh, o, chooser, c);
    open_slits_between_parts(mesh, o, choose.open_slits, chooser, c);
    if (choose.join_on_a_sheet) join_parts_on_a_sheet(mesh, o, chooser, c);
  };
  if (!keep_patches_only_if_legible(chooser, o, candidates, best, finish)) finish(best);
  if (best.patches)
    return {std::move(best.parts.unfolding), too_large, best.parts.unfolding.piece_count,
            std::move(best.layout), true};
  const int untouched = u.piece_count - best.parts.split_pieces;
  return {std::move(best.parts.unfolding), best.parts.split_pieces,
          best.parts.unfolding.piece_count - untouched, std::move(best.layout)};
}

// Tabs tucked into bays pack most nets closer (layout::TabOptions::into_bays), not every one:
// lowpoly/football at 250 mm took 7 sheets with them (every candidate's estimate 7), 6 without. Where
// the layout stays more than a sheet above what any partition needs (`least`), the parts are chosen
// again with alternating tabs.
ChosenParts with_alternating_tabs_if_fewer(const unfold::Mesh& mesh, const unfold::Unfolding& u,
                                           const layout::LayoutOptions& asked,
                                           const unfold::PartOptions& parts, const ChooseOptions& choose,
                                           long least, ChosenParts chosen) {
  const auto over = [least](const ChosenParts& c) {
    return c.layout ? static_cast<long>(c.layout->sheets.size()) - least : 0;
  };
  if (!asked.tab.into_bays || least <= 0 || over(chosen) <= 1 || mesh.num_faces() > kManyFaces) return chosen;
  if (asked.deadline && std::chrono::steady_clock::now() > *asked.deadline) return chosen;
  layout::LayoutOptions alternating = asked;
  alternating.tab.into_bays = false;
  try {
    long unused = 0;
    ChosenParts other = choose_parts_once(mesh, u, alternating, parts, choose, unused);
    if (over(other) < over(chosen)) return other;
  } catch (const LayoutError&) {
    // out of time: the choice made stands
  }
  return chosen;
}

// Whether `closer` is legible enough to take the place of `held` for the sheet it saves: at most
// kPatchLabelShare of its labels more flaws, and no more than issue 12's kLegibleLabelShare unless
// `held` had as many. rocker_arm_350 at 150 mm fits one sheet at 1 mm with 6 of 390 labels unclear
// (1.5%) where its two sheets had none: under 2% alone, but it took the label sweep's total over it.
bool as_legible_as(const layout::LayoutResult& closer, const layout::LayoutResult& held) {
  const int labels = closer.label_audit.labels;
  const int more = labels_at_share(kPatchLabelShare, labels);
  const int legible = labels_at_share(kLegibleLabelShare, labels);
  return cli::flaws(closer) <= std::max(cli::flaws(held), std::min(legible, cli::flaws(held) + more));
}

// The gaps between parts are what ragged nets lose most paper to: half of them takes bumpy_528 at
// 250 mm from 7 sheets to 6 and bunny_1000 from 6 to 5. A gap is the builder's room to cut one part
// without nicking the next, so it closes only where that saves a sheet, and only where no colour
// bleeds into it (ChooseOptions::closer_spacing_mm is then unset or no closer). The choice at the
// closer gap is screened by its estimates first: where none saves a sheet it stops before its full
// layouts (cheburashka_500 at 250 mm: 19.2 -> 12.6 s of CPU, the same 4 sheets). Nor does it try its
// tabs alternating too: each of the five runs that saved a sheet saved it with tabs in bays.
ChosenParts closer_if_a_sheet_fewer(const unfold::Mesh& mesh, const unfold::Unfolding& u,
                                    const layout::LayoutOptions& asked, const unfold::PartOptions& parts,
                                    const ChooseOptions& choose, long least, ChosenParts chosen) {
  if (!choose.closer_spacing_mm || !(*choose.closer_spacing_mm < asked.pack.spacing_mm)) return chosen;
  if (!chosen.layout || mesh.num_faces() > kManyFaces) return chosen;
  const layout::LayoutResult& held = *chosen.layout;
  if (!closer_spacing_worth_trying(held, least)) return chosen;
  if (asked.deadline && std::chrono::steady_clock::now() > *asked.deadline) return chosen;
  layout::LayoutOptions closer = asked;
  closer.pack.spacing_mm = *choose.closer_spacing_mm;
  const long held_sheets = static_cast<long>(held.sheets.size());
  try {
    long unused = 0;
    ChosenParts other = choose_parts_once(mesh, u, closer, parts, choose, unused, held_sheets);
    if (!other.layout || static_cast<long>(other.layout->sheets.size()) >= held_sheets) return chosen;
    if (!as_legible_as(*other.layout, held)) return chosen;
    other.layout->notes.push_back("pieces packed " + format_length_mm(closer.pack.spacing_mm) +
                                  " apart, not " + format_length_mm(asked.pack.spacing_mm) +
                                  ", which saves a sheet (" + std::to_string(other.layout->sheets.size()) +
                                  " instead of " + std::to_string(held.sheets.size()) +
                                  "); --spacing keeps the gap asked");
    return other;
  } catch (const LayoutError&) {
    // out of time: the choice made stands
  }
  return chosen;
}

}  // namespace

bool closer_spacing_worth_trying(const layout::LayoutResult& held, long least) {
  const long sheets = static_cast<long>(held.sheets.size());
  if (least <= 0 || sheets <= least) return false;  // so sheets >= 2
  const double fewer_fill = held.overall.coverage * sheets / (sheets - 1);
  return fewer_fill <= kCloserSpacingReach &&
         flaws(held) <= labels_at_share(kLegibleLabelShare, held.label_audit.labels);
}

ChosenParts choose_parts(const unfold::Mesh& mesh, const unfold::Unfolding& u,
                         const layout::LayoutOptions& asked, const unfold::PartOptions& parts,
                         const ChooseOptions& choose) {
  long least = 0;
  ChosenParts chosen = choose_parts_once(mesh, u, asked, parts, choose, least);
  chosen = with_alternating_tabs_if_fewer(mesh, u, asked, parts, choose, least, std::move(chosen));
  return closer_if_a_sheet_fewer(mesh, u, asked, parts, choose, least, std::move(chosen));
}

}  // namespace foldkit::cli
