#pragma once
// The layout stage: Unfolding -> sheets. Scales the pieces, draws outlines and folds, adds glue tabs,
// matching edge numbers, optional direction arrows and assembly hints, packs everything onto sheets
// and adds registration marks. Built from the small modules beside this header.
#include <chrono>
#include <functional>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "foldkit/error.hpp"
#include "foldkit/layout/edge_numbers.hpp"
#include "foldkit/layout/folds.hpp"
#include "foldkit/layout/label_audit.hpp"
#include "foldkit/layout/pack.hpp"
#include "foldkit/layout/regmarks.hpp"
#include "foldkit/layout/tabs.hpp"
#include "foldkit/sheet/sheet.hpp"
#include "foldkit/unfold/unfolding.hpp"

namespace foldkit::layout {

/// A layout that left a sheet without its 1 in square packs that sheet's pieces again with a corner kept
/// for it, then maybe all pieces: those stages are named with these in front ("keeping a corner:
/// labelling", "keeping a corner on every sheet: packing", ...).
inline constexpr const char* kCornerStage = "keeping a corner: ";
inline constexpr const char* kCornersStage = "keeping a corner on every sheet: ";

/// How far a layout has come: `done` of `total` steps of `stage` ("drawing", "packing", "labelling",
/// "sheets", then maybe the kCornerStage and kCornersStage ones). Within one stage `done` never falls and
/// ends at `total`; a layout may go through its stages more than once (--fit tries several scales).
struct LayoutProgress {
  std::string stage;
  long done = 0;
  long total = 0;
};

struct LayoutOptions {
  /// Largest model dimension on paper, mm. Ignored when fit is set.
  std::optional<double> size_mm;
  /// Largest scale at which the whole model fits on one sheet.
  bool fit = false;
  /// Pieces larger than the paper at size_mm are cut into parts that fit (by the stage above layout that
  /// chooses the parts: layout itself never re-cuts an unfolding); when
  /// false they stay whole and layout_sheets refuses them, naming the largest size that fits.
  bool split_oversized = true;
  Vec2 paper_mm{210, 297};  ///< A4 portrait by default (already turned to the wanted orientation)
  double margin_mm = 10;
  /// Which folds are drawn (flat ones are not) and how far short of their vertices they stop.
  FoldOptions fold;

  bool tabs = true;  ///< one glue tab per seam pair
  /// A seam whose one face has no room beside the edge for its label while the other has gets its tab on
  /// the side without room, with steep ends and the label's height, to carry that label
  /// (tab_sides_for_labels). Without it (or without numbers) the tabs are planned as if there were no
  /// labels: the tabs of the part chooser's estimate.
  bool tab_sides_for_labels = true;
  /// Where a label finds no clear spot on its face, its seam's tab moves to its side and takes steep
  /// ends and the label's height, so that the label goes on the tab. The tabs take a little more paper.
  bool tabs_for_labels = true;
  /// With tabs_for_labels: a long seam whose one tab holds one label while the other finds no clear
  /// spot on its face gets its tab split in two halves, one on each side, each holding its side's label.
  bool split_tabs_for_labels = true;
  /// Where any of the three above is off (tabs for labels cost a sheet), the packed sheets still take the
  /// tabs they would plan, seam by seam, wherever there is room for them (tabs_in_place.hpp); on meshes
  /// up to 1,500 faces (above, the second drawing it takes would cost too much of a layout's time).
  bool label_tabs_in_place = true;
  /// Tab width and shape; a min_width_mm above width_mm counts as width_mm.
  TabOptions tab;

  bool numbers = true;  ///< matching edge numbers
  /// Edge-number sizes and clearances; min_mm is also the part letters' least size. With arrows the
  /// labels sit higher above their edge (kArrowLabelGap_mm).
  LabelOptions label;
  bool arrows = false;        ///< coloured direction arrows per seam pair (seed Figure 1(c))
  bool hints = false;         ///< assembly step beside each number and an assembly-order list
  bool piece_letters = true;  ///< each part's letter (A, B, …) inside it
  bool furniture = true;      ///< sheet number, model name, scale check and legend (furniture.hpp)
  std::string model_name;     ///< printed beside the sheet number

  bool regmarks = false;  ///< Silhouette registration marks for print-and-cut
  RegMarkOptions regmark;

  /// Spacing between pieces (with tabs), rotations tried, raster cell and engine. Where they go is the
  /// layout's to say: area_mm, keep_out_mm, max_sheets, deadline and progress are set by layout_sheets.
  PackOptions pack;
  /// When set, layout stops here with a LayoutError ("stopped at the time limit …").
  std::optional<std::chrono::steady_clock::time_point> deadline;
  /// Called as the layout goes (from the calling thread, often: keep it cheap); may be empty.
  std::function<void(const LayoutProgress&)> progress;
};

/// Figures for one sheet, or the whole layout.
struct SheetStats {
  double coverage = 0;  ///< area of pieces and tabs over the printable area (0..1)
  double piece_area_mm2 = 0, tab_area_mm2 = 0;
  /// The pieces' packed outlines (with their tabs) grown by half the packing spacing: no two of these
  /// overlap, so no packing fits more of them on a sheet than the printable area so grown holds.
  double spaced_area_mm2 = 0;
  int pieces = 0, tabs = 0, dropped_tabs = 0, labels = 0;
  int split_tabs = 0;       ///< seams whose tab is split in two halves (each half counts in tabs)
  int leaders = 0;          ///< labels standing off their edge, tied to it by a leader
  double min_label_mm = 0;  ///< smallest label cap height (0 when there is none)
};

/// One step of the assembly order: glue seam pair `number` (as printed) at step `step` (1-based).
struct AssemblyStep {
  int step = 0;
  int number = 0;
  double fold_angle_rad = 0;  ///< dihedral of the seam: sharp seams come first
  int edge = -1;              ///< the seam's mesh edge
  std::string name;           ///< as listed: "A-B 3", "A 7", or "7" for a model in one part (seam_name)
};

/// Where a piece went: the flat net's point p (model units) lands on sheet `sheet` at
/// q = rotate(angle_rad) * (scale * p) + offset_mm, in a frame with y up from the paper's bottom-left;
/// on the sheet (y down) that is (q.x, paper height - q.y). See LayoutResult::to_sheet.
struct PiecePlacement {
  int sheet = -1;
  double angle_rad = 0;
  Vec2 offset_mm;
};

struct LayoutResult {
  std::vector<Sheet> sheets;
  double scale_mm_per_unit = 1;  ///< model units -> mm
  double size_mm = 0;            ///< the model's largest dimension on paper
  double spacing_mm = 0;         ///< the least gap its pieces keep (PackOptions::spacing_mm)
  std::vector<SheetStats> sheet_stats;
  SheetStats overall;
  std::vector<AssemblyStep> assembly;  ///< filled when hints are on
  std::vector<std::string> notes;      ///< e.g. which tabs were dropped and why
  /// Per mesh edge, the number printed on both sides of a glued seam (0 for other edges). Numbers are
  /// counted per part and per pair of parts (number_seams_by_part): the edge's parts and this number
  /// name the seam.
  std::vector<int> seam_number;
  /// Per piece of the unfolding, where it went.
  std::vector<PiecePlacement> placements;
  /// Per piece of the unfolding, its letter (A, B, …; in glue order with hints).
  std::vector<std::string> piece_letters;
  /// The printed labels checked from the sheets' geometry (all sheets).
  LabelAudit label_audit;
  /// Seam labels that found no spot clear of every line and label (they cross a fold or touch).
  int labels_without_room = 0;
  /// Those labels, so that a maker can find them: the text printed, the seam's name (as listed) and the
  /// piece the label is on.
  struct CrowdedLabel {
    std::string text;
    std::string seam_name;
    int piece = -1;
  };
  std::vector<CrowdedLabel> crowded_labels;
  /// When more than 2% of the labels have no room: how many times larger the model (or its faces)
  /// must be for all but 2% to find a clear spot; 1 otherwise.
  double label_room_factor = 1;
  /// Names (seam_name, as listed) of the seams that got no glue tab.
  std::vector<std::string> dropped_tab_seams;
  double paper_height_mm = 0;

  /// A point of the flat net (model units) of `piece` in its sheet's coordinates (mm, y down).
  Vec2 to_sheet(int piece, Vec2 model_point) const {
    const PiecePlacement& p = placements[piece];
    const Vec2 q = rotated(model_point * scale_mm_per_unit, p.angle_rad) + p.offset_mm;
    return {q.x, paper_height_mm - q.y};
  }
};

/// How far above their edge labels sit when arrows run along the edges (LabelOptions::gap_mm), mm.
constexpr double kArrowLabelGap_mm = 1.6;

/// The printable area of a sheet with these options, sheet frame (mm from the top-left, y down).
Box2 printable_area(const LayoutOptions& options);

/// The fewest sheets any packing of r's pieces (laid out on the paper of `options`) can take: their
/// outlines grown by half the spacing they were packed at (LayoutResult::spacing_mm)
/// (SheetStats::spaced_area_mm2) never overlap and lie within the printable area grown alike. Above the area
/// bound where many or ragged pieces keep their gaps; 0 without pieces.
long spaced_sheet_bound(const LayoutResult& r, const LayoutOptions& options);

/// The rectangle (mm) a piece without its tabs must fit at its best rotation to be sure of a place on
/// a sheet: the printable area less piece_border_mm on every side (and the registration marks' corners).
Vec2 piece_room_mm(const LayoutOptions& options);

/// The border a piece keeps on every side within the printable area: room for its tabs, the spacing
/// and the packing raster (mm).
double piece_border_mm(const LayoutOptions& options);

/// The least side of piece_room_mm with which a layout can be made.
constexpr double kLeastPartRoom_mm = 2;

/// Throws LayoutError when the options are unusable: sizes not positive, margins that leave no printable
/// area, or a printable area with no room for a part (piece_room_mm under kLeastPartRoom_mm). Checked
/// by layout_sheets; callers that cut parts first check it before.
void check_options(const LayoutOptions& options);

/// Two sides of a seam within one piece that lie closer than this (mm) at both ends of its edge take no
/// glue tab with these options (a narrow slit, tabs.hpp): a partition should put them in two parts.
double narrow_slit_gap_mm(const LayoutOptions& options);

/// A piece fits no sheet at the asked model size. Carries the numbers, so that the caller can word the
/// size as its user sets it (the CLI: --size).
class PieceTooLarge : public LayoutError {
 public:
  PieceTooLarge(int piece, Vec2 area_mm, double asked_mm, double largest_mm)
      : LayoutError(message(piece, area_mm, asked_mm, largest_mm, "size")),
        piece_(piece),
        area_mm_(area_mm),
        asked_mm_(asked_mm),
        largest_mm_(largest_mm) {}
  /// The message with the model size called `size_name`.
  std::string message(const std::string& size_name) const {
    return message(piece_, area_mm_, asked_mm_, largest_mm_, size_name);
  }
  double largest_mm() const { return largest_mm_; }

 private:
  static std::string message(int piece, Vec2 area_mm, double asked_mm, double largest_mm,
                             const std::string& size_name);
  int piece_;
  Vec2 area_mm_;
  double asked_mm_, largest_mm_;
};

/// Scales, places and draws every piece. Throws LayoutError when the options are unusable, PieceTooLarge
/// when a piece cannot fit a sheet at the asked size (naming the largest size that fits).
LayoutResult layout_sheets(const unfold::Unfolding& unfolding, const LayoutOptions& options);

/// A layout that may stop once packed: `layout` is empty when the packing took more than the sheets
/// asked for, and nothing was labelled or drawn (half or more of a layout's time), for a caller that
/// would then lay out again with other options. `packed_sheets`: the sheets the packing took.
struct BoundedLayout {
  std::optional<LayoutResult> layout;
  long packed_sheets = 0;
};

/// layout_sheets(), stopped after packing when that takes more than `most_sheets` sheets; at a fixed
/// size only (with fit or without a size, the whole layout). Throws as layout_sheets does.
BoundedLayout layout_sheets_within(const unfold::Unfolding& unfolding, const LayoutOptions& options,
                                   long most_sheets);

}  // namespace foldkit::layout
