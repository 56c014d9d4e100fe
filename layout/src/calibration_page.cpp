#include "foldkit/layout/calibration_page.hpp"

#include <cmath>
#include <string>

#include "foldkit/error.hpp"

namespace foldkit::layout {
namespace {

constexpr double kMajorTickMm = 1.2;  // tick length at every whole millimetre
constexpr double kMinorTickMm = 0.6;  // tick length at the half millimetres
constexpr double kLabelHeightMm = 3;
constexpr double kInstructionHeightMm = 2.2;
constexpr double kInstructionLeadMm = 4.5;
constexpr double kInstructionIndentMm = 10;

Path line(PathRole role, Vec2 a, Vec2 b) {
  Path p;
  p.role = role;
  p.points_mm = {a, b};
  return p;
}

// A printed cross with ticks every tick_step_mm across both arms: the cut line's distance from the
// printed centre line is read off them like a ruler.
void add_printed_cross(Sheet& sheet, Vec2 c, const CalibrationOptions& o) {
  const double arm = o.cross_arm_mm;
  sheet.paths.push_back(line(PathRole::Hint, c - Vec2{arm, 0}, c + Vec2{arm, 0}));
  sheet.paths.push_back(line(PathRole::Hint, c - Vec2{0, arm}, c + Vec2{0, arm}));
  const int steps = static_cast<int>(std::floor(arm / o.tick_step_mm + 1e-9));
  for (int i = -steps; i <= steps; ++i) {
    if (i == 0) continue;
    const double d = i * o.tick_step_mm;
    const bool whole = std::abs(std::remainder(d, 1.0)) < 1e-9;
    const double half = (whole ? kMajorTickMm : kMinorTickMm) / 2;
    sheet.paths.push_back(line(PathRole::Hint, c + Vec2{d, -half}, c + Vec2{d, half}));
    sheet.paths.push_back(line(PathRole::Hint, c + Vec2{-half, d}, c + Vec2{half, d}));
  }
}

void add_cut_cross(Sheet& sheet, Vec2 c, const CalibrationOptions& o) {
  const double arm = o.cut_arm_mm;
  sheet.paths.push_back(line(PathRole::Cut, c - Vec2{arm, 0}, c + Vec2{arm, 0}));
  sheet.paths.push_back(line(PathRole::Cut, c - Vec2{0, arm}, c + Vec2{0, arm}));
}

// Between the top row of crosses and the centre one, clear of the marks and their keep-out zones.
void add_instructions(Sheet& sheet, Box2 area, Vec2 top_cross, Vec2 centre_cross) {
  const char* lines[] = {
      "foldkit print-and-cut calibration: print at 100 %, then cut this page relative to its marks.",
      "At each cross: how far right (+) or left (-), down (+) or up (-) is the PRINTED line from the CUT?",
      "Ticks every 0.5 mm. Enter the mean: foldkit calibrate --device ID --offset DX,DYmm",
  };
  double y = (top_cross.y + centre_cross.y) / 2 - kInstructionLeadMm;
  for (const char* text : lines) {
    Text t;
    t.text = text;
    t.at_mm = {area.min.x + kInstructionIndentMm, y};
    t.height_mm = kInstructionHeightMm;
    t.role = PathRole::Hint;
    sheet.texts.push_back(t);
    y += kInstructionLeadMm;
  }
}

}  // namespace

CalibrationPage calibration_page(const CalibrationOptions& o) {
  const Box2 area = regmark_cut_area(o.paper_mm, o.regmark);
  const double reach = o.inset_mm + o.cross_arm_mm;
  if (area.width() < 2 * reach || area.height() < 2 * reach + 20)
    throw LayoutError("the paper is too small for the calibration page (its marks span " +
                      std::to_string(static_cast<int>(area.width())) + " x " +
                      std::to_string(static_cast<int>(area.height())) + " mm)");
  CalibrationPage page;
  page.sheet.size_mm = o.paper_mm;
  page.sheet.printable_mm = area;
  page.sheet.paths = regmark_paths(o.paper_mm, o.regmark);
  const Box2 inner{area.min + Vec2{o.inset_mm, o.inset_mm}, area.max - Vec2{o.inset_mm, o.inset_mm + 15}};
  page.crosses_mm = {inner.min,
                     {inner.max.x, inner.min.y},
                     (inner.min + inner.max) * 0.5,
                     {inner.min.x, inner.max.y},
                     inner.max};
  for (std::size_t i = 0; i < page.crosses_mm.size(); ++i) {
    const Vec2 c = page.crosses_mm[i];
    add_printed_cross(page.sheet, c, o);
    add_cut_cross(page.sheet, c, o);
    Text label;
    label.text = std::to_string(i + 1);
    label.at_mm = c + Vec2{-o.cross_arm_mm, -2};
    label.height_mm = kLabelHeightMm;
    label.role = PathRole::Hint;
    page.sheet.texts.push_back(label);
  }
  add_instructions(page.sheet, area, page.crosses_mm[0], page.crosses_mm[2]);
  return page;
}

}  // namespace foldkit::layout
