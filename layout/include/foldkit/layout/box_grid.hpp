#pragma once
// A uniform grid of boxes over a bounded region: which of many small items may touch a query box, in
// time proportional to the items near it. Labels and part letters look up the lines and labels they
// must keep clear of through it, so placing them stays near-linear on meshes of any size.
#include <cstdint>
#include <vector>

#include "foldkit/geom/vec.hpp"

namespace foldkit::layout {

class BoxGrid {
 public:
  /// A grid over `region` (items and queries outside it fall into the border cells, so nothing is
  /// missed) with cells of about `cell_mm`, coarsened so that a side has at most `max_cells_per_side`.
  BoxGrid(const Box2& region, double cell_mm, int max_cells_per_side = 256);

  /// Registers item `id` (>= 0) as covering `box`.
  void insert(int id, const Box2& box);

  /// Calls `visit(id)` once for every item whose box overlaps `box`; stops when `visit` returns false.
  /// Returns false when stopped.
  template <class Visit>
  bool visit(const Box2& box, Visit&& visit_item) const {
    const auto [x0, y0, x1, y1] = cell_range(box);
    ++stamp_;
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x)
        for (int id : cells_[static_cast<std::size_t>(y) * nx_ + x]) {
          if (seen_[id] == stamp_) continue;
          seen_[id] = stamp_;
          if (boxes_[id].overlaps(box) && !visit_item(id)) return false;
        }
    return true;
  }

 private:
  struct Range {
    int x0, y0, x1, y1;
  };
  Range cell_range(const Box2& box) const;

  Vec2 origin_;
  double cell_ = 1;
  int nx_ = 1, ny_ = 1;
  std::vector<std::vector<int>> cells_;
  std::vector<Box2> boxes_;
  // Per item, the query that last saw it: each item is visited once per query.
  mutable std::vector<std::uint32_t> seen_;
  mutable std::uint32_t stamp_ = 0;
};

}  // namespace foldkit::layout
