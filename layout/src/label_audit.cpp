#include "foldkit/layout/label_audit.hpp"

#include <array>
#include <cctype>
#include <cmath>

#include "foldkit/layout/box_grid.hpp"
#include "foldkit/layout/edge_numbers.hpp"
#include "foldkit/layout/label_text.hpp"
#include "foldkit/layout/piece_letters.hpp"
#include "foldkit/layout/polygon.hpp"

namespace foldkit::layout {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Overlaps shallower than this are contact, not crossing (placement keeps 0.25 mm).
constexpr double kTouch_mm = 0.01;
constexpr double kGridCell_mm = 4;

// Audits work in a y-up frame (the sheet's y negated), where the polygon helpers expect
// counter-clockwise shapes.
Vec2 up_frame(Vec2 p) {
  return {p.x, -p.y};
}

Polygon text_box(const Text& text) {
  const double w = text.role == PathRole::Piece
                       ? letter_width_mm(text.text, text.height_mm, PieceLetterOptions{})
                       : label_width_mm(text.text, text.height_mm, LabelOptions{});
  const Vec2 dir{std::cos(text.angle_rad), std::sin(text.angle_rad)};  // page frame, y down
  const Vec2 up{dir.y, -dir.x};                                        // where glyphs grow on the page
  // From below the descenders ("p2") to the cap height.
  const double descent = text.role == PathRole::Piece ? 0 : label_descent_mm(text.text, text.height_mm);
  const Vec2 a = text.at_mm - up * descent;
  const double h = text.height_mm + descent;
  Polygon box{up_frame(a), up_frame(a + dir * w), up_frame(a + dir * w + up * h), up_frame(a + up * h)};
  if (signed_area(box) < 0) std::swap(box[1], box[3]);
  return box;
}

bool audited(const Text& t) {
  return t.piece >= 0 && (t.role == PathRole::Label || t.role == PathRole::Hint || t.role == PathRole::Piece);
}

int unmarked_numbers(const std::string& text) {
  int count = 0;
  for (std::size_t i = 0; i < text.size();) {
    if (!std::isdigit(static_cast<unsigned char>(text[i]))) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < text.size() && std::isdigit(static_cast<unsigned char>(text[j])))
      ++j;
    // Seam and step numbers are short; a long digit run is not one of ours.
    if (j - i <= 9 && reads_as_other_number_turned(std::stoi(text.substr(i, j - i))) &&
        (j >= text.size() || text[j] != '.'))
      ++count;
    i = j;
  }
  return count;
}

}  // namespace

LabelAudit& LabelAudit::operator+=(const LabelAudit& o) {
  labels += o.labels;
  crossing_lines += o.crossing_lines;
  touching += o.touching;
  turned += o.turned;
  unmarked += o.unmarked;
  letters += o.letters;
  letters_crossing_lines += o.letters_crossing_lines;
  return *this;
}

LabelAudit audit_labels(const Sheet& sheet) {
  LabelAudit a;
  const Box2 region{up_frame({0, sheet.size_mm.y}), up_frame({sheet.size_mm.x, 0})};
  std::vector<std::array<Vec2, 2>> lines;
  BoxGrid line_grid(region, kGridCell_mm);
  for (const Path& p : sheet.paths) {
    if (p.role != PathRole::Cut && p.role != PathRole::Mountain && p.role != PathRole::Valley) continue;
    const std::size_t n = p.points_mm.size();
    for (std::size_t i = 0; i + 1 < n + (p.closed ? 1 : 0); ++i) {
      const std::array<Vec2, 2> seg{up_frame(p.points_mm[i]), up_frame(p.points_mm[(i + 1) % n])};
      Box2 box;
      box.add(seg[0]);
      box.add(seg[1]);
      line_grid.insert(static_cast<int>(lines.size()), box);
      lines.push_back(seg);
    }
  }
  std::vector<Polygon> boxes(sheet.texts.size());
  BoxGrid text_grid(region, kGridCell_mm);
  for (std::size_t i = 0; i < sheet.texts.size(); ++i) {
    const Text& t = sheet.texts[i];
    if (!audited(t)) continue;
    boxes[i] = text_box(t);
    text_grid.insert(static_cast<int>(i), bounds_of(boxes[i]));
  }
  for (std::size_t i = 0; i < sheet.texts.size(); ++i) {
    const Text& t = sheet.texts[i];
    if (!audited(t)) continue;
    const double angle = std::remainder(t.angle_rad, 2 * kPi);
    a.turned += angle >= 0.5 * kPi + 1e-6 || angle < -0.5 * kPi - 1e-6;
    if (t.role != PathRole::Piece) a.unmarked += unmarked_numbers(t.text);
    const Box2 reach = bounds_of(boxes[i]);
    const bool crosses =
        !line_grid.visit(reach, [&](int l) { return !convex_overlap(boxes[i], lines[l], kTouch_mm); });
    if (t.role == PathRole::Piece) {
      a.letters += 1;
      a.letters_crossing_lines += crosses;
      continue;
    }
    a.labels += t.role == PathRole::Label;
    a.crossing_lines += crosses;
    a.touching += !text_grid.visit(reach, [&](int k) {
      return k == static_cast<int>(i) || !convex_overlap(boxes[i], boxes[k], kTouch_mm);
    });
  }
  return a;
}

}  // namespace foldkit::layout
