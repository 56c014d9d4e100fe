#include "foldkit/layout/box_grid.hpp"

#include <algorithm>
#include <cmath>

namespace foldkit::layout {

BoxGrid::BoxGrid(const Box2& region, double cell_mm, int max_cells_per_side) {
  const Box2 r = region.empty() ? Box2{{0, 0}, {1, 1}} : region;
  origin_ = r.min;
  const double extent = std::max({r.width(), r.height(), 1e-9});
  cell_ = std::max({cell_mm, extent / std::max(max_cells_per_side, 1), 1e-9});
  nx_ = std::clamp(static_cast<int>(std::ceil(r.width() / cell_)), 1, std::max(max_cells_per_side, 1));
  ny_ = std::clamp(static_cast<int>(std::ceil(r.height() / cell_)), 1, std::max(max_cells_per_side, 1));
  cells_.resize(static_cast<std::size_t>(nx_) * ny_);
}

BoxGrid::Range BoxGrid::cell_range(const Box2& box) const {
  auto cell = [&](double v, double o, int n) {
    const double c = std::floor((v - o) / cell_);
    // Clamping keeps far-away (and non-finite) coordinates in the border cells instead of overflowing.
    if (!(c > 0)) return 0;
    return c >= n - 1 ? n - 1 : static_cast<int>(c);
  };
  return {cell(box.min.x, origin_.x, nx_), cell(box.min.y, origin_.y, ny_), cell(box.max.x, origin_.x, nx_),
          cell(box.max.y, origin_.y, ny_)};
}

void BoxGrid::insert(int id, const Box2& box) {
  if (id >= static_cast<int>(boxes_.size())) {
    boxes_.resize(id + 1);
    seen_.resize(id + 1, 0);
  }
  boxes_[id] = box;
  const auto [x0, y0, x1, y1] = cell_range(box);
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x)
      cells_[static_cast<std::size_t>(y) * nx_ + x].push_back(id);
}

}  // namespace foldkit::layout
