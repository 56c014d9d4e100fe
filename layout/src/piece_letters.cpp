#include "foldkit/layout/piece_letters.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

#include "foldkit/layout/box_grid.hpp"

namespace foldkit::layout {
namespace {

constexpr double kGridCell_mm = 4;

double segment_distance(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double len2 = dot(ab, ab);
  const double t = len2 > 0 ? std::clamp(dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return norm(p - (a + ab * t));
}

struct Circle {
  Vec2 centre;
  double radius = 0;
};

Circle incircle(const Triangle2& t) {
  const double a = norm(t[1] - t[2]), b = norm(t[2] - t[0]), c = norm(t[0] - t[1]);
  const double perimeter = a + b + c;
  if (!(perimeter > 0)) return {t[0], 0};
  const Vec2 centre = (t[0] * a + t[1] * b + t[2] * c) * (1.0 / perimeter);
  return {centre, 2 * std::fabs(signed_area(t)) / perimeter};
}

Polygon octagon(Vec2 centre, double radius) {
  // Circumscribed: its sides touch the disc, so nothing clear of it touches the disc.
  const double r = radius / std::cos(std::numbers::pi / 8);
  Polygon out;
  for (int i = 0; i < 8; ++i) {
    const double a = std::numbers::pi / 8 + i * std::numbers::pi / 4;
    out.push_back(centre + Vec2{std::cos(a), std::sin(a)} * r);
  }
  return out;
}

// The lines of one piece and the distance from a point to the nearest of them (all, or outline only),
// looked up within a bounded reach.
struct PieceLines {
  std::vector<std::array<Vec2, 2>> lines;
  std::vector<bool> fold;
  BoxGrid grid;
  explicit PieceLines(const Box2& region) : grid(region, kGridCell_mm) {}

  void add(Vec2 a, Vec2 b, bool is_fold) {
    Box2 box;
    box.add(a);
    box.add(b);
    grid.insert(static_cast<int>(lines.size()), box);
    lines.push_back({a, b});
    fold.push_back(is_fold);
  }
  // Nearest distance to any line and to the outline, both capped at `reach`.
  std::pair<double, double> clearance(Vec2 p, double reach) const {
    double all = reach, outline = reach;
    grid.visit(Box2{p - Vec2{reach, reach}, p + Vec2{reach, reach}}, [&](int i) {
      const double d = segment_distance(p, lines[i][0], lines[i][1]);
      all = std::min(all, d);
      if (!fold[i]) outline = std::min(outline, d);
      return true;
    });
    return {all, outline};
  }
};

}  // namespace

std::vector<int> letter_ranks(int piece_count, std::span<const Seam> seams, std::span<const int> order) {
  std::vector<int> rank(static_cast<std::size_t>(std::max(piece_count, 0)), -1);
  int next = 0;
  for (int s : order)
    for (const SeamSide& side : seams[s].sides)
      if (side.piece >= 0 && side.piece < piece_count && rank[side.piece] < 0) rank[side.piece] = next++;
  for (int& r : rank)
    if (r < 0) r = next++;
  return rank;
}

double letter_width_mm(const std::string& text, double height_mm, const PieceLetterOptions& options) {
  return static_cast<double>(text.size()) * options.char_width * height_mm;
}

std::vector<PieceLetter> place_piece_letters(std::span<const ScaledPiece> pieces,
                                             std::span<const std::vector<FoldLine>> fold_lines,
                                             std::span<const std::string> texts,
                                             const PieceLetterOptions& o) {
  std::vector<PieceLetter> out;
  for (std::size_t p = 0; p < pieces.size() && p < texts.size(); ++p) {
    const ScaledPiece& piece = pieces[p];
    const std::string& text = texts[p];
    // Disc radius per cap height: half the diagonal of the text's box.
    const double aspect = std::hypot(0.5 * letter_width_mm(text, 1, o), 0.5);
    const auto height_for = [&](double clear) { return std::max(0.0, clear - o.clearance_mm) / aspect; };
    const double reach = aspect * o.max_mm + o.clearance_mm;

    Box2 region;
    for (const Triangle2& t : piece.triangles_mm)
      for (Vec2 v : t)
        region.add(v);
    PieceLines lines(region);
    for (const OutlineLoop& loop : piece.outline_mm)
      for (const OutlineEdge& e : loop)
        lines.add(e.a, e.b, false);
    if (p < fold_lines.size())
      for (const FoldLine& f : fold_lines[p])
        lines.add(f.a, f.b, true);

    // Candidates: the incentres of the faces with the largest incircles (bounded, so large parts stay
    // cheap), plus the midpoints of fold lines, where a letter may straddle two faces.
    std::vector<Circle> circles;
    circles.reserve(piece.triangles_mm.size());
    for (const Triangle2& t : piece.triangles_mm)
      circles.push_back(incircle(t));
    const std::size_t keep =
        std::min<std::size_t>(circles.size(), static_cast<std::size_t>(o.max_candidates));
    std::nth_element(circles.begin(), circles.begin() + static_cast<std::ptrdiff_t>(keep) - (keep > 0),
                     circles.end(), [](const Circle& a, const Circle& b) { return a.radius > b.radius; });
    circles.resize(keep);
    std::vector<Vec2> candidates;
    for (const Circle& c : circles)
      candidates.push_back(c.centre);
    if (p < fold_lines.size())
      for (std::size_t f = 0; f < fold_lines[p].size() && f < static_cast<std::size_t>(o.max_candidates); ++f)
        candidates.push_back(0.5 * (fold_lines[p][f].a + fold_lines[p][f].b));

    // Best clear spot and best spot clear of the outline only; ties go to the earlier candidate.
    double best_all = -1, best_outline = -1;
    Vec2 at_all = candidates.empty() ? Vec2{} : candidates.front(), at_outline = at_all;
    for (Vec2 c : candidates) {
      const auto [all, outline] = lines.clearance(c, reach);
      if (all > best_all) {
        best_all = all;
        at_all = c;
      }
      if (outline > best_outline) {
        best_outline = outline;
        at_outline = c;
      }
    }
    const double h_all = std::min(height_for(best_all), o.max_mm);
    const double h_outline = std::min(height_for(best_outline), o.max_mm);
    PieceLetter letter;
    letter.piece = static_cast<int>(p);
    letter.text = text;
    if (h_all >= o.preferred_mm || (h_all >= o.min_mm && h_outline < o.preferred_mm)) {
      letter.centre_mm = at_all;
      letter.height_mm = h_all;
    } else {
      letter.centre_mm = at_outline;
      letter.height_mm = std::max(h_outline, o.min_mm);
      letter.over_fold = true;
    }
    letter.radius_mm = aspect * letter.height_mm;
    if (letter.over_fold)
      letter.over_fold = lines.clearance(letter.centre_mm, reach).first < letter.radius_mm;
    letter.footprint_mm = octagon(letter.centre_mm, letter.radius_mm);
    out.push_back(std::move(letter));
  }
  return out;
}

}  // namespace foldkit::layout
