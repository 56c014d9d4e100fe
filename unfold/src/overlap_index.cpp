// Hashed uniform grid: cell (piece, cx, cy) -> bucket of face ids. Buckets are shared by hash
// collisions, which queries filter by piece and bounding box; that keeps memory linear in the number
// of faces however far pieces drift apart in the plane.
#include "foldkit/unfold/overlap_index.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

namespace foldkit::unfold {

OverlapIndex::OverlapIndex(int num_faces, double cell_size, double eps)
    : inv_cell_(cell_size > 0 ? 1.0 / cell_size : 1.0),
      eps_(eps),
      tri_(num_faces),
      box_(num_faces),
      range_(num_faces),
      piece_(num_faces, -1),
      present_(num_faces, 0),
      stamp_(num_faces, 0) {
  // About four buckets per face keeps buckets short for triangles covering one to four cells.
  std::size_t n = std::bit_ceil(static_cast<std::size_t>(std::max(16, 4 * num_faces)));
  buckets_.resize(n);
  mask_ = n - 1;
}

OverlapIndex::Range OverlapIndex::cells_of(const Box2& b) const {
  // Clamped so that absurd coordinates cannot make a triangle cover billions of cells.
  auto cell = [this](double v) {
    return static_cast<std::int64_t>(std::floor(std::clamp(v * inv_cell_, -1e15, 1e15)));
  };
  return Range{cell(b.min.x), cell(b.min.y), cell(b.max.x), cell(b.max.y)};
}

std::size_t OverlapIndex::bucket_of(int piece, std::int64_t cx, std::int64_t cy) const {
  std::uint64_t h = static_cast<std::uint64_t>(cx) * 0x9E3779B97F4A7C15ull;
  h ^= static_cast<std::uint64_t>(cy) * 0xC2B2AE3D27D4EB4Full + (h << 6) + (h >> 2);
  h ^= static_cast<std::uint64_t>(piece) * 0x165667B19E3779F9ull;
  h ^= h >> 29;
  return static_cast<std::size_t>(h) & mask_;
}

std::uint32_t OverlapIndex::next_stamp() {
  if (++stamp_counter_ == 0) {
    std::fill(stamp_.begin(), stamp_.end(), 0);
    stamp_counter_ = 1;
  }
  return stamp_counter_;
}

void OverlapIndex::insert(int f, int piece, const Triangle2& t) {
  tri_[f] = t;
  box_[f] = bounds(t);
  piece_[f] = piece;
  present_[f] = 1;
  Range r = cells_of(box_[f]);
  if (r.x1 - r.x0 > kMaxSpan || r.y1 - r.y0 > kMaxSpan) {
    range_[f] = Range{};
    large_.push_back(f);
    return;
  }
  range_[f] = r;
  for (std::int64_t cy = r.y0; cy <= r.y1; ++cy)
    for (std::int64_t cx = r.x0; cx <= r.x1; ++cx)
      buckets_[bucket_of(piece, cx, cy)].push_back(f);
}

void OverlapIndex::remove(int f) {
  present_[f] = 0;
  const Range r = range_[f];
  if (r.x1 < r.x0) {
    auto it = std::find(large_.begin(), large_.end(), f);
    if (it != large_.end()) {
      *it = large_.back();
      large_.pop_back();
    }
    return;
  }
  for (std::int64_t cy = r.y0; cy <= r.y1; ++cy) {
    for (std::int64_t cx = r.x0; cx <= r.x1; ++cx) {
      auto& b = buckets_[bucket_of(piece_[f], cx, cy)];
      auto it = std::find(b.begin(), b.end(), f);
      if (it != b.end()) {
        *it = b.back();
        b.pop_back();
      }
    }
  }
}

double suggested_cell_size(const std::vector<Triangle2>& triangles) {
  double sum = 0;
  int n = 0;
  for (const auto& t : triangles) {
    Box2 b = bounds(t);
    if (b.empty()) continue;
    sum += std::max(b.width(), b.height());
    ++n;
  }
  return n > 0 && sum > 0 ? sum / n : 1.0;
}

}  // namespace foldkit::unfold
