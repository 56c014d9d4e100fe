#include "foldkit/devices/printed_marks.hpp"

#include <vector>

#include "foldkit/error.hpp"

namespace foldkit::devices {
namespace {

Box2 bounds(const Path& p) {
  Box2 b;
  for (Vec2 q : p.points_mm)
    b.add(q);
  return b;
}

[[noreturn]] void malformed(const std::string& why) {
  throw DeviceError("the sheet's registration marks are not a square and two L brackets (" + why + ")");
}

}  // namespace

std::optional<PrintedMarks> printed_marks(const Sheet& sheet) {
  std::vector<const Path*> squares, brackets;
  for (const Path& p : sheet.paths) {
    if (p.role != PathRole::RegMark || p.points_mm.empty()) continue;
    (p.filled && p.closed ? squares : brackets).push_back(&p);
  }
  if (squares.empty() && brackets.empty()) return std::nullopt;
  if (squares.size() != 1) malformed(std::to_string(squares.size()) + " filled squares");
  if (brackets.size() != 2) malformed(std::to_string(brackets.size()) + " brackets");
  const Box2 sq = bounds(*squares.front());
  Box2 a = bounds(*brackets[0]), b = bounds(*brackets[1]);
  if (a.max.x < b.max.x) std::swap(a, b);  // a: top-right, b: bottom-left
  const double half_stroke = a.min.y - sq.min.y;
  if (!(half_stroke >= 0) || a.width() <= 0 || b.height() <= 0) malformed("brackets above the square");
  PrintedMarks m;
  m.origin_mm = sq.min;
  m.square_mm = sq.width();
  m.stroke_mm = 2 * half_stroke;
  m.arm_mm = a.width() + half_stroke;
  m.extent_mm = {a.max.x + half_stroke - sq.min.x, b.max.y + half_stroke - sq.min.y};
  return m;
}

}  // namespace foldkit::devices
