#include "sheet_fill.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <utility>
#include <vector>

#include "median.hpp"

namespace foldkit::cli {
namespace {

// Areas are sums of face areas in floating point: a run that fills exactly two sheets at a fill must
// not round up to three.
constexpr double kAreaSlack = 1e-9;

long sheets_of(const FilledRun& run, double fill) {
  return std::max(run.bound, static_cast<long>(std::ceil(run.used_sheets / fill - kAreaSlack)));
}

// The least multiple of kFillStep in (0, 1] for which `enough` holds; 1 if none does.
double least_fill(const std::function<bool(double)>& enough) {
  const int steps = static_cast<int>(std::lround(1 / kFillStep));
  for (int k = 1; k <= steps; ++k)
    if (enough(k * kFillStep)) return k * kFillStep;
  return 1;
}

}  // namespace

long sheets_at_fill(std::span<const FilledRun> runs, double fill) {
  long sheets = 0;
  for (const FilledRun& run : runs)
    sheets += sheets_of(run, fill);
  return sheets;
}

double median_coverage_at_fill(std::span<const FilledRun> runs, double fill) {
  std::vector<double> coverage;
  coverage.reserve(runs.size());
  for (const FilledRun& run : runs)
    coverage.push_back(run.used_sheets / static_cast<double>(sheets_of(run, fill)));
  return median(std::move(coverage));
}

double fill_for_sheets(std::span<const FilledRun> runs, long sheets) {
  return least_fill([&](double fill) { return sheets_at_fill(runs, fill) <= sheets; });
}

double fill_for_median_coverage(std::span<const FilledRun> runs, double coverage) {
  return least_fill([&](double fill) { return median_coverage_at_fill(runs, fill) >= coverage; });
}

}  // namespace foldkit::cli
