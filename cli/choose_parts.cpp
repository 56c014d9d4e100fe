#include "choose_parts.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <utility>

#include "foldkit/unfold/parts.hpp"

namespace foldkit::cli {
namespace {

long sheets_with_pieces(const layout::LayoutResult& r) {
  return std::count_if(r.sheet_stats.begin(), r.sheet_stats.end(),
                       [](const layout::SheetStats& s) { return s.pieces > 0; });
}

struct Candidate {
  unfold::PartsResult parts;
  layout::LayoutResult layout;
  long sheets = 0;
  double used_mm2 = 0;
};

}  // namespace

ChosenParts choose_parts(const unfold::Mesh& mesh, const unfold::Unfolding& u,
                         const layout::LayoutOptions& o) {
  if (!o.size_mm || o.fit || !o.split_oversized || !(u.model_extent > 0)) return {u, 0, 0, std::nullopt};
  unfold::PartOptions po;
  po.room_mm = layout::piece_room_mm(o);
  po.mm_per_unit = *o.size_mm / u.model_extent;

  auto evaluate = [&](double fraction, unfold::PartGrowth growth) {
    po.room_fraction = fraction;
    po.growth = growth;
    // Judged by a full layout: a crowded label can stick out of a small face and take room.
    Candidate c{unfold::split_into_parts(mesh, u, po), {}, 0, 0};
    c.layout = layout::layout_sheets(c.parts.unfolding, o);
    c.sheets = sheets_with_pieces(c.layout);
    c.used_mm2 = c.layout.overall.piece_area_mm2 + c.layout.overall.tab_area_mm2;
    return c;
  };
  using Clock = std::chrono::steady_clock;
  const auto first_start = Clock::now();
  Candidate best = evaluate(1.0, unfold::PartGrowth::Tree);
  const auto trial_time = Clock::now() - first_start;
  if (best.parts.split_pieces == 0) return {std::move(best.parts.unfolding), 0, 0, std::move(best.layout)};

  // Parts as large as the sheet allows give the fewest seams but, cut from a spindly net, pack
  // poorly; smaller, rounder parts often save a sheet. Packing is a heuristic, so each split is judged
  // by packing it: fewer sheets first, then fewer parts.
  auto better = [](const Candidate& a, const Candidate& b) {
    return std::make_pair(a.sheets, a.parts.unfolding.piece_count) <
           std::make_pair(b.sheets, b.parts.unfolding.piece_count);
  };
  // No partition needs fewer sheets than its area: reaching that bound ends the trials.
  const Box2 area = layout::printable_area(o);
  const long bound =
      std::max(1L, static_cast<long>(std::ceil(best.used_mm2 / (area.width() * area.height()) - 1e-9)));
  const std::pair<double, unfold::PartGrowth> tries[] = {
      {1.0, unfold::PartGrowth::Round}, {0.7, unfold::PartGrowth::Tree},  {0.5, unfold::PartGrowth::Tree},
      {0.85, unfold::PartGrowth::Tree}, {0.7, unfold::PartGrowth::Round}, {0.5, unfold::PartGrowth::Round},
      {0.35, unfold::PartGrowth::Tree}};
  // Large meshes try the first three only, so their layout stays fast; a count, not a clock, so the
  // same input always gives the same parts.
  constexpr int kManyFaces = 1500;
  const std::size_t trials = mesh.num_faces() > kManyFaces ? 3 : std::size(tries);
  for (std::size_t t = 0; t < trials; ++t) {
    const auto [fraction, growth] = tries[t];
    if (best.sheets <= bound) break;
    // Under a time limit, another trial must leave room for the final layout (with labels, dearer).
    if (o.deadline && Clock::now() + 3 * trial_time > *o.deadline) break;
    Candidate c = evaluate(fraction, growth);
    if (better(c, best)) best = std::move(c);
  }
  return {std::move(best.parts.unfolding), best.parts.split_pieces, best.parts.new_pieces,
          std::move(best.layout)};
}

}  // namespace foldkit::cli
