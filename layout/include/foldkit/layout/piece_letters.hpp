#pragma once
// Part letters: every part carries its letter (A, B, …, Z, AA, …) inside it, large enough to find at a
// glance. Letters follow the glue order when there is one, so part A is where the builder starts.
// A letter is placed before the seam numbers, which then keep clear of it; it reads upright whatever
// rotation packing gives its part, because what it keeps clear is a disc round its centre.
#include <span>
#include <string>
#include <vector>

#include "foldkit/layout/folds.hpp"
#include "foldkit/layout/outline.hpp"
#include "foldkit/layout/polygon.hpp"

namespace foldkit::layout {

struct PieceLetterOptions {
  double preferred_mm =
      5;              ///< a letter at least this tall is found at a glance; crossing a fold for it is fine
  double max_mm = 8;  ///< no taller than this
  double min_mm = 2;  ///< no smaller than this, even on the tiniest part
  double char_width = 1.0;    ///< advance of a capital as a fraction of its cap height (DejaVu Sans: 0.94)
  double clearance_mm = 0.4;  ///< between the letter's disc and any line
  /// Candidate centres examined per part at most (the faces with the largest incircles).
  int max_candidates = 2000;
};

/// The rank of each piece in the lettering: pieces in the order the glue order `order` (seam indices,
/// may be empty) first touches them, then the others by index.
std::vector<int> letter_ranks(int piece_count, std::span<const Seam> seams, std::span<const int> order);

/// A placed letter in its piece's frame (mm, y up): a disc round `centre_mm` holds the upright text.
struct PieceLetter {
  int piece = -1;
  std::string text;
  Vec2 centre_mm;
  double height_mm = 0;
  double radius_mm = 0;    ///< the disc the letter keeps to at any rotation
  bool over_fold = false;  ///< the disc crosses a fold line (no clear spot large enough)
  Polygon footprint_mm;    ///< an octagon round the disc, for other labels to keep clear of
};

/// Width of `text` at cap height `height_mm`.
double letter_width_mm(const std::string& text, double height_mm, const PieceLetterOptions& options);

/// One letter per piece: `texts[p]` for piece p, placed at the spot farthest from every line (outline
/// and fold) when that gives at least preferred_mm, else the spot farthest from the outline.
std::vector<PieceLetter> place_piece_letters(std::span<const ScaledPiece> pieces,
                                             std::span<const std::vector<FoldLine>> fold_lines,
                                             std::span<const std::string> texts,
                                             const PieceLetterOptions& options = {});

}  // namespace foldkit::layout
