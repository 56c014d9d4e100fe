#include "foldkit/layout/hints.hpp"

#include <cmath>

namespace foldkit::layout {

std::vector<std::vector<int>> seam_loops(std::span<const ScaledPiece> pieces, std::span<const Seam> seams) {
  std::vector<std::vector<int>> loops;
  for (const ScaledPiece& piece : pieces)
    for (const OutlineLoop& loop : piece.outline_mm)
      loops.emplace_back(loop.size(), -1);
  std::vector<std::size_t> first_loop(pieces.size() + 1, 0);
  for (std::size_t p = 0; p < pieces.size(); ++p)
    first_loop[p + 1] = first_loop[p] + pieces[p].outline_mm.size();
  for (std::size_t s = 0; s < seams.size(); ++s)
    for (const SeamSide& side : seams[s].sides)
      if (side.piece >= 0) loops[first_loop[side.piece] + side.loop][side.index] = static_cast<int>(s);
  return loops;
}

std::vector<int> assembly_order(std::vector<std::vector<int>> loops, std::span<const Seam> seams) {
  std::vector<int> order;
  std::vector<char> done(seams.size(), 0);
  auto sharper = [&](int a, int b) {
    const double fa = std::fabs(seams[a].fold_angle_rad), fb = std::fabs(seams[b].fold_angle_rad);
    return fa > fb + 1e-12 || (fa >= fb - 1e-12 && a < b);
  };
  for (;;) {
    // Type I first: a seam whose two sides follow each other on a loop.
    int best = -1, best_loop = -1;
    std::size_t best_at = 0;
    for (std::size_t l = 0; l < loops.size(); ++l) {
      const auto& loop = loops[l];
      const std::size_t n = loop.size();
      if (n < 2) continue;
      for (std::size_t i = 0; i < n; ++i) {
        const int s = loop[i];
        if (s >= 0 && loop[(i + 1) % n] == s && (best < 0 || sharper(s, best))) {
          best = s;
          best_loop = static_cast<int>(l);
          best_at = i;
        }
      }
    }
    if (best >= 0) {
      auto& loop = loops[best_loop];
      const std::size_t n = loop.size(), next = (best_at + 1) % n;
      // Erase the later position first so the earlier one stays valid.
      loop.erase(loop.begin() + static_cast<long>(std::max(best_at, next)));
      loop.erase(loop.begin() + static_cast<long>(std::min(best_at, next)));
      done[best] = 1;
      order.push_back(best);
      continue;
    }
    // Otherwise the sharpest seam left: type II within a loop (splits it) or joining two loops.
    for (std::size_t s = 0; s < seams.size(); ++s)
      if (!done[s] && (best < 0 || sharper(static_cast<int>(s), best))) best = static_cast<int>(s);
    if (best < 0) break;
    int loop1 = -1, loop2 = -1;
    std::size_t at1 = 0, at2 = 0;
    for (std::size_t l = 0; l < loops.size(); ++l)
      for (std::size_t i = 0; i < loops[l].size(); ++i)
        if (loops[l][i] == best) {
          if (loop1 < 0) {
            loop1 = static_cast<int>(l);
            at1 = i;
          } else {
            loop2 = static_cast<int>(l);
            at2 = i;
          }
        }
    done[best] = 1;
    order.push_back(best);
    if (loop1 < 0 || loop2 < 0) continue;  // a seam missing from the loops: nothing to simulate
    auto cyclic_after = [](const std::vector<int>& loop, std::size_t at, std::size_t count) {
      std::vector<int> out;
      for (std::size_t k = 1; k <= count; ++k)
        out.push_back(loop[(at + k) % loop.size()]);
      return out;
    };
    if (loop1 == loop2) {
      // x A y B  ->  A and B
      auto& loop = loops[loop1];
      const std::size_t n = loop.size();
      std::vector<int> a = cyclic_after(loop, at1, at2 - at1 - 1);
      std::vector<int> b = cyclic_after(loop, at2, n - (at2 - at1) - 1);
      loop = std::move(a);
      loops.push_back(std::move(b));
    } else {
      // x A and y B  ->  A B
      std::vector<int> merged = cyclic_after(loops[loop1], at1, loops[loop1].size() - 1);
      std::vector<int> b = cyclic_after(loops[loop2], at2, loops[loop2].size() - 1);
      merged.insert(merged.end(), b.begin(), b.end());
      loops[loop1] = std::move(merged);
      loops[loop2].clear();
    }
  }
  return order;
}

}  // namespace foldkit::layout
