// Part letters: one per part, inside it, as large as it allows, in glue order.
#include <gtest/gtest.h>

#include "foldkit/layout/hints.hpp"
#include "foldkit/layout/piece_letters.hpp"
#include "foldkit/layout/split.hpp"
#include "layout_fixtures.hpp"

using namespace foldkit;
using namespace foldkit::layout;

namespace {

double segment_distance(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double t = std::clamp(dot(p - a, ab) / std::max(dot(ab, ab), 1e-300), 0.0, 1.0);
  return norm(p - (a + ab * t));
}

}  // namespace

TEST(PieceLetters, EveryPartGetsOneLetterInsideItClearOfItsOutline) {
  const auto& ex = test::unfolded_example("spot_350.obj");
  LayoutOptions o;
  o.size_mm = 150;
  const SplitResult split = split_to_fit(ex.mesh, ex.unfolding, o);
  const auto pieces = scaled_pieces(split.unfolding, 150 / split.unfolding.model_extent);
  ASSERT_GT(pieces.size(), 1u);
  std::vector<std::vector<FoldLine>> folds;
  for (const ScaledPiece& p : pieces)
    folds.push_back(fold_lines(split.unfolding, p));
  std::vector<std::string> texts;
  for (std::size_t p = 0; p < pieces.size(); ++p)
    texts.push_back(std::string(1, static_cast<char>('A' + p % 26)));
  const PieceLetterOptions options;
  const auto letters = place_piece_letters(pieces, folds, texts, options);
  ASSERT_EQ(letters.size(), pieces.size());
  int large = 0;
  for (const PieceLetter& l : letters) {
    const ScaledPiece& piece = pieces[l.piece];
    EXPECT_EQ(l.text, texts[l.piece]);
    EXPECT_GE(l.height_mm, options.min_mm - 1e-9);
    EXPECT_LE(l.height_mm, options.max_mm + 1e-9);
    bool inside = false;
    for (const Triangle2& t : piece.triangles_mm)
      inside = inside || inside_convex(t, l.centre_mm, 0);
    EXPECT_TRUE(inside) << "letter " << l.text << " outside its part";
    double to_outline = 1e300, to_any = 1e300;
    for (const OutlineLoop& loop : piece.outline_mm)
      for (const OutlineEdge& e : loop)
        to_outline = std::min(to_outline, segment_distance(l.centre_mm, e.a, e.b));
    to_any = to_outline;
    for (const FoldLine& f : folds[l.piece])
      to_any = std::min(to_any, segment_distance(l.centre_mm, f.a, f.b));
    if (l.height_mm > options.min_mm + 1e-9) {
      EXPECT_GE(to_outline, l.radius_mm) << l.text;
    }
    if (!l.over_fold) {
      EXPECT_GE(to_any, l.radius_mm - 1e-9) << l.text;
    }
    large += l.height_mm >= options.preferred_mm - 1e-9;
  }
  EXPECT_GE(large, static_cast<int>(letters.size()) / 2) << "most parts have room for a 5 mm letter";
}

TEST(PieceLetters, LettersFollowTheGlueOrderThenThePieceIndex) {
  std::vector<Seam> seams(3);
  seams[0].sides = {SeamSide{2, 0, 0}, SeamSide{2, 0, 1}};
  seams[1].sides = {SeamSide{3, 0, 0}, SeamSide{1, 0, 1}};
  seams[2].sides = {SeamSide{0, 0, 0}, SeamSide{0, 0, 1}};
  const std::vector<int> order{1, 0};
  EXPECT_EQ(letter_ranks(5, seams, order), (std::vector<int>{3, 1, 2, 0, 4}));
  EXPECT_EQ(letter_ranks(3, seams, {}), (std::vector<int>{0, 1, 2}));
}
