#pragma once
// A spatial index of flat triangles for incremental overlap tests: a hashed uniform grid keyed by
// (piece, cell), so a query only meets triangles of the same piece, and a triangle can be removed and
// re-inserted in time proportional to the cells it covers. This is the hot path of every unfolder
// that moves one part of a piece at a time (search moves, GA stitches, rearrangement).
#include <cstdint>
#include <vector>

#include "foldkit/geom/predicates.hpp"
#include "foldkit/geom/vec.hpp"

namespace foldkit::unfold {

/// Face ids 0..num_faces-1, each either absent or present with one triangle and one piece id.
class OverlapIndex {
 public:
  /// `cell_size` (model units) should be about the size of a typical triangle; `eps` is the overlap
  /// depth (a length) below which touching triangles do not count as overlapping (see triangles_overlap).
  OverlapIndex(int num_faces, double cell_size, double eps);

  /// Adds face f (not present) with triangle t in piece p.
  void insert(int f, int piece, const Triangle2& t);
  /// Removes face f (present).
  void remove(int f);
  bool contains(int f) const { return present_[f] != 0; }
  int piece_of(int f) const { return piece_[f]; }
  const Triangle2& triangle(int f) const { return tri_[f]; }

  /// Calls visit(g) once for every present face g of `piece` whose triangle overlaps t (interiors,
  /// deeper than eps) and for which skip(g) is false. visit returns false to stop early.
  /// Not thread-safe: uses internal scratch marks (one index per thread).
  template <class Skip, class Visit>
  void query(const Triangle2& t, int piece, Skip&& skip, Visit&& visit);

  double eps() const { return eps_; }

 private:
  struct Range {
    std::int64_t x0 = 0, y0 = 0, x1 = -1, y1 = -1;
  };
  Range cells_of(const Box2& b) const;
  std::size_t bucket_of(int piece, std::int64_t cx, std::int64_t cy) const;
  std::uint32_t next_stamp();

  double inv_cell_;
  double eps_;
  std::size_t mask_;
  std::vector<std::vector<int>> buckets_;
  /// Triangles spanning more than kMaxSpan cells per axis: kept out of the grid, scanned by every query.
  std::vector<int> large_;
  static constexpr std::int64_t kMaxSpan = 16;
  std::vector<Triangle2> tri_;
  std::vector<Box2> box_;
  std::vector<Range> range_;
  std::vector<int> piece_;
  std::vector<char> present_;
  std::vector<std::uint32_t> stamp_;
  std::uint32_t stamp_counter_ = 0;
};

template <class Skip, class Visit>
void OverlapIndex::query(const Triangle2& t, int piece, Skip&& skip, Visit&& visit) {
  const Box2 b = bounds(t);
  const Range r = cells_of(b);
  const std::uint32_t s = next_stamp();
  auto consider = [&](int g) {
    // Buckets are hashed: other pieces and cells share them, and a face spans several cells.
    if (stamp_[g] == s) return true;
    stamp_[g] = s;
    if (piece_[g] != piece || !box_[g].overlaps(b) || skip(g)) return true;
    if (!triangles_overlap(t, tri_[g], eps_)) return true;
    return static_cast<bool>(visit(g));
  };
  for (int g : large_)
    if (!consider(g)) return;
  if (r.x1 - r.x0 > kMaxSpan || r.y1 - r.y0 > kMaxSpan) {
    // A large query triangle: scanning every face of the grid is cheaper than its cells.
    for (const auto& bucket : buckets_)
      for (int g : bucket)
        if (!consider(g)) return;
    return;
  }
  for (std::int64_t cy = r.y0; cy <= r.y1; ++cy) {
    for (std::int64_t cx = r.x0; cx <= r.x1; ++cx) {
      for (int g : buckets_[bucket_of(piece, cx, cy)])
        if (!consider(g)) return;
    }
  }
}

/// A cell size for `OverlapIndex` suited to the given triangles (their mean bounding-box extent).
double suggested_cell_size(const std::vector<Triangle2>& triangles);

}  // namespace foldkit::unfold
