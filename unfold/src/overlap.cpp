#include "foldkit/unfold/overlap.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace foldkit::unfold {

double overlap_tolerance(const std::vector<Triangle2>& flat) {
  if (flat.empty()) return 0;
  double sum = 0;
  for (const auto& t : flat)
    for (int i = 0; i < 3; ++i)
      sum += norm(t[(i + 1) % 3] - t[i]);
  return 1e-6 * sum / (3.0 * static_cast<double>(flat.size()));
}

std::vector<FacePair> overlapping_pairs(const std::vector<Triangle2>& flat,
                                        const std::vector<int>& piece_of_face) {
  return overlapping_pairs(flat, piece_of_face, overlap_tolerance(flat));
}

std::vector<FacePair> overlapping_pairs(const std::vector<Triangle2>& flat,
                                        const std::vector<int>& piece_of_face, double eps_length) {
  const int n = static_cast<int>(flat.size());
  std::vector<FacePair> result;
  if (n < 2) return result;

  std::vector<Box2> boxes(n);
  Box2 all = bounds(flat[0]);
  double size_sum = 0;
  for (int f = 0; f < n; ++f) {
    boxes[f] = bounds(flat[f]);
    all.add(boxes[f]);
    size_sum += std::max(boxes[f].max.x - boxes[f].min.x, boxes[f].max.y - boxes[f].min.y);
  }
  // Cells about twice the mean triangle size: each triangle touches a few cells, each cell holds a few.
  double cell = std::max(2.0 * size_sum / n, 1e-300);
  const double span_x = all.max.x - all.min.x, span_y = all.max.y - all.min.y;
  // Bound the grid so a few huge slivers cannot make it quadratic in memory.
  const double max_cells = 4.0 * n + 16;
  while ((span_x / cell + 1) * (span_y / cell + 1) > max_cells)
    cell *= 1.5;
  const int nx = static_cast<int>(span_x / cell) + 1, ny = static_cast<int>(span_y / cell) + 1;
  auto cell_x = [&](double x) { return std::clamp(static_cast<int>((x - all.min.x) / cell), 0, nx - 1); };
  auto cell_y = [&](double y) { return std::clamp(static_cast<int>((y - all.min.y) / cell), 0, ny - 1); };

  // Counting sort of (cell, face) entries: two passes, no per-cell vectors.
  std::vector<int> start(static_cast<std::size_t>(nx) * ny + 1, 0);
  for (int f = 0; f < n; ++f)
    for (int y = cell_y(boxes[f].min.y); y <= cell_y(boxes[f].max.y); ++y)
      for (int x = cell_x(boxes[f].min.x); x <= cell_x(boxes[f].max.x); ++x)
        ++start[std::size_t(y) * nx + x + 1];
  for (std::size_t c = 1; c < start.size(); ++c)
    start[c] += start[c - 1];
  std::vector<int> entries(start.back());
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (int f = 0; f < n; ++f)
    for (int y = cell_y(boxes[f].min.y); y <= cell_y(boxes[f].max.y); ++y)
      for (int x = cell_x(boxes[f].min.x); x <= cell_x(boxes[f].max.x); ++x)
        entries[fill[std::size_t(y) * nx + x]++] = f;

  for (int cy = 0; cy < ny; ++cy)
    for (int cx = 0; cx < nx; ++cx) {
      const std::size_t c = std::size_t(cy) * nx + cx;
      for (int i = start[c]; i < start[c + 1]; ++i)
        for (int j = i + 1; j < start[c + 1]; ++j) {
          int a = entries[i], b = entries[j];
          if (piece_of_face[a] != piece_of_face[b]) continue;
          const Box2& ba = boxes[a];
          const Box2& bb = boxes[b];
          double lo_x = std::max(ba.min.x, bb.min.x), lo_y = std::max(ba.min.y, bb.min.y);
          if (lo_x > std::min(ba.max.x, bb.max.x) || lo_y > std::min(ba.max.y, bb.max.y)) continue;
          // Test each pair once: in the cell holding the low corner of the boxes' intersection.
          if (cell_x(lo_x) != cx || cell_y(lo_y) != cy) continue;
          if (triangles_overlap(flat[a], flat[b], eps_length))
            result.push_back({std::min(a, b), std::max(a, b)});
        }
    }
  std::sort(result.begin(), result.end(),
            [](const FacePair& p, const FacePair& q) { return p.a != q.a ? p.a < q.a : p.b < q.b; });
  return result;
}

}  // namespace foldkit::unfold
