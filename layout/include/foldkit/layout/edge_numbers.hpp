#pragma once
// Matching edge numbers: every seam pair gets a unique number, written on both of its sides: inside
// the piece along the edge, or on the tab when the side has one. Labels are sized to their edge
// (never below a legible minimum), keep clear of outline and fold lines and of each other, and read
// with their foot towards the edge they name (or, on a needle face too narrow along its short edge,
// across it, starting at the edge).
#include <array>
#include <span>
#include <string>
#include <vector>

#include "foldkit/layout/folds.hpp"
#include "foldkit/layout/ids.hpp"
#include "foldkit/layout/outline.hpp"
#include "foldkit/layout/polygon.hpp"
#include "foldkit/layout/tabs.hpp"

namespace foldkit::layout {

/// How hard a label without a clear spot beside its edge looks for one on a leader. Quick: reading along
/// or across its edge. Thorough: also along or across the leader and at 45 degrees to the edge (the gaps
/// between a fan's slivers run every way), and where labels stand in the way of a spot, moving them
/// elsewhere. Thorough costs most where most labels find no spot (torus_2000 at 150 mm: 1.5 -> 2.5 s).
enum class LeaderSearch { Quick, Thorough };

struct LabelOptions {
  double min_mm = 2;    ///< smallest cap height
  double max_mm = 3.5;  ///< largest cap height
  /// Cap height as a fraction of the edge length before the limits apply.
  double per_length = 0.3;
  /// Advance of one digit as a fraction of the cap height: Liberation Sans Narrow, the labels' print
  /// family, has 0.456 em digits with 0.688 em capitals (0.67). Outputs in another font (a pen's
  /// Hershey futural is 0.95) squeeze each label to the length reserved for it.
  double char_width = 0.70;
  double gap_mm = 0.3;         ///< between the edge and the label's foot
  double clearance_mm = 0.25;  ///< least distance from other lines and labels
  /// The least distance where clearance_mm leaves no spot, before a label crosses a line: half the
  /// 0.2 mm ink of a line and a little more, so that no line touches the text.
  double tight_clearance_mm = 0.12;
  /// The assembly-step hint after the number: its cap height and the gap before it, as shares of the
  /// number's cap height.
  double hint_height_share = 0.75;
  double hint_gap_share = 0.3;
  /// A label with no clear spot beside its edge may stand this far from the edge's middle (the nearest
  /// point of its box), inside its piece, tied to the edge by a leader line: read clearly a few
  /// millimetres away rather than over a line. 0: no leaders.
  double leader_reach_mm = 16;
  LeaderSearch leader_search = LeaderSearch::Thorough;
  /// Threads that place the labels of different pieces at once (0: all cores). Without hints a piece's
  /// labels depend on that piece alone, so the labels are the same whatever the count.
  int threads = 0;
};

/// A label in its piece's frame (mm, y up): text from `at_mm` (its baseline) along `dir`, glyphs growing
/// towards perp_ccw(dir); `box_mm` reaches from the descenders below the baseline to the cap height.
struct Label {
  SeamId seam;
  int side = 0;
  int piece = -1;
  std::string text;
  Vec2 at_mm;
  Vec2 dir{1, 0};
  double height_mm = 0;
  bool on_tab = false;
  bool crowded = false;  ///< no clear spot: at the minimum size beside the edge where it runs into the least
  /// Text drawn just after the number in the hint role (the assembly step), "" for none.
  std::string hint;
  Polygon box_mm;          ///< the area the label (with its hint) covers
  bool over_fold = false;  ///< clear of outlines and labels but across a fold line
  /// Where the label stands away from its edge: the leader, from beside the label to just inside the
  /// edge's middle, then the bar along the edge it points at (two segments, four points); else empty.
  /// It crosses no outline and no other label, and no other label crosses it.
  std::vector<std::array<Vec2, 2>> leader_mm;
};

/// Numbers seams 1..N in outline order: piece by piece along each outline, so that the numbers of
/// neighbouring edges are close. Returns number per seam. This order is the seams' identity within a
/// layout (tabs alternate along it); what is printed is number_seams_by_part.
std::vector<int> number_seams(std::span<const ScaledPiece> pieces, std::span<const Seam> seams);

/// The numbers printed: the seams inside one part numbered 1, 2, … among themselves, and the seams
/// between two parts numbered 1, 2, … among the seams of that pair, each in the order of
/// `outline_numbers` (number_seams). A label is named by its number together with the mate's letter,
/// so numbers need only be unique per pair of parts; they stay one or two digits where one count over
/// the whole model needs three, and a short label is what fits beside a small face. With one part this
/// is number_seams.
/// With `room_mm` (per seam, seam_label_room_mm), the narrowest numbers go where room is least: within
/// each count the numbers are ranked by printed width (1-5, 7 and 8, then the marked "6." and "9.", then
/// 10, 11, …, the marked "16." after the unmarked two-digit numbers), the tightest seams take the
/// narrowest, and the numbers of one width still rise in outline order, so a label that has to squeeze
/// beside a small face is one digit, not three, and unmarked where it can be.
std::vector<int> number_seams_by_part(std::span<const Seam> seams, std::span<const int> outline_numbers,
                                      std::span<const double> room_mm = {});

/// Per seam, the width its tighter side's face leaves beside a label at the legible minimum height (the
/// label's own width not taken off); the smaller, the harder to label. Sides on no piece count as roomy.
std::vector<double> seam_label_room_mm(std::span<const ScaledPiece> pieces, std::span<const Seam> seams,
                                       const LabelOptions& options);

/// What each side of each seam may print, per seam and side: `full` where it fits clear of every line
/// and label (e.g. "B12 p3"), `brief` where only a shorter form does (e.g. "B12", when the sheets say
/// which parts they hold); `brief` may be empty for "as full".
struct SeamTexts {
  std::vector<std::array<std::string, 2>> full, brief;
};

/// Per seam, the side whose glue tab should carry its label, for plan_tabs: the side whose face has no
/// room beside the edge for a label of `widths_mm` (per seam) at the legible minimum, when the other
/// side's face has; -1 where the faces do not decide. The tab takes the label the face cannot, and the
/// mate's label goes on the face that has room.
std::vector<int> tab_sides_for_labels(std::span<const ScaledPiece> pieces, std::span<const Seam> seams,
                                      std::span<const double> widths_mm, const LabelOptions& options);

/// The side of seam `seam` whose label place_labels gives first (and which shows the step mark where it
/// can): the side with the tab, else side 0. Labels come seam by seam, this side first.
int first_labelled_side(const TabPlan& tabs, std::size_t seam);

/// Two labels per seam (one per side). `hints` (per seam, may be empty) is printed after the number.
/// `fold_lines` per piece are the lines labels must keep clear of, besides the outlines. Without
/// `texts` (empty) a side prints number_text of its number. Every label first gets a spot at the
/// legible minimum (the sides with the least room first; one that finds none may move up to two labels
/// in its way to other clear spots), then the full text, the hint and a larger size where the room
/// allows. Obstacles are looked up through grids, so the time grows with the number of seams, not its
/// square. `taken` (per piece, may be empty) are convex areas already used (part
/// letters) that labels keep clear of like other labels. `only_pieces` (empty: all) places the labels
/// of those pieces only; without hints they come out as the same pieces' labels of a call for all (a
/// label keeps clear of its own piece only), so a caller may place again only what changed. With hints
/// a seam's step mark goes on one of its two sides, which may lie in two pieces.
std::vector<Label> place_labels(std::span<const ScaledPiece> pieces, std::span<const Seam> seams,
                                std::span<const int> numbers, const TabPlan& tabs,
                                std::span<const std::vector<FoldLine>> fold_lines,
                                std::span<const std::string> hints, const LabelOptions& options,
                                const SeamTexts& texts = {}, std::span<const std::vector<Polygon>> taken = {},
                                std::span<const int> only_pieces = {});

/// How far the glyphs of `text` at cap height `height_mm` reach below the baseline: the descender of
/// "p" (in "p2") and of brackets, about a third of the cap height in DejaVu Sans and Hershey futural;
/// 0 for digits, capitals and periods. Label boxes reach that far below the foot.
double label_descent_mm(const std::string& text, double height_mm);

/// Length of `text` on the page at cap height `height_mm` under `options.char_width`.
double label_width_mm(const std::string& text, double height_mm, const LabelOptions& options);

/// Length of a label on the page: its `text` at cap height `height_mm`, then its `hint` ("" for none)
/// after the hint gap at the hint's height.
double label_width_mm(const std::string& text, const std::string& hint, double height_mm,
                      const LabelOptions& options);

}  // namespace foldkit::layout
