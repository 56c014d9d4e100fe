#include "foldkit/layout/pack.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <numbers>
#include <numeric>
#include <optional>
#include <span>
#include <string>
#include <thread>
#include <tuple>
#include <utility>
#include <vector>

#include "foldkit/error.hpp"
#include "foldkit/geom/hull.hpp"
#include "foldkit/geom/parallel.hpp"

namespace foldkit::layout {
namespace {

// About 4 bytes a cell per open sheet (SheetGrid): a 3 m x 3 m sheet in 0.5 mm cells is 36 million.
constexpr double kMaxGridCells = 64e6;
// Cells across a sheet at most: a column number fits two bytes (SheetGrid::Column). 16 m at 0.5 mm.
constexpr double kMostGridColumns = 32767;
constexpr std::uint64_t kShakeSeed = 1;

// An item at one rotation, as runs of cells per row relative to its raster origin.
struct Raster {
  double angle_rad = 0;
  Vec2 origin;  // item-frame point (after rotation) at the raster's lower-left cell corner
  int width = 0, height = 0;
  // Per row j: inclusive [i0, i1] runs, run_cells[row_start[j] .. row_start[j + 1]), kept in one block.
  std::vector<std::pair<int, int>> run_cells;
  std::vector<int> row_start;
  std::vector<int> widest_run;   // per row: the longest run, in cells
  std::vector<int> probe_order;  // rows spread out: far rows collide independently
  long cells = 0;
  double centroid_x = 0, centroid_y = 0;  // mean cell position, in cells from the raster origin

  std::span<const std::pair<int, int>> runs(int j) const {
    return {run_cells.data() + row_start[j], run_cells.data() + row_start[j + 1]};
  }
};

std::vector<Polygon> rotate_all(std::span<const Polygon> shape, double angle) {
  std::vector<Polygon> out(shape.begin(), shape.end());
  for (Polygon& p : out)
    for (Vec2& v : p)
      v = rotated(v, angle);
  return out;
}

// The shape grown by `grow` plus the arc tolerance, in the item's frame. Growing commutes with
// rotation, so one offset serves every rotation (it was most of the packing time on large parts).
std::vector<Polygon> grow_shape(std::span<const Polygon> shape, double grow) {
  constexpr double kArcTolerance = 0.02;
  return polygon_offset(shape, grow + kArcTolerance, kArcTolerance);
}

// 0..n-1 in van der Corput order (the middle, the quarters, the eighths, ...).
std::vector<int> spread_order(int n) {
  std::vector<int> order;
  order.reserve(static_cast<std::size_t>(std::max(n, 0)));
  int bits = 0;
  while ((1 << bits) < n)
    ++bits;
  for (int k = 0; k < (1 << bits); ++k) {
    int rev = 0;
    for (int b = 0; b < bits; ++b)
      if (k & (1 << b)) rev |= 1 << (bits - 1 - b);
    if (rev < n) order.push_back(rev);
  }
  return order;
}

// Marks every cell whose centre lies inside the grown shape turned by `angle`: with grow = spacing/2
// plus half a cell diagonal, that is every cell the shape grown by spacing/2 touches.
// A shape larger than the grid (nx x ny cells) gets no cells and a size that fits nowhere: its cell
// count would overflow an int, and its rows would be gigabytes, long before it could be placed.
Raster rasterize(std::span<const Polygon> grown_shape, double angle, double cell, int nx, int ny) {
  Raster r;
  r.angle_rad = angle;
  const std::vector<Polygon> grown = rotate_all(grown_shape, angle);
  Box2 box;
  for (const Polygon& p : grown)
    box.add(bounds_of(p));
  if (box.empty()) return r;
  if (!(box.width() / cell < nx && box.height() / cell < ny)) {
    r.width = nx + 1;
    r.height = ny + 1;
    return r;
  }
  r.origin = box.min;
  r.width = static_cast<int>(std::ceil(box.width() / cell)) + 1;
  r.height = static_cast<int>(std::ceil(box.height() / cell)) + 1;
  r.row_start.reserve(static_cast<std::size_t>(r.height) + 1);
  // Each edge adds its crossings to the rows whose centre line it spans: one pass over the edges
  // instead of one per row.
  std::vector<std::vector<double>> crossings(r.height);
  for (const Polygon& p : grown)
    for (std::size_t i = 0, n = p.size(); i < n; ++i) {
      const Vec2 a = p[i], b = p[(i + 1) % n];
      if (a.y == b.y) continue;
      const double lo = std::min(a.y, b.y), hi = std::max(a.y, b.y);
      // The rows whose centre line may lie in [lo, hi), one more each side against rounding; the
      // exact test below decides.
      const int j0 = std::max(0, static_cast<int>(std::floor((lo - r.origin.y) / cell - 0.5)));
      const int j1 = std::min(r.height - 1, static_cast<int>(std::floor((hi - r.origin.y) / cell - 0.5)) + 1);
      for (int j = j0; j <= j1; ++j) {
        const double y = r.origin.y + cell * (j + 0.5);
        if ((a.y <= y) != (b.y <= y)) crossings[j].push_back(a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y));
      }
    }
  for (int j = 0; j < r.height; ++j) {
    r.row_start.push_back(static_cast<int>(r.run_cells.size()));
    std::vector<double>& xs = crossings[j];
    std::sort(xs.begin(), xs.end());
    // Clipper's offset output is a set of disjoint outer loops and holes: even-odd filling is exact.
    for (std::size_t k = 0; k + 1 < xs.size(); k += 2) {
      int i0 = static_cast<int>(std::ceil((xs[k] - r.origin.x) / cell - 0.5));
      int i1 = static_cast<int>(std::floor((xs[k + 1] - r.origin.x) / cell - 0.5));
      i0 = std::max(i0, 0);
      i1 = std::min(i1, r.width - 1);
      if (i0 > i1) continue;
      auto& row = r.run_cells;
      if (static_cast<int>(row.size()) > r.row_start.back() && i0 <= row.back().second + 1) {
        row.back().second = std::max(row.back().second, i1);
      } else {
        row.push_back({i0, i1});
      }
    }
    r.widest_run.push_back(0);
    for (std::size_t k = static_cast<std::size_t>(r.row_start.back()); k < r.run_cells.size(); ++k) {
      const auto [i0, i1] = r.run_cells[k];
      r.widest_run.back() = std::max(r.widest_run.back(), i1 - i0 + 1);
      const long n = i1 - i0 + 1;
      r.cells += n;
      r.centroid_x += 0.5 * (i0 + i1) * n;
      r.centroid_y += static_cast<double>(j) * n;
    }
  }
  r.row_start.push_back(static_cast<int>(r.run_cells.size()));
  r.probe_order = spread_order(r.height);
  if (r.cells > 0) {
    r.centroid_x /= r.cells;
    r.centroid_y /= r.cells;
  }
  return r;
}

// Occupancy of one sheet. last_taken[y * nx + x] is the largest x' <= x whose cell is taken, or -1:
// a run of an item collides exactly when the last taken cell at its right end is at or after its left end,
// and that cell tells how far the item must move right.
class SheetGrid {
 public:
  // A cell's column; sheets are at most kMostGridColumns cells across (pack_grid), so two bytes hold
  // it and a sheet row is half the memory the packing reads most.
  using Column = std::int16_t;

  SheetGrid(int nx, int ny)
      : nx_(nx),
        ny_(ny),
        last_taken_(std::size_t(nx) * ny, Column{-1}),
        widest_free_(ny, nx),
        runs_of_length_(std::size_t(nx + 1) * ny, 0) {
    free_ = long(nx) * ny;
    for (int y = 0; y < ny; ++y)
      runs_of_length_[std::size_t(y) * (nx + 1) + nx] = 1;
  }

  int nx() const { return nx_; }
  int ny() const { return ny_; }
  long free_cells() const { return free_; }

  // The runs of free cells of row y counted by length afresh, and the longest.
  void count_free_runs(int y) {
    const Column* last = &last_taken_[std::size_t(y) * nx_];
    std::uint16_t* runs = &runs_of_length_[std::size_t(y) * (nx_ + 1)];
    std::fill(runs, runs + nx_ + 1, std::uint16_t{0});
    int widest = 0;
    for (int x = 0; x < nx_; ++x) {
      const int run = x - last[x];
      if (run > 0 && (x + 1 == nx_ || last[x + 1] == x + 1)) {
        ++runs[run];
        widest = std::max(widest, run);
      }
    }
    widest_free_[y] = widest;
  }

  // This grid made equal to `blank` (a grid of the same size this one was copied from) by copying back
  // only the rows taken since: a sheet's grid is about a megabyte, most of it untouched by a packing.
  void reset_to(const SheetGrid& blank) {
    if (dirty_low_ <= dirty_high_) {
      const std::size_t from = std::size_t(dirty_low_) * nx_, to = std::size_t(dirty_high_ + 1) * nx_;
      std::copy(blank.last_taken_.begin() + from, blank.last_taken_.begin() + to, last_taken_.begin() + from);
      std::copy(blank.widest_free_.begin() + dirty_low_, blank.widest_free_.begin() + dirty_high_ + 1,
                widest_free_.begin() + dirty_low_);
      const std::size_t row = std::size_t(nx_) + 1;
      std::copy(blank.runs_of_length_.begin() + dirty_low_ * row,
                blank.runs_of_length_.begin() + (dirty_high_ + 1) * row,
                runs_of_length_.begin() + dirty_low_ * row);
    }
    free_ = blank.free_;
    dirty_low_ = blank.dirty_low_;
    dirty_high_ = blank.dirty_high_;
  }

  void take(int y, int x0, int x1) {
    if (y < 0 || y >= ny_) return;
    x0 = std::max(x0, 0);
    x1 = std::min(x1, nx_ - 1);
    if (x0 > x1) return;
    dirty_low_ = std::min(dirty_low_, y);
    dirty_high_ = std::max(dirty_high_, y);
    Column* last = &last_taken_[std::size_t(y) * nx_];
    const int run_start = x0 > 0 ? last[x0 - 1] + 1 : 0;
    const long free_before = free_;
    for (int x = x0; x <= x1; ++x) {
      free_ -= last[x] != x;  // a cell is taken where it is its own last taken cell
      last[x] = static_cast<Column>(x);
    }
    // Beyond the run, the last taken cell is x1 until a cell taken before.
    int run_end = x1 + 1;
    for (; run_end < nx_ && last[run_end] < x1; ++run_end)
      last[run_end] = static_cast<Column>(x1);
    // Cells taken out of one free run (an item's, never overlapping) leave every other run as it was:
    // that run is counted as the two pieces left of it, and the widest shrinks only when no run that
    // long is left.
    if (free_before - free_ != x1 - x0 + 1) {
      count_free_runs(y);
      return;
    }
    std::uint16_t* runs = &runs_of_length_[std::size_t(y) * (nx_ + 1)];
    --runs[run_end - run_start];
    ++runs[x0 - run_start];
    ++runs[run_end - 1 - x1];
    runs[0] = 0;
    int widest = widest_free_[y];
    while (widest > 0 && runs[widest] == 0)
      --widest;
    widest_free_[y] = widest;
  }

  // False when some row of r, with its bottom row at y, is wider than any free run of the sheet row it
  // would lie on: the cheap test that skips the full rows of a filling sheet.
  // `hot` is the raster row that failed last, and becomes the one that fails: scanning down a row at a
  // time, the row above it lands on the same sheet row next, so the check starts there.
  bool rows_may_fit(const Raster& r, int y, int& hot) const {
    if (r.height == 0) return true;
    const int* free_width = &widest_free_[std::size_t(y)];
    const int* need = r.widest_run.data();
    const int first = hot + 1 == r.height ? 0 : hot + 1;
    if (free_width[first] < need[first]) {
      hot = first;
      return false;
    }
    // Then every row, a block at a time: comparisons without branches, which the compiler vectorises
    // (a piece that fits its rows costs a comparison per row, and most rows tried do).
    constexpr int kBlock = 32;
    for (int j0 = 0; j0 < r.height; j0 += kBlock) {
      const int j1 = std::min(j0 + kBlock, r.height);
      int short_rows = 0;
      for (int j = j0; j < j1; ++j)
        short_rows += free_width[j] < need[j];
      if (short_rows == 0) continue;
      int j = j0;
      while (free_width[j] >= need[j])
        ++j;
      hot = j;
      return false;
    }
    return true;
  }

  // After rows_may_fit(r, y, hot) failed: the highest row below y worth trying. Sheet row y + hot is
  // narrower than raster row hot; each lower row puts a higher raster row on it, and a row that is
  // still too wide there fails the same way, so the scan skips down the piece's wide body at once.
  int next_row_to_try(const Raster& r, int y, int hot) const {
    const int narrow = y + hot;
    const int free_width = widest_free_[narrow];
    int below = y - 1;
    while (below >= 0 && narrow - below < r.height && r.widest_run[narrow - below] > free_width)
      --below;
    return below;
  }

  // Smallest x >= from at which raster r, with its bottom row at y, meets no taken cell; -1 if none.
  int first_fit_in_row(const Raster& r, int y, int from) const {
    int x = from;
    int hot_row = -1;  // the row that collided last is the likeliest to collide again
    const auto collides = [&](int j) {
      const Column* last = &last_taken_[std::size_t(y + j) * nx_];
      for (auto [i0, i1] : r.runs(j)) {
        const int hit = last[x + i1];
        if (hit >= x + i0) {
          x = hit - i0 + 1;
          return true;
        }
      }
      return false;
    };
    while (x + r.width <= nx_) {
      if (hot_row >= 0 && collides(hot_row)) continue;
      bool collided = false;
      for (int j : r.probe_order) {
        if (j != hot_row && collides(j)) {
          hot_row = j;
          collided = true;
          break;
        }
      }
      if (!collided) return x;
    }
    return -1;
  }

 private:
  int nx_, ny_;
  std::vector<Column> last_taken_;
  std::vector<int> widest_free_;               // per row: the longest run of free cells
  std::vector<std::uint16_t> runs_of_length_;  // per row, per length 0..nx: free runs that long
  long free_ = 0;
  int dirty_low_ = std::numeric_limits<int>::max(), dirty_high_ = -1;  // rows taken since made blank
};

struct Spot {
  int x = -1, y = -1;
  const Raster* raster = nullptr;
  double score_y = -1e300, score_x = 1e300;
};

// Whether a spot scored (score_y, score_x) at rotation k (the index in the item's rasters) beats `b` at
// rotation b_k: its centre of area higher on the sheet, then further left, then an earlier rotation.
bool beats(double score_y, double score_x, int k, const Spot& b, int b_k) {
  if (score_y > b.score_y + 1e-9) return true;
  if (score_y < b.score_y - 1e-9) return false;
  return score_x < b.score_x || (score_x == b.score_x && k < b_k);
}

// The placement whose centre of area is highest on the sheet (then leftmost), over all rotations:
// judging by the centre rather than the bottom edge lets a tall piece drop into a tall gap instead
// of lying flat across the top. For each rotation the highest feasible row is found by scanning down.
// The rows' widths alone say how high each rotation could lie, cheaply: rotations are tried highest
// first, and once the best found lies above what the rest could reach, they are not tried at all.
Spot find_spot(const SheetGrid& grid, const std::vector<Raster>& rasters) {
  struct Reach {
    int k = 0, y = -1, hot = -1;
    double score_y = 0;
  };
  std::vector<Reach> reach;
  reach.reserve(rasters.size());
  for (int k = 0; k < static_cast<int>(rasters.size()); ++k) {
    const Raster& r = rasters[static_cast<std::size_t>(k)];
    if (r.width > grid.nx() || r.height > grid.ny() || r.cells > grid.free_cells()) continue;
    Reach at{k, grid.ny() - r.height, -1, 0};
    while (at.y >= 0 && !grid.rows_may_fit(r, at.y, at.hot))
      at.y = grid.next_row_to_try(r, at.y, at.hot);
    if (at.y < 0) continue;
    at.score_y = at.y + r.centroid_y;
    reach.push_back(at);
  }
  std::stable_sort(reach.begin(), reach.end(),
                   [](const Reach& a, const Reach& b) { return a.score_y > b.score_y; });
  Spot best;
  int best_k = -1;
  for (Reach& at : reach) {
    if (at.score_y < best.score_y - 1e-9) break;
    const Raster& r = rasters[static_cast<std::size_t>(at.k)];
    for (int y = at.y; y >= 0; --y) {
      const double score_y = y + r.centroid_y;
      if (score_y < best.score_y - 1e-9) break;
      if (y < at.y && !grid.rows_may_fit(r, y, at.hot)) {
        y = grid.next_row_to_try(r, y, at.hot) + 1;  // the loop steps down to it
        continue;
      }
      const int x = grid.first_fit_in_row(r, y, 0);
      if (x < 0) continue;
      const double score_x = x + r.centroid_x;
      if (best_k < 0 || beats(score_y, score_x, at.k, best, best_k)) {
        best = {x, y, &r, score_y, score_x};
        best_k = at.k;
      }
      break;
    }
  }
  return best;
}

// The turns that lay each of the `count` longest edges of the hull of `points` along the x axis.
std::vector<double> hull_edge_angles(const std::vector<Vec2>& points, int count) {
  const std::vector<Vec2> hull = convex_hull(points);
  std::vector<std::pair<double, double>> edges;  // minus the length (longest first), direction
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Vec2 e = hull[(i + 1) % hull.size()] - hull[i];
    edges.emplace_back(-norm(e), std::atan2(e.y, e.x));
  }
  std::sort(edges.begin(), edges.end());
  edges.resize(std::min(edges.size(), static_cast<std::size_t>(std::max(count, 0))));
  std::vector<double> angles;
  for (const auto& [minus_length, direction] : edges)
    angles.push_back(-direction);
  return angles;
}

std::vector<double> candidate_angles(const PackItem& item, const PackOptions& options) {
  if (!item.rotate) return {0.0};
  std::vector<double> angles;
  const int n = std::max(options.rotations, 1);
  for (int k = 0; k < n; ++k)
    angles.push_back(2 * std::numbers::pi * k / n);
  std::vector<Vec2> points;
  for (const Polygon& p : item.shape_mm)
    points.insert(points.end(), p.begin(), p.end());
  const double tight = min_area_rect_angle(points);
  for (int k = 0; k < 4; ++k)
    angles.push_back(tight + k * std::numbers::pi / 2);
  angles.insert(angles.end(), item.extra_angles_rad.begin(), item.extra_angles_rad.end());
  for (double flush : hull_edge_angles(points, options.aligned_hull_edges))
    for (int k = 0; k < 4; ++k)
      angles.push_back(flush + k * std::numbers::pi / 2);
  std::vector<double> unique;
  for (double a : angles) {
    a = std::fmod(a, 2 * std::numbers::pi);
    if (a < 0) a += 2 * std::numbers::pi;
    bool seen = false;
    for (double u : unique) {
      double d = std::fabs(a - u);
      seen |= std::min(d, 2 * std::numbers::pi - d) < std::numbers::pi / 360;
    }
    if (!seen) unique.push_back(a);
  }
  return unique;
}

// SplitMix64: a portable stream of uniform numbers in [0, 1) (std:: distributions differ between
// standard libraries, and the packing must not).
double unit_random(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * 0x1.0p-53;
}

// The cells of all items, each at its leanest rotation (grown by half the spacing).
double leanest_cells(const std::vector<std::vector<Raster>>& rasters) {
  double cells = 0;
  for (const std::vector<Raster>& item : rasters) {
    long least = 0;
    for (const Raster& r : item)
      if (r.cells > 0 && (least == 0 || r.cells < least)) least = r.cells;
    cells += static_cast<double>(least);
  }
  return cells;
}

// The fewest sheets the items' cells could fill at `fill` of each sheet's cells.
long sheets_at_fill(const std::vector<std::vector<Raster>>& rasters, long sheet_cells, double fill) {
  const double room = fill * static_cast<double>(sheet_cells);
  return room > 0 ? std::max(1L, static_cast<long>(std::ceil(leanest_cells(rasters) / room))) : 1;
}

// The share of a sheet's cells that papercraft shapes can fill: fewer sheets are not worth shaken orders.
constexpr double kReachableFill = 0.75;

// Shaken orders cost a packing run each, and a run costs more the more items there are: the count
// shrinks with the items so a layout of many parts stays fast.
int shaken_orders(std::size_t items, int most) {
  constexpr double kItemRuns = 400;  // items x runs
  if (items < 2) return 0;
  return std::clamp(static_cast<int>(kItemRuns / static_cast<double>(items)), std::min(most, 4), most);
}

// The packing grid: cells of cell_mm over the area grown by half a gap on every side (an item's grown
// shape may use that margin, the item may not).
struct PackGrid {
  double cell = 0, half_gap = 0;
  double grow = 0;  // how far item shapes are grown before rasterising
  Vec2 min;         // sheet-frame corner of cell (0, 0)
  int nx = 0, ny = 0;
};

PackGrid pack_grid(const PackOptions& options) {
  PackGrid g;
  g.cell = options.cell_mm;
  g.half_gap = 0.5 * options.spacing_mm;
  g.min = options.area_mm.min - Vec2{g.half_gap, g.half_gap};
  const double cells_x = std::floor((options.area_mm.width() + 2 * g.half_gap) / g.cell);
  const double cells_y = std::floor((options.area_mm.height() + 2 * g.half_gap) / g.cell);
  // Checked in floating point, before any cast or allocation (a 1e9 mm sheet was a 4e18-byte grid).
  if (!(cells_x * cells_y <= kMaxGridCells && cells_x <= kMostGridColumns)) {
    char text[160];
    if (cells_x > kMostGridColumns)
      std::snprintf(text, sizeof text, "the sheet is too wide to pack: %g mm in %g mm cells is over %g cells",
                    options.area_mm.width(), g.cell, kMostGridColumns);
    else
      std::snprintf(text, sizeof text,
                    "the sheet is too large to pack: %gx%g mm in %g mm cells is over %g cells",
                    options.area_mm.width(), options.area_mm.height(), g.cell, kMaxGridCells);
    throw LayoutError(text);
  }
  g.nx = std::max(0, static_cast<int>(cells_x));
  g.ny = std::max(0, static_cast<int>(cells_y));
  g.grow = g.half_gap + g.cell * std::sqrt(0.5);
  return g;
}

// A fresh sheet: every cell free except those within half a gap of a keep-out zone.
SheetGrid blank_sheet(const PackGrid& g, std::span<const Box2> keep_out) {
  SheetGrid sheet(g.nx, g.ny);
  for (const Box2& box : keep_out) {
    const int x0 = static_cast<int>(std::floor((box.min.x - g.half_gap - g.min.x) / g.cell));
    const int x1 = static_cast<int>(std::ceil((box.max.x + g.half_gap - g.min.x) / g.cell)) - 1;
    const int y0 = static_cast<int>(std::floor((box.min.y - g.half_gap - g.min.y) / g.cell));
    const int y1 = static_cast<int>(std::ceil((box.max.y + g.half_gap - g.min.y) / g.cell)) - 1;
    for (int y = y0; y <= y1; ++y)
      sheet.take(y, x0, x1);
  }
  return sheet;
}

// Every item rasterised at each of its rotations, with the sizes the largest-first orders sort by.
struct ItemRasters {
  std::vector<std::vector<Raster>> rasters;
  std::vector<double> area, longest, girth;
};

ItemRasters rasterize_items(std::span<const PackItem> items, const PackOptions& options, const PackGrid& g) {
  ItemRasters r;
  r.rasters.resize(items.size());
  r.area.resize(items.size());
  r.longest.resize(items.size());
  r.girth.resize(items.size());
  for (std::size_t i = 0; i < items.size(); ++i) {
    const std::vector<Polygon> grown = grow_shape(items[i].shape_mm, g.grow);
    for (double angle : candidate_angles(items[i], options))
      r.rasters[i].push_back(rasterize(grown, angle, g.cell, g.nx, g.ny));
    r.area[i] = std::fabs(total_area(items[i].shape_mm));
    Box2 box;
    for (const Polygon& p : items[i].shape_mm)
      box.add(bounds_of(p));
    r.longest[i] = std::max(box.width(), box.height());
    r.girth[i] = box.width() + box.height();
  }
  return r;
}

// Progress counts placements over every order tried: the three plain ones and the shaken ones. Orders
// run on several threads; every thread counts, and the calling thread tells (progress callbacks need
// not be thread-safe), so the reports still rise with every placement it makes.
struct PlacementCount {
  const PackOptions& options;
  long most = 0;
  std::atomic<long> done{0};
  std::thread::id teller = std::this_thread::get_id();
  void placed() {
    const long now = ++done;
    if (options.progress && std::this_thread::get_id() == teller) options.progress(now, most);
  }
};

// One greedy pass: the result, and how many rows the last sheet uses.
struct OrderRun {
  PackResult result;
  int last_rows = 0;
  std::vector<long> item_cells;  // per item: the cells it takes where placed
};

// The first open sheet with room takes the item at its best spot; a new sheet opens when none has
// room (unless max_sheets are open).
// `sheets` is scratch kept between runs: a sheet's grid is about a megabyte, and allocating it afresh for
// every sheet of every order was two thirds of the packing time (copies and page faults).
OrderRun pack_in_order(const std::vector<int>& order, const ItemRasters& shapes, const PackGrid& g,
                       const SheetGrid& blank, const PackOptions& options, PlacementCount& count,
                       std::vector<SheetGrid>& sheets) {
  OrderRun run;
  PackResult& result = run.result;
  result.placements.resize(shapes.rasters.size());
  run.item_cells.resize(shapes.rasters.size());
  int open = 0;
  int last_lowest = g.ny;
  for (std::size_t placed = 0; placed < order.size(); ++placed) {
    const int index = order[placed];
    if (options.deadline && std::chrono::steady_clock::now() > *options.deadline)
      throw LayoutError("stopped at the time limit while packing: " + std::to_string(placed) + " of " +
                        std::to_string(order.size()) + " pieces placed");
    Spot spot;
    int sheet = 0;
    for (; sheet < open; ++sheet) {
      spot = find_spot(sheets[sheet], shapes.rasters[index]);
      if (spot.raster) break;
    }
    if (!spot.raster && (!options.max_sheets || open < *options.max_sheets)) {
      spot = find_spot(blank, shapes.rasters[index]);
      if (spot.raster) {
        if (open == static_cast<int>(sheets.size())) {
          sheets.push_back(blank);
        } else {
          sheets[open].reset_to(blank);
        }
        ++open;
        last_lowest = g.ny;
      }
    }
    if (!spot.raster) {
      result.unplaced.push_back(index);
      continue;
    }
    const Raster& r = *spot.raster;
    for (int j = 0; j < r.height; ++j)
      for (auto [i0, i1] : r.runs(j))
        sheets[sheet].take(spot.y + j, spot.x + i0, spot.x + i1);
    if (sheet + 1 == open) last_lowest = std::min(last_lowest, spot.y);
    run.item_cells[index] = r.cells;
    const Vec2 corner = g.min + Vec2{g.cell * spot.x, g.cell * spot.y};
    result.placements[index] = {sheet, Rigid2{r.angle_rad, corner - r.origin}};
    count.placed();
  }
  std::sort(result.unplaced.begin(), result.unplaced.end());
  result.sheet_count = open;
  run.last_rows = g.ny - last_lowest;
  return run;
}

// The best run so far: the one that places most, on fewest sheets, leaving the last sheet emptiest (so
// the others are fullest).
struct BestRun {
  std::optional<OrderRun> best;
  void consider(OrderRun run) {
    const auto rank = [](const OrderRun& r) {
      return std::make_tuple(r.result.unplaced.size(), r.result.sheet_count, r.last_rows);
    };
    if (!best || rank(run) < rank(*best)) best = std::move(run);
  }
};

// Packs the orders in batches, one thread per order, and judges each batch in order: the best run is the
// one a single thread would find, whatever the threads. `go_on(best)` is asked before each order is
// judged; once it says no, the rest are not run. Each thread keeps its own sheet grids.
class OrderPacker {
 public:
  OrderPacker(const ItemRasters& shapes, const PackGrid& g, const SheetGrid& blank,
              const PackOptions& options, PlacementCount& count)
      : shapes_(shapes),
        g_(g),
        blank_(blank),
        options_(options),
        count_(count),
        threads_(resolve_threads(options.threads)),
        scratch_(static_cast<std::size_t>(threads_)) {}

  template <class GoOn>
  void run(const std::vector<std::vector<int>>& orders, BestRun& runs, GoOn go_on) {
    run(orders, options_, count_, runs, go_on);
  }

  // The same with other options (at most a few sheets), placements counted elsewhere and another judge.
  template <class Judge, class GoOn>
  void run(const std::vector<std::vector<int>>& orders, const PackOptions& options, PlacementCount& count,
           Judge& runs, GoOn go_on) {
    for (std::size_t first = 0; first < orders.size(); first += scratch_.size()) {
      if (runs.best && !go_on(*runs.best)) return;
      const int batch = static_cast<int>(std::min(scratch_.size(), orders.size() - first));
      std::vector<std::optional<OrderRun>> done(static_cast<std::size_t>(batch));
      run_parallel(batch, threads_, [&](int k) {
        done[k] = pack_in_order(orders[first + k], shapes_, g_, blank_, options, count, scratch_[k]);
      });
      for (std::optional<OrderRun>& r : done) {
        if (runs.best && !go_on(*runs.best)) return;
        runs.consider(std::move(*r));
      }
    }
  }

 private:
  const ItemRasters& shapes_;
  const PackGrid& g_;
  const SheetGrid& blank_;
  const PackOptions& options_;
  PlacementCount& count_;
  int threads_;
  std::vector<std::vector<SheetGrid>> scratch_;
};

// Which items each sheet of a packing holds, and the cells they take.
struct SheetLoads {
  std::vector<std::vector<int>> items;
  std::vector<long> cells;
};

SheetLoads loads_of(const OrderRun& run) {
  SheetLoads loads;
  loads.items.resize(static_cast<std::size_t>(run.result.sheet_count));
  loads.cells.resize(loads.items.size());
  for (std::size_t i = 0; i < run.result.placements.size(); ++i) {
    const int sheet = run.result.placements[i].sheet;
    if (sheet < 0) continue;
    loads.items[sheet].push_back(static_cast<int>(i));
    loads.cells[sheet] += run.item_cells[i];
  }
  return loads;
}

// `subset` by decreasing key, ties in input order.
std::vector<int> largest_first_of(std::vector<int> subset, const std::vector<double>& key) {
  std::stable_sort(subset.begin(), subset.end(), [&](int a, int b) { return key[a] > key[b]; });
  return subset;
}

// The three largest-first orders of `items`: by area, by longest side, by girth.
std::vector<std::vector<int>> plain_orders_of(const std::vector<int>& items, const ItemRasters& shapes) {
  return {largest_first_of(items, shapes.area), largest_first_of(items, shapes.longest),
          largest_first_of(items, shapes.girth)};
}

// `count` largest-first orders of `items`, each area scaled by a pseudo-random factor within [1/2, 2].
std::vector<std::vector<int>> shaken_orders_of(const std::vector<int>& items, const ItemRasters& shapes,
                                               int count, std::uint64_t& seed) {
  std::vector<std::vector<int>> orders;
  std::vector<double> key = shapes.area;
  for (int k = 0; k < count; ++k) {
    for (int i : items)
      key[i] = shapes.area[i] * std::exp2(2 * unit_random(seed) - 1);
    orders.push_back(largest_first_of(items, key));
  }
  return orders;
}

// The cells the items on a run's last sheet take (0 without sheets).
long last_sheet_cells(const OrderRun& run) {
  long cells = 0;
  for (std::size_t i = 0; i < run.result.placements.size(); ++i)
    if (run.result.placements[i].sheet == run.result.sheet_count - 1) cells += run.item_cells[i];
  return cells;
}

// Judges the repackings of a target sheet's items with its partners' onto the partners and one sheet
// more: all placed, on fewest sheets, with least on the last one (the target's).
struct EmptiestLast {
  std::optional<OrderRun> best;
  static auto rank(const OrderRun& r) {
    return std::make_tuple(r.result.unplaced.size(), r.result.sheet_count, last_sheet_cells(r));
  }
  void consider(OrderRun run) {
    if (!best || rank(run) < rank(*best)) best = std::move(run);
  }
};

// The sets of sheets a target's items are packed with: each other sheet, then each pair of them,
// emptiest first (they have the most room to take).
std::vector<std::vector<int>> partner_sets(const SheetLoads& loads, int target) {
  constexpr std::size_t kMostPairs = 21;
  std::vector<int> others;
  for (int s = 0; s < static_cast<int>(loads.cells.size()); ++s)
    if (s != target) others.push_back(s);
  std::stable_sort(others.begin(), others.end(),
                   [&](int a, int b) { return loads.cells[a] < loads.cells[b]; });
  std::vector<std::vector<int>> sets;
  for (int s : others)
    sets.push_back({s});
  std::vector<std::vector<int>> pairs;
  for (std::size_t a = 0; a < others.size(); ++a)
    for (std::size_t b = a + 1; b < others.size(); ++b)
      pairs.push_back({others[a], others[b]});
  std::stable_sort(pairs.begin(), pairs.end(), [&](const std::vector<int>& x, const std::vector<int>& y) {
    return loads.cells[x[0]] + loads.cells[x[1]] < loads.cells[y[0]] + loads.cells[y[1]];
  });
  if (pairs.size() > kMostPairs) pairs.resize(kMostPairs);
  sets.insert(sets.end(), pairs.begin(), pairs.end());
  return sets;
}

// Takes a repacking of `target` and `partners` (its sheet j is partners[j], its sheet past them the
// target's) into `best`; a target left empty is removed and the sheets after it move down.
void take_repacking(OrderRun& best, const OrderRun& repacked, const std::vector<int>& partners, int target) {
  std::vector<int> sheet_of = partners;
  sheet_of.push_back(target);
  for (std::size_t i = 0; i < repacked.result.placements.size(); ++i) {
    const PackPlacement& p = repacked.result.placements[i];
    if (p.sheet < 0) continue;
    best.result.placements[i] = {sheet_of[static_cast<std::size_t>(p.sheet)], p.transform};
    best.item_cells[i] = repacked.item_cells[i];
  }
  if (repacked.result.sheet_count > static_cast<int>(partners.size())) return;
  for (PackPlacement& p : best.result.placements)
    if (p.sheet > target) --p.sheet;
  --best.result.sheet_count;
}

// Sheets numbered fullest first, so that the emptiest is the last.
void fullest_first(OrderRun& run) {
  const SheetLoads loads = loads_of(run);
  std::vector<int> by_cells(loads.cells.size());
  std::iota(by_cells.begin(), by_cells.end(), 0);
  std::stable_sort(by_cells.begin(), by_cells.end(),
                   [&](int a, int b) { return loads.cells[a] > loads.cells[b]; });
  std::vector<int> number(by_cells.size());
  for (std::size_t k = 0; k < by_cells.size(); ++k)
    number[static_cast<std::size_t>(by_cells[k])] = static_cast<int>(k);
  for (PackPlacement& p : run.result.placements)
    if (p.sheet >= 0) p.sheet = number[static_cast<std::size_t>(p.sheet)];
}

// Parts placed one by one leave each sheet with gaps that no later part fits, though the parts of two
// or three sheets packed together again often leave one of them emptier. The emptiest sheet's parts are
// packed with those of one other sheet, then of two, onto those sheets and one more; a repacking that
// leaves less on the last of them is taken, and one that leaves nothing saves the sheet. It ends when no
// repacking helps, at `fewest` sheets, or when `most_orders` orders are spent.
void empty_sheets(OrderRun& best, const ItemRasters& shapes, OrderPacker& packer, const PackOptions& options,
                  long fewest, int most_orders) {
  constexpr int kShakenPerSet = 5;
  std::uint64_t seed = kShakeSeed;
  PackOptions few = options;
  few.progress = nullptr;
  few.deadline.reset();           // the packing is complete: past the deadline the search stops, keeping it
  PlacementCount uncounted{few};  // the progress tells of the orders; this search comes on top
  while (best.result.sheet_count > fewest && most_orders > 0) {
    const SheetLoads loads = loads_of(best);
    const int target =
        static_cast<int>(std::min_element(loads.cells.begin(), loads.cells.end()) - loads.cells.begin());
    bool took = false;
    for (const std::vector<int>& partners : partner_sets(loads, target)) {
      if (most_orders <= 0 || (options.deadline && std::chrono::steady_clock::now() > *options.deadline))
        break;
      std::vector<int> items = loads.items[static_cast<std::size_t>(target)];
      for (int s : partners)
        items.insert(items.end(), loads.items[static_cast<std::size_t>(s)].begin(),
                     loads.items[static_cast<std::size_t>(s)].end());
      std::vector<std::vector<int>> orders = plain_orders_of(items, shapes);
      for (std::vector<int>& shaken : shaken_orders_of(items, shapes, kShakenPerSet, seed))
        orders.push_back(std::move(shaken));
      most_orders -= static_cast<int>(orders.size());
      few.max_sheets = static_cast<int>(partners.size()) + 1;
      EmptiestLast runs;
      const long before = loads.cells[static_cast<std::size_t>(target)];
      packer.run(orders, few, uncounted, runs, [&](const OrderRun& r) {
        return !(r.result.unplaced.empty() && r.result.sheet_count <= static_cast<int>(partners.size()));
      });
      const OrderRun& r = *runs.best;
      if (!r.result.unplaced.empty()) continue;
      const bool saved = r.result.sheet_count <= static_cast<int>(partners.size());
      if (!saved && last_sheet_cells(r) >= before) continue;
      take_repacking(best, r, partners, target);
      took = true;
      break;
    }
    if (!took) break;
  }
  fullest_first(best);
}
}  // namespace

PackResult pack_items(std::span<const PackItem> items, const PackOptions& options) {
  if (options.engine == PackEngine::Nest2d) return pack_items_nest2d(items, options);
  const PackGrid g = pack_grid(options);
  const SheetGrid blank = blank_sheet(g, options.keep_out_mm);
  const ItemRasters shapes = rasterize_items(items, options, g);
  const int shaken = shaken_orders(items.size(), options.shaken_orders);
  PlacementCount count{options, static_cast<long>(3 + shaken) * static_cast<long>(items.size())};

  // Greedy packing depends on the order: a few largest-first orders, keeping the best.
  std::vector<int> all(items.size());
  std::iota(all.begin(), all.end(), 0);
  BestRun runs;
  OrderPacker packer(shapes, g, blank, options, count);
  packer.run(plain_orders_of(all, shapes), runs, [](const OrderRun&) { return true; });

  // When that leaves more sheets than the items' cells could fill, shaken largest-first orders often
  // save the last one. A fixed count and seed: the same input always packs the same way.
  const long bound = sheets_at_fill(shapes.rasters, blank.free_cells(), kReachableFill);
  std::uint64_t seed = kShakeSeed;
  packer.run(shaken_orders_of(all, shapes, shaken, seed), runs, [&](const OrderRun& best) {
    return best.result.unplaced.empty() && best.result.sheet_count > bound;
  });
  OrderRun& best = *runs.best;
  // Many items leave many gaps to fill and cost each order more: over `bench --layout` every sheet the
  // search saved was on a packing of at most kMostItemsSearched items.
  constexpr std::size_t kMostItemsSearched = 24;
  if (best.result.unplaced.empty() && options.sheet_search_orders > 0 && items.size() <= kMostItemsSearched)
    empty_sheets(best, shapes, packer, options, bound, options.sheet_search_orders);
  if (options.progress) options.progress(count.most, count.most);
  return std::move(runs.best->result);
}

}  // namespace foldkit::layout
