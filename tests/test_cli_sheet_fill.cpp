// The layout benchmark's yardstick: the fill of every sheet that a count of sheets or a median
// coverage corresponds to.
#include "sheet_fill.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using foldkit::cli::FilledRun;

TEST(SheetFill, ARunTakesItsAreaOverTheFillRoundedUpAndNeverFewerThanItsBound) {
  const std::vector<FilledRun> runs{{1.5, 2}};
  EXPECT_EQ(foldkit::cli::sheets_at_fill(runs, 0.75), 2);
  EXPECT_EQ(foldkit::cli::sheets_at_fill(runs, 0.74), 3);
  EXPECT_EQ(foldkit::cli::sheets_at_fill(runs, 0.5), 3);
  EXPECT_EQ(foldkit::cli::sheets_at_fill(runs, 0.49), 4);
  const std::vector<FilledRun> bound_by_shapes{{0.4, 3}};
  EXPECT_EQ(foldkit::cli::sheets_at_fill(bound_by_shapes, 1.0), 3) << "the bound holds whatever the fill";
}

TEST(SheetFill, TheFillForACountOfSheetsIsTheLeastThatReachesIt) {
  // 1.5 sheets' area on 2 sheets needs 75%; 0.6 on 1 needs 60%.
  const std::vector<FilledRun> runs{{1.5, 2}, {0.6, 1}};
  EXPECT_EQ(foldkit::cli::sheets_at_fill(runs, 0.5), 3 + 2);
  EXPECT_NEAR(foldkit::cli::fill_for_sheets(runs, 4), 0.60, 1e-9);
  EXPECT_NEAR(foldkit::cli::fill_for_sheets(runs, 3), 0.75, 1e-9);
  EXPECT_NEAR(foldkit::cli::fill_for_sheets(runs, 2), 1.0, 1e-9) << "no fill goes below the bounds";
}

TEST(SheetFill, AMedianCoverageIsReachedWhenTheRunsAroundTheMiddleSaveTheirSheets) {
  // Full sheets: coverage 0.5, 0.7 and 1.6 / 2 = 0.8, median 0.7. Below 80% the third run takes a
  // third sheet (0.53), and the median falls to it.
  const std::vector<FilledRun> runs{{0.5, 1}, {0.7, 1}, {1.6, 2}};
  EXPECT_NEAR(foldkit::cli::median_coverage_at_fill(runs, 1.0), 0.7, 1e-9);
  EXPECT_NEAR(foldkit::cli::median_coverage_at_fill(runs, 0.79), 1.6 / 3, 1e-9);
  EXPECT_NEAR(foldkit::cli::fill_for_median_coverage(runs, 0.7), 0.8, 1e-9);
  // 0.5 as the median: the third run on three sheets, 1.6 / 3 = 53.3% rounded up to the step.
  EXPECT_NEAR(foldkit::cli::fill_for_median_coverage(runs, 0.5), 0.535, 1e-9);
}

TEST(SheetFill, NoRunsHaveNoMedian) {
  EXPECT_TRUE(std::isnan(foldkit::cli::median_coverage_at_fill({}, 0.7)));
}
