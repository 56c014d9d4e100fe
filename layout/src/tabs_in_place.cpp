#include "foldkit/layout/tabs_in_place.hpp"

#include <algorithm>
#include <optional>

#include "foldkit/layout/box_grid.hpp"

namespace foldkit::layout {
namespace {

// Touching (a tab's corner on its neighbour's) is not overlapping.
constexpr double kTouch_mm = 1e-6;
// Grid cells of about a tab's size: a query meets few cells and few shapes.
constexpr double kCell_mm = 5;

// One shape on a packed sheet: a piece's body part, one of its tabs, or something else packed.
struct Shape {
  int piece = -1;  // -1: not a piece's
  int seam = -1;   // the seam of a tab, else -1
  Polygon mm;      // packing frame
  bool present = true;
};

class PackedSheets {
 public:
  PackedSheets(const PackedRoom& room, int sheet_count) : room_(room) {
    grids_.reserve(sheet_count);
    for (int k = 0; k < sheet_count; ++k)
      grids_.emplace_back(room.area_mm, kCell_mm);
  }

  int add(int sheet, Shape shape) {
    const int id = static_cast<int>(shapes_.size());
    grids_[sheet].insert(id, bounds_of(shape.mm));
    shapes_.push_back(std::move(shape));
    return id;
  }

  void remove(int id) { shapes_[id].present = false; }

  // Whether `tab` (packing frame) of `seam` on `piece` may go on `sheet`: inside the area, out of the
  // keep-out zones, clear of the piece's other tabs and of every other piece by the spacing. The seam's
  // own tabs are the ones it replaces. With seam -1 the shape is no tab (a label) and only the other
  // pieces count.
  bool holds(int sheet, int piece, int seam, const Polygon& tab) const {
    const Box2 box = bounds_of(tab);
    const Box2& area = room_.area_mm;
    if (box.min.x < area.min.x - kTouch_mm || box.min.y < area.min.y - kTouch_mm ||
        box.max.x > area.max.x + kTouch_mm || box.max.y > area.max.y + kTouch_mm)
      return false;
    const double gap = room_.spacing_mm;
    const Box2 near{{box.min.x - gap, box.min.y - gap}, {box.max.x + gap, box.max.y + gap}};
    for (const Box2& z : room_.keep_out_mm) {
      const Polygon zone{z.min, {z.max.x, z.min.y}, z.max, {z.min.x, z.max.y}};
      if (z.overlaps(near) && convex_overlap(tab, zone, -gap)) return false;
    }
    return grids_[sheet].visit(near, [&](int id) {
      const Shape& s = shapes_[id];
      if (!s.present || (seam >= 0 && s.seam == seam)) return true;
      if (s.piece == piece) return seam < 0 || s.seam < 0 || !convex_overlap(tab, s.mm, kTouch_mm);
      return !convex_overlap(tab, s.mm, -gap);
    });
  }

 private:
  const PackedRoom& room_;
  std::vector<BoxGrid> grids_;
  std::vector<Shape> shapes_;
};

// The tabs a plan gives seam s, by side (a split seam has both).
std::array<const Tab*, 2> tabs_of(const TabPlan& plan, std::size_t s) {
  return {plan.on_side(s, 0), plan.on_side(s, 1)};
}

bool same_tab(const Tab* a, const Tab* b) {
  return a == nullptr ? b == nullptr : b != nullptr && a->quad_mm == b->quad_mm;
}

Shape tab_shape(const Tab& tab, const PackedRoom& room) {
  return {tab.piece, static_cast<int>(tab.seam.index()),
          room.placements[tab.piece].transform.apply(tab.quad_mm)};
}

int sheet_count_of(std::span<const PackPlacement> placements,
                   std::span<const std::pair<int, Polygon>> others) {
  int count = 0;
  for (const PackPlacement& p : placements)
    count = std::max(count, p.sheet + 1);
  for (const auto& [sheet, shape] : others)
    count = std::max(count, sheet + 1);
  return count;
}

// The packed sheets with every piece's body and the tabs of `plan`; per seam, the ids of its tabs.
PackedSheets index_room(std::span<const Seam> seams, const TabPlan& plan, const PackedRoom& room,
                        std::vector<std::vector<int>>& tab_shapes) {
  PackedSheets sheets(room, sheet_count_of(room.placements, room.others_mm));
  for (std::size_t p = 0; p < room.placements.size(); ++p)
    for (const Polygon& body : room.bodies_mm[p])
      sheets.add(room.placements[p].sheet,
                 {static_cast<int>(p), -1, room.placements[p].transform.apply(body)});
  for (const auto& [sheet, shape] : room.others_mm)
    sheets.add(sheet, {-1, -1, shape});
  tab_shapes.assign(seams.size(), {});
  for (const Tab* tab : plan.all())
    tab_shapes[tab->seam.index()].push_back(
        sheets.add(room.placements[tab->piece].sheet, tab_shape(*tab, room)));
  return sheets;
}

}  // namespace

TabPlan tabs_in_place(std::span<const Seam> seams, const TabPlan& placed, const TabPlan& wanted,
                      const PackedRoom& room) {
  std::vector<std::vector<int>> tab_shapes;
  PackedSheets sheets = index_room(seams, placed, room, tab_shapes);
  TabPlan mixed = placed;
  for (std::size_t s = 0; s < seams.size(); ++s) {
    const std::array<const Tab*, 2> now = tabs_of(placed, s), want = tabs_of(wanted, s);
    if (same_tab(now[0], want[0]) && same_tab(now[1], want[1])) continue;
    if (!want[0] && !want[1]) continue;  // never a seam without a tab for one with
    const int seam = static_cast<int>(s);
    const bool fits = std::all_of(want.begin(), want.end(), [&](const Tab* t) {
      return t == nullptr ||
             sheets.holds(room.placements[t->piece].sheet, t->piece, seam, tab_shape(*t, room).mm);
    });
    if (!fits) continue;
    for (int id : tab_shapes[s])
      sheets.remove(id);
    tab_shapes[s].clear();
    for (const Tab* t : want)
      if (t) tab_shapes[s].push_back(sheets.add(room.placements[t->piece].sheet, tab_shape(*t, room)));
    mixed.tab_of_seam[s] = wanted.tab_of_seam[s];
    const bool split = s < wanted.second_half_of_seam.size() && wanted.second_half_of_seam[s];
    if (split || s < mixed.second_half_of_seam.size()) {
      mixed.second_half_of_seam.resize(seams.size());
      mixed.second_half_of_seam[s] = split ? wanted.second_half_of_seam[s] : std::nullopt;
    }
  }
  mixed.dropped.clear();
  for (SeamId s : placed.dropped)
    if (!mixed.tab_of_seam[s.index()]) mixed.dropped.push_back(s);
  return mixed;
}

bool clear_in_place(std::span<const std::pair<int, Polygon>> shapes, std::span<const Seam> seams,
                    const TabPlan& plan, const PackedRoom& room) {
  std::vector<std::vector<int>> tab_shapes;
  const PackedSheets sheets = index_room(seams, plan, room, tab_shapes);
  return std::all_of(shapes.begin(), shapes.end(), [&](const std::pair<int, Polygon>& shape) {
    const PackPlacement& at = room.placements[shape.first];
    return sheets.holds(at.sheet, shape.first, -1, at.transform.apply(shape.second));
  });
}

}  // namespace foldkit::layout
