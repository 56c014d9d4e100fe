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
constexpr double kLeastText_mm = 2;  ///< the least cap height a furniture text is shrunk to
constexpr double kHeading_mm = 17;   ///< the number, name, parts and bar above the square
/// The legend's own block when it cannot share one with the square: its five rows and their names.
constexpr Vec2 kLegendBlock_mm{31, 27};
/// The legend in one row in the top margin: four entries of a sample and a name ("mountain fold" is the
/// longest, about 23 mm in the sheet's font), 4 mm high.
constexpr Vec2 kLegendRow_mm{144, 4};

Polygon rect(const Box2& b) {
  return {b.min, {b.max.x, b.min.y}, b.max, {b.min.x, b.max.y}};
}

// The width of a furniture text: set in the sheet's font, not the labels' narrow family, whose advances
// label_width_mm knows (DejaVu Sans' digits are 0.87 of the cap height against 0.67).
double sheet_text_width_mm(const std::string& text, double cap_mm) {
  constexpr double kWiderThanLabels = 0.87 / 0.67;
  return kWiderThanLabels * label_width_mm(text, cap_mm, LabelOptions{});
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

// A free place for a block of `size`: the corners of the printable area, bottom-right first (packing
// fills from the top-left), then along the bottom and right edges, then the other corners and edges.
std::optional<Box2> free_spot(const Sheet& sheet, const Occupied& o, Vec2 size, double spacing) {
  const Box2 area = sheet.printable_mm;
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

// A block placed on the sheet: later blocks keep clear of it.
void occupy(Occupied& o, const Box2& block) {
  o.shapes.push_back(rect(block));
  o.boxes.push_back(block);
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

// The sheet's number and name, its parts and the 50 mm bar, in the top 15 mm of a block from `o`.
void draw_heading(Sheet& sheet, Vec2 o, const std::string& heading, const std::string& parts,
                  const FurnitureOptions& options) {
  add_text(sheet, heading, o + Vec2{0, options.text_mm}, options.text_mm);
  if (!parts.empty()) add_text(sheet, parts, o + Vec2{0, 7.2}, kSmallText_mm);
  add_text(sheet, "50 mm", o + Vec2{0.5 * kBar_mm - 4, 10.5}, kSmallText_mm);
  add_bar(sheet, o + Vec2{0, 13});
}

// The 1 in square with its top-left corner at `sq`, named inside.
void draw_square(Sheet& sheet, Vec2 sq) {
  add_line(sheet, {sq, sq + Vec2{kInch_mm, 0}, sq + Vec2{kInch_mm, kInch_mm}, sq + Vec2{0, kInch_mm}}, true);
  add_text(sheet, "1 in", sq + Vec2{0.5 * kInch_mm - 3, 0.5 * kInch_mm + 1.2}, kSmallText_mm);
}

bool margin_holds_heading(double bottom_margin_mm, const FurnitureOptions& options) {
  return bottom_margin_mm >= options.text_mm + 2;
}

// The parts line in the bottom margin from `at`, ending before `end_x`, a little smaller if need be; a
// long one goes to the right end of the top margin, where that is deep enough and clear of the marks.
void draw_parts_line_in_margins(Sheet& sheet, const std::string& parts, Vec2 at, double end_x,
                                std::span<const Box2> keep_out) {
  for (double cap : {kSmallText_mm, kLeastText_mm}) {
    if (at.x + sheet_text_width_mm(parts, cap) >= end_x) continue;
    add_text(sheet, parts, at, cap);
    return;
  }
  const double top = sheet.printable_mm.min.y;
  const Box2 line{
      {sheet.printable_mm.max.x - sheet_text_width_mm(parts, kSmallText_mm), 0.5 * (top - kSmallText_mm)},
      {sheet.printable_mm.max.x, 0.5 * (top + kSmallText_mm)}};
  if (top < kSmallText_mm + 2 || line.min.x < sheet.printable_mm.min.x ||
      std::any_of(keep_out.begin(), keep_out.end(), [&](const Box2& z) { return z.overlaps(line); }))
    return;
  add_text(sheet, parts, {line.min.x, line.max.y}, kSmallText_mm);
}

// Number, name and bar in the bottom margin when it is deep enough (the sheet had no room for the whole
// block); false when it is not.
bool draw_heading_in_margin(Sheet& sheet, const std::string& heading, const std::string& parts,
                            std::span<const Box2> keep_out, const FurnitureOptions& options) {
  const double margin = sheet.size_mm.y - sheet.printable_mm.max.y;
  if (!margin_holds_heading(margin, options)) return false;
  const double base = sheet.printable_mm.max.y + 0.5 * (margin + options.text_mm);
  double x = sheet.printable_mm.min.x;
  for (const Box2& z : keep_out)
    if (z.max.y > sheet.printable_mm.max.y && z.min.x <= x + 1e-9)
      x = std::max(x, z.max.x + options.spacing_mm);
  add_text(sheet, heading, {x, base}, options.text_mm);
  const double parts_x = x + sheet_text_width_mm(heading, options.text_mm) + 4;
  const double bar_x = sheet.printable_mm.max.x - kBar_mm;
  add_bar(sheet, {bar_x, base - 0.5 * options.text_mm});
  // The bar's name ends before its left tick: set in the sheet's font (not the labels' narrow one) it
  // is about 12 mm wide.
  constexpr double kBarName_mm = 14;
  const double name_x = bar_x - kBarName_mm;
  add_text(sheet, "50 mm", {name_x, base}, kSmallText_mm);
  if (!parts.empty()) draw_parts_line_in_margins(sheet, parts, {parts_x, base}, name_x - 2, keep_out);
  return true;
}

// The square's own block, with the heading above it when the margin cannot hold that.
Vec2 square_block_mm(bool heading_in_margin) {
  return heading_in_margin ? Vec2{kInch_mm + 2, kInch_mm + 1} : Vec2{kBar_mm + 2, kHeading_mm + kInch_mm + 1};
}

// The first sheet had no spot for the legend: it goes in one row in the top margin, where that is deep
// enough and clear of the mark zones. False when it is not.
bool legend_in_top_margin(Sheet& sheet, std::span<const Box2> keep_out) {
  const double margin = sheet.printable_mm.min.y;
  if (margin < kLegendRow_mm.y + 2 || sheet.printable_mm.width() < kLegendRow_mm.x) return false;
  const Vec2 at{sheet.printable_mm.min.x, 0.5 * (margin - kLegendRow_mm.y)};
  const Box2 row{at, at + kLegendRow_mm};
  for (const Box2& z : keep_out)
    if (z.overlaps(row)) return false;
  // A parts line may have gone to the top margin already.
  for (const Text& t : sheet.texts)
    if (t.role == PathRole::Sheet && t.at_mm.y < margin && t.at_mm.x < row.max.x + 2) return false;
  sheet.legend_mm = row;
  sheet.legend_in_row = true;
  return true;
}

// What one sheet got.
struct Furnished {
  bool square = false;
  bool legend = false;
};

// The whole block in one free spot: heading and bar on top, the square below, the legend beside it.
std::optional<Furnished> furnish_in_one_block(Sheet& sheet, Occupied& occupied, const std::string& heading,
                                              const std::string& parts, bool with_legend,
                                              const FurnitureOptions& options) {
  const std::optional<Box2> block = free_spot(sheet, occupied, furniture_size_mm(), options.spacing_mm);
  if (!block) return std::nullopt;
  occupy(occupied, *block);
  const Vec2 o = block->min + Vec2{1, 0};
  draw_heading(sheet, o, heading, parts, options);
  const Vec2 sq = o + Vec2{0, kHeading_mm};
  draw_square(sheet, sq);
  if (with_legend) sheet.legend_mm = Box2{sq + Vec2{kInch_mm + 2, 0}, block->max};
  return Furnished{true, with_legend};
}

// A sheet too full for the block: the heading goes in the bottom margin, and the square and the legend
// each take a smaller free spot of their own (a gap beside a part often holds a 1 in square where no
// 58 mm block fits).
Furnished furnish_in_pieces(Sheet& sheet, Occupied& occupied, const std::string& heading,
                            const std::string& parts, bool with_legend, std::span<const Box2> keep_out,
                            const FurnitureOptions& options) {
  Furnished got;
  const bool heading_in_margin = draw_heading_in_margin(sheet, heading, parts, keep_out, options);
  // Without a margin deep enough the heading needs a spot of its own, above the square.
  const double heading_mm = heading_in_margin ? 0 : kHeading_mm;
  const Vec2 square_block = square_block_mm(heading_in_margin);
  if (const std::optional<Box2> spot = free_spot(sheet, occupied, square_block, options.spacing_mm)) {
    occupy(occupied, *spot);
    const Vec2 o = spot->min + Vec2{1, 0};
    if (!heading_in_margin) draw_heading(sheet, o, heading, parts, options);
    draw_square(sheet, o + Vec2{0, heading_mm});
    got.square = true;
  }
  if (!with_legend) return got;
  if (const std::optional<Box2> spot = free_spot(sheet, occupied, kLegendBlock_mm, options.spacing_mm)) {
    occupy(occupied, *spot);
    sheet.legend_mm = Box2{spot->min + Vec2{1, 0}, spot->max};
    got.legend = true;
  }
  return got;
}

}  // namespace

Vec2 furniture_size_mm() {
  return {kBlockWidth_mm, kBlockHeight_mm};
}

Vec2 least_furniture_block_mm(double bottom_margin_mm, const FurnitureOptions& options) {
  return square_block_mm(margin_holds_heading(bottom_margin_mm, options));
}

std::vector<int> add_sheet_furniture(std::span<Sheet> sheets, std::span<const Box2> keep_out,
                                     const FurnitureOptions& options) {
  std::vector<int> without_square;
  bool legend_placed = false;
  for (std::size_t k = 0; k < sheets.size(); ++k) {
    Sheet& sheet = sheets[k];
    Occupied occupied = occupied_on(sheet, keep_out);
    const std::string heading = title(k, sheets.size(), options.model_name);
    const std::string parts = parts_line(sheet);
    // The legend goes on the first sheet, or the first after it with room.
    const bool with_legend = !legend_placed;
    Furnished got;
    if (const std::optional<Furnished> block =
            furnish_in_one_block(sheet, occupied, heading, parts, with_legend, options))
      got = *block;
    else
      got = furnish_in_pieces(sheet, occupied, heading, parts, with_legend, keep_out, options);
    // The first sheet carries the legend: in its top margin rather than on a later sheet.
    if (k == 0 && with_legend && !got.legend) got.legend = legend_in_top_margin(sheet, keep_out);
    legend_placed = legend_placed || got.legend;
    if (!got.square) without_square.push_back(static_cast<int>(k));
  }
  return without_square;
}

}  // namespace foldkit::layout
