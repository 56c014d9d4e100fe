#pragma once
// The median the benchmarks report: of an even count, the mean of the two middle values; NaN of none.
#include <vector>

namespace foldkit::cli {

double median(std::vector<double> values);

}  // namespace foldkit::cli
