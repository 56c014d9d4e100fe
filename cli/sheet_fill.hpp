#pragma once
// A yardstick for the layout benchmark: how full every sheet would have to be for its totals. A run
// whose parts and tabs take `used_sheets` printable areas needs ceil(used_sheets / fill) sheets when a
// packing fills every sheet (its last one aside) to `fill`, and never fewer than its bound. Over a set
// of runs this says which fill the sheets counted correspond to, and which fill a target on the total
// sheets or on the median coverage asks for: targets become comparable with the fullest sheets any
// layout reaches.
#include <span>

namespace foldkit::cli {

/// One layout run as the yardstick sees it.
struct FilledRun {
  double used_sheets = 0;  ///< area of parts and tabs over one printable area
  long bound = 1;          ///< the sheets no packing can go below (the area bound)
};

/// Fills are searched in steps of this size.
inline constexpr double kFillStep = 0.005;

/// The sheets the runs take when every sheet is filled to `fill` (0..1] of its printable area.
long sheets_at_fill(std::span<const FilledRun> runs, double fill);

/// The median over the runs of used area over the sheets taken, every sheet filled to `fill`.
double median_coverage_at_fill(std::span<const FilledRun> runs, double fill);

/// The least fill (a multiple of kFillStep, at most 1) at which the runs take at most `sheets`; 1 when
/// even full sheets take more.
double fill_for_sheets(std::span<const FilledRun> runs, long sheets);

/// The least fill (a multiple of kFillStep, at most 1) at which the median coverage reaches `coverage`.
double fill_for_median_coverage(std::span<const FilledRun> runs, double coverage);

}  // namespace foldkit::cli
