// The label audit counts what a reader would see wrong on the printed sheet.
#include <gtest/gtest.h>

#include "foldkit/layout/label_audit.hpp"

using namespace foldkit;
using namespace foldkit::layout;

namespace {

Sheet sheet_with_cut_square() {
  Sheet s;
  s.size_mm = {210, 297};
  s.printable_mm = Box2{{10, 10}, {200, 287}};
  s.paths.push_back({PathRole::Cut, {{50, 50}, {100, 50}, {100, 100}, {50, 100}}, true, 0});
  return s;
}

Text label(std::string text, Vec2 at, double angle_rad = 0) {
  return Text{std::move(text), at, 3, angle_rad, PathRole::Label, 0};
}

}  // namespace

TEST(LabelAudit, AClearLabelPassesAndOneAcrossTheCutLineIsCounted) {
  Sheet s = sheet_with_cut_square();
  s.texts.push_back(label("12", {60, 70}));
  EXPECT_EQ(audit_labels(s).crossing_lines, 0);
  s.texts.push_back(label("13", {96, 80}));  // runs over x = 100
  const LabelAudit a = audit_labels(s);
  EXPECT_EQ(a.labels, 2);
  EXPECT_EQ(a.crossing_lines, 1);
  EXPECT_EQ(a.touching, 0);
}

TEST(LabelAudit, OverlappingLabelsCountAsTouchingBothOfThem) {
  Sheet s = sheet_with_cut_square();
  s.texts.push_back(label("12", {60, 70}));
  s.texts.push_back(label("14", {62, 71}));
  s.texts.push_back(label("15", {60, 90}));
  EXPECT_EQ(audit_labels(s).touching, 2);
}

TEST(LabelAudit, TextsTurnedBeyondAQuarterTurnAndUnmarkedAmbiguousNumbersAreCounted) {
  Sheet s = sheet_with_cut_square();
  const double pi = 3.14159265358979323846;
  s.texts.push_back(label("12", {60, 60}, 0.5 * pi - 0.01));
  s.texts.push_back(label("21", {60, 70}, -0.5 * pi));  // reads bottom to top: upright enough
  s.texts.push_back(label("22", {60, 80}, 0.5 * pi + 0.01));
  s.texts.push_back(label("B 16 p2", {60, 90}, pi));
  s.texts.push_back(label("9.", {80, 60}));
  const LabelAudit a = audit_labels(s);
  EXPECT_EQ(a.turned, 2);
  EXPECT_EQ(a.unmarked, 1);
}

TEST(LabelAudit, ALabelAcrossAFoldLineIsCountedAndOneBesideItIsNot) {
  Sheet s = sheet_with_cut_square();
  s.paths.push_back({PathRole::Valley, {{50, 75}, {100, 75}}, false, 0});
  s.paths.push_back({PathRole::Mountain, {{75, 50}, {75, 75}}, false, 0});
  s.texts.push_back(label("12", {60, 70}));     // foot at y = 70, glyphs up to y = 67: clear of y = 75
  s.texts.push_back(label("B13", {60, 76.5}));  // spans y 73.5..76.5 across the valley fold
  s.texts.push_back(label("14", {73, 65}));     // spans x 73..78.7 across the mountain fold
  const LabelAudit a = audit_labels(s);
  EXPECT_EQ(a.labels, 3);
  EXPECT_EQ(a.crossing_lines, 2);
  EXPECT_EQ(a.touching, 0);
}
