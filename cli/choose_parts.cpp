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

// A candidate is judged by its sheets and parts only, so labels (the costliest part of a layout, and
// inside the pieces, so they change no placement) are left out of the trial.
layout::LayoutOptions trial_options(layout::LayoutOptions o) {
  o.numbers = false;
  o.arrows = false;
  return o;
}

struct Candidate {
  unfold::PartsResult parts;
  long sheets = 0;
  double used_mm2 = 0;
};

}  // namespace

ChosenParts choose_parts(const unfold::Mesh& mesh, const unfold::Unfolding& u,
                         const layout::LayoutOptions& o) {
  if (!o.size_mm || o.fit || !o.split_oversized || !(u.model_extent > 0)) return {u, 0, 0};
  unfold::PartOptions po;
  po.room_mm = layout::piece_room_mm(o);
  po.mm_per_unit = *o.size_mm / u.model_extent;
  const layout::LayoutOptions trial = trial_options(o);

  auto evaluate = [&](double fraction, unfold::PartGrowth growth) {
    po.room_fraction = fraction;
    po.growth = growth;
    Candidate c{unfold::split_into_parts(mesh, u, po), 0, 0};
    const layout::LayoutResult r = layout::layout_sheets(c.parts.unfolding, trial);
    c.sheets = sheets_with_pieces(r);
    c.used_mm2 = r.overall.piece_area_mm2 + r.overall.tab_area_mm2;
    return c;
  };
  using Clock = std::chrono::steady_clock;
  const auto first_start = Clock::now();
  Candidate best = evaluate(1.0, unfold::PartGrowth::Tree);
  const auto trial_time = Clock::now() - first_start;
  if (best.parts.split_pieces == 0) return {std::move(best.parts.unfolding), 0, 0};

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
      {1.0, unfold::PartGrowth::Round}, {0.85, unfold::PartGrowth::Tree}, {0.7, unfold::PartGrowth::Tree},
      {0.7, unfold::PartGrowth::Round}, {0.5, unfold::PartGrowth::Tree},  {0.5, unfold::PartGrowth::Round},
      {0.35, unfold::PartGrowth::Tree}};
  // The trials together cost at most this many first trials, so a large mesh stays fast.
  constexpr int kTrialBudget = 6;
  for (auto [fraction, growth] : tries) {
    if (best.sheets <= bound) break;
    if (Clock::now() - first_start > kTrialBudget * trial_time) break;
    // Under a time limit, another trial must leave room for the final layout (with labels, dearer).
    if (o.deadline && Clock::now() + 3 * trial_time > *o.deadline) break;
    Candidate c = evaluate(fraction, growth);
    if (better(c, best)) best = std::move(c);
  }
  return {std::move(best.parts.unfolding), best.parts.split_pieces, best.parts.new_pieces};
}

}  // namespace foldkit::cli
