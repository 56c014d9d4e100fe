// The print-and-cut calibration page: marks where the planner finds them, a printed (never cut) cross
// at each known place, and short cuts centred on every cross.
#include "foldkit/layout/calibration_page.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "foldkit/error.hpp"

using namespace foldkit;
using foldkit::layout::calibration_page;
using foldkit::layout::CalibrationOptions;

TEST(CalibrationPage, HasRegistrationMarksAndFiveCrossesInsideTheirCutArea) {
  const CalibrationOptions o;
  const auto page = calibration_page(o);
  const Box2 area = layout::regmark_cut_area(o.paper_mm, o.regmark);
  int marks = 0;
  for (const Path& p : page.sheet.paths)
    marks += p.role == PathRole::RegMark;
  EXPECT_EQ(marks, 3);
  ASSERT_EQ(page.crosses_mm.size(), 5u);
  for (Vec2 c : page.crosses_mm) {
    EXPECT_GE(c.x - o.cross_arm_mm, area.min.x);
    EXPECT_LE(c.x + o.cross_arm_mm, area.max.x);
    EXPECT_GE(c.y - o.cross_arm_mm, area.min.y);
    EXPECT_LE(c.y + o.cross_arm_mm, area.max.y);
  }
}

TEST(CalibrationPage, EveryCrossHasTwoCutsCentredOnIt) {
  const auto page = calibration_page();
  for (Vec2 c : page.crosses_mm) {
    int centred = 0;
    for (const Path& p : page.sheet.paths) {
      if (p.role != PathRole::Cut) continue;
      ASSERT_EQ(p.points_mm.size(), 2u);
      const Vec2 mid = (p.points_mm[0] + p.points_mm[1]) * 0.5;
      if (std::abs(mid.x - c.x) < 1e-9 && std::abs(mid.y - c.y) < 1e-9) ++centred;
    }
    EXPECT_EQ(centred, 2) << c.x << ", " << c.y;
  }
}

TEST(CalibrationPage, PrintedCrossesAndTicksAreNeverCut) {
  const auto page = calibration_page();
  int cuts = 0, printed = 0;
  for (const Path& p : page.sheet.paths) {
    cuts += p.role == PathRole::Cut;
    printed += p.role == PathRole::Hint;
  }
  EXPECT_EQ(cuts, 10);
  // Per cross: two lines and ticks every 0.5 mm on both sides of both 12 mm arms.
  EXPECT_EQ(printed, 5 * (2 + 4 * 24));
}

TEST(CalibrationPage, PaperTooSmallForTheMarksAndCrossesIsALayoutError) {
  CalibrationOptions o;
  o.paper_mm = {80, 80};
  EXPECT_THROW(calibration_page(o), LayoutError);
}
