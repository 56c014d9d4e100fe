#include "foldkit/layout/furniture.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "foldkit/layout/edge_numbers.hpp"
#include "foldkit/layout/label_text.hpp"
#include "foldkit/layout/polygon.hpp"

namespace foldkit::layout {
namespace {

constexpr double kBar_mm = 50;
constexpr double kInch_mm = 25.4;
constexpr double kBlockWidth_mm = 58;
constexpr double kBlockHeight_mm = 44;
constexpr double kStep_mm = 4;
constexpr double kSmallText_mm = 2.5;

Polygon rect(const Box2& b) {
  return {b.min, {b.max.x, b.min.y}, b.max, {b.min.x, b.max.y}};
}

Box2 grown(const Box2& b, double d) {
  return Box2{b.min - Vec2{d, d}, b.max + Vec2{d, d}};
}

// What the block must keep clear of on one sheet: closed part and tab outlines, text blocks that lie in
// no part (the glue-order list), the keep-out zones.
struct Occupied {
  std::vector<Polygon> shapes;
  std::vector<Box2> boxes;  // bounds of shapes
  std::vector<Box2> zones;
};

Occupied occupied_on(const Sheet& sheet, std::span<const Box2> keep_out) {
  Occupied o;
  for (const Path& p : sheet.paths) {
    if (p.points_mm.size() < 2 || p.role == PathRole::Sheet) continue;
    o.shapes.push_back(p.points_mm);
    o.boxes.push_back(bounds_of(p.points_mm));
  }
  for (const Text& t : sheet.texts) {
    if (t.piece >= 0 || t.role == PathRole::Sheet) continue;
    const double w = label_width_mm(t.text, t.height_mm, LabelOptions{});
    const Vec2 dir{std::cos(t.angle_rad), std::sin(t.angle_rad)}, up{dir.y, -dir.x};
    Polygon box{t.at_mm, t.at_mm + dir * w, t.at_mm + dir * w + up * t.height_mm, t.at_mm + up * t.height_mm};
    o.boxes.push_back(bounds_of(box));
    o.shapes.push_back(std::move(box));
  }
  o.zones.assign(keep_out.begin(), keep_out.end());
  return o;
}

bool is_free(const Occupied& o, const Box2& block, double spacing) {
  const Box2 reach = grown(block, spacing);
  for (const Box2& z : o.zones)
    if (z.overlaps(reach)) return false;
  const std::vector<Polygon> area{rect(reach)};
  for (std::size_t i = 0; i < o.shapes.size(); ++i) {
    if (!o.boxes[i].overlaps(reach)) continue;
    // A path that is not closed still blocks: the union of its bounds is close enough for the few open
    // paths (fold lines lie inside part outlines anyway).
    const std::vector<Polygon> shape{o.shapes[i]};
    if (std::fabs(intersection_area(area, shape)) > 1e-6) return false;
  }
  return true;
}

// Candidate corners of the printable area, bottom-right first (packing fills from the top-left), then
// along the bottom and right edges, then the other corners.
std::optional<Box2> free_block(const Sheet& sheet, const Occupied& o, double spacing) {
  const Box2 area = sheet.printable_mm;
  const Vec2 size = furniture_size_mm();
  if (area.width() < size.x || area.height() < size.y) return std::nullopt;
  auto at = [&](double x, double y) { return Box2{{x, y}, {x + size.x, y + size.y}}; };
  const double right = area.max.x - size.x, bottom = area.max.y - size.y;
  std::vector<Box2> candidates;
  for (double x = right; x >= area.min.x - 1e-9; x -= kStep_mm)
    candidates.push_back(at(x, bottom));
  for (double y = bottom - kStep_mm; y >= area.min.y - 1e-9; y -= kStep_mm)
    candidates.push_back(at(right, y));
  for (double x = area.min.x; x <= right + 1e-9; x += kStep_mm)
    candidates.push_back(at(x, area.min.y));
  for (double y = area.min.y; y <= bottom + 1e-9; y += kStep_mm)
    candidates.push_back(at(area.min.x, y));
  for (const Box2& c : candidates)
    if (is_free(o, c, spacing)) return c;
  return std::nullopt;
}

void add_text(Sheet& sheet, std::string text, Vec2 at, double height) {
  sheet.texts.push_back(Text{std::move(text), at, height, 0, PathRole::Sheet, -1});
}

void add_line(Sheet& sheet, std::vector<Vec2> points, bool closed = false) {
  sheet.paths.push_back(Path{PathRole::Sheet, std::move(points), closed, -1});
}

// The 50 mm bar with end ticks from `left` (the bar's left end on its baseline).
void add_bar(Sheet& sheet, Vec2 left) {
  add_line(sheet, {left, left + Vec2{kBar_mm, 0}});
  add_line(sheet, {left + Vec2{0, -1.5}, left + Vec2{0, 1.5}});
  add_line(sheet, {left + Vec2{kBar_mm, -1.5}, left + Vec2{kBar_mm, 1.5}});
}

// The parts the sheet holds, by their letters, runs as ranges ("parts A-D, G"): a label whose mate is
// part G says where G is even where it had no room for the sheet number. "" when the sheet has none.
std::string parts_line(const Sheet& sheet) {
  std::vector<int> ranks;
  for (const Text& t : sheet.texts)
    if (t.role == PathRole::Piece && letter_rank(t.text) >= 0) ranks.push_back(letter_rank(t.text));
  std::sort(ranks.begin(), ranks.end());
  ranks.erase(std::unique(ranks.begin(), ranks.end()), ranks.end());
  std::string line;
  for (std::size_t i = 0; i < ranks.size();) {
    std::size_t j = i;
    while (j + 1 < ranks.size() && ranks[j + 1] == ranks[j] + 1)
      ++j;
    line += (line.empty() ? "" : ", ") + piece_letter(ranks[i]);
    if (j > i) line += (j == i + 1 ? ", " : "-") + piece_letter(ranks[j]);
    i = j + 1;
  }
  if (line.empty()) return line;
  return (ranks.size() == 1 ? "part " : "parts ") + line;
}

std::string title(std::size_t k, std::size_t n, const std::string& name) {
  std::string t = std::to_string(k + 1) + "/" + std::to_string(n);
  if (!name.empty()) t.append("  ").append(name);
  return t;
}

}  // namespace

Vec2 furniture_size_mm() {
  return {kBlockWidth_mm, kBlockHeight_mm};
}

std::vector<int> add_sheet_furniture(std::span<Sheet> sheets, std::span<const Box2> keep_out,
                                     const FurnitureOptions& options) {
  std::vector<int> without_room;
  bool legend_placed = false;
  for (std::size_t k = 0; k < sheets.size(); ++k) {
    Sheet& sheet = sheets[k];
    const Occupied occupied = occupied_on(sheet, keep_out);
    const std::string heading = title(k, sheets.size(), options.model_name);
    const std::string parts = parts_line(sheet);
    if (const std::optional<Box2> block = free_block(sheet, occupied, options.spacing_mm)) {
      const Vec2 o = block->min + Vec2{1, 0};
      add_text(sheet, heading, o + Vec2{0, options.text_mm}, options.text_mm);
      if (!parts.empty()) add_text(sheet, parts, o + Vec2{0, 7.2}, kSmallText_mm);
      add_text(sheet, "50 mm", o + Vec2{0.5 * kBar_mm - 4, 10.5}, kSmallText_mm);
      add_bar(sheet, o + Vec2{0, 13});
      const Vec2 sq = o + Vec2{0, 17};
      add_line(sheet, {sq, sq + Vec2{kInch_mm, 0}, sq + Vec2{kInch_mm, kInch_mm}, sq + Vec2{0, kInch_mm}},
               true);
      add_text(sheet, "1 in", sq + Vec2{0.5 * kInch_mm - 3, 0.5 * kInch_mm + 1.2}, kSmallText_mm);
      // The legend's place beside the square: the renderer draws it in its own line styles. It goes on
      // the first sheet, or the first with a free corner when that one is full.
      if (!legend_placed) sheet.legend_mm = Box2{sq + Vec2{kInch_mm + 2, 0}, block->max};
      legend_placed = true;
      continue;
    }
    without_room.push_back(static_cast<int>(k));
    // No free corner: number, name and bar in the bottom margin when it is deep enough.
    const double margin = sheet.size_mm.y - sheet.printable_mm.max.y;
    if (margin < options.text_mm + 2) continue;
    const double base = sheet.printable_mm.max.y + 0.5 * (margin + options.text_mm);
    double x = sheet.printable_mm.min.x;
    for (const Box2& z : keep_out)
      if (z.max.y > sheet.printable_mm.max.y && z.min.x <= x + 1e-9)
        x = std::max(x, z.max.x + options.spacing_mm);
    add_text(sheet, heading, {x, base}, options.text_mm);
    const double parts_x = x + label_width_mm(heading, options.text_mm, LabelOptions{}) + 4;
    const double bar_x = sheet.printable_mm.max.x - kBar_mm;
    add_bar(sheet, {bar_x, base - 0.5 * options.text_mm});
    add_text(sheet, "50 mm", {bar_x - 12, base}, kSmallText_mm);
    if (!parts.empty() && parts_x + label_width_mm(parts, kSmallText_mm, LabelOptions{}) < bar_x - 14)
      add_text(sheet, parts, {parts_x, base}, kSmallText_mm);
  }
  return without_room;
}

}  // namespace foldkit::layout
