#pragma once
// Glue tabs: one trapezoid per seam pair, on one side only (or, asked for, split in two halves, one on
// each side along opposite halves of the edge). Between two pieces the side in a bay of its piece is
// preferred (packing nests the pieces closer); otherwise sides alternate along the outlines. Each tab's
// slanted ends take at most half of the free angle at its corners, so it keeps clear of the neighbouring
// edges and of a neighbour's tab even at sharp reflex corners; short edges get narrower tabs. A tab that
// would overlap its own piece or one of the piece's tabs is narrowed, then moved to the partner edge, and
// dropped only when neither side has room even at the minimum width. Other pieces are kept apart by packing,
// which treats a piece and its tabs as one shape.
#include <numbers>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "foldkit/layout/ids.hpp"
#include "foldkit/layout/outline.hpp"
#include "foldkit/layout/polygon.hpp"

namespace foldkit::layout {

/// The steepest end (angle from the edge) a tab gets, where gentler ends would leave a short edge's tab
/// too narrow; always within its corner's share of the free angle.
inline constexpr double kSteepestTabSlant_rad = 5 * std::numbers::pi / 12;

struct TabOptions {
  double width_mm = 5;      ///< full width, from the edge to the tab's outer side
  double min_width_mm = 2;  ///< narrower tabs are not worth gluing: try the other side or drop
  double max_slant_rad = 0.25 * std::numbers::pi;  ///< angle between edge and slanted end at most
  /// Tabs are at most this fraction of their edge's length wide, so short edges get narrow tabs.
  double width_per_length = 0.45;
  /// A tab wanted for its label (plan_tabs' wanted_sides) is first tried at least this wide (never
  /// above width_mm), where its edge's length alone would make it too narrow for the label; 0: no floor.
  double label_width_mm = 0;
  /// A seam between two pieces gets its tab on the side that lies in a bay of its piece (inside the
  /// piece's convex hull) where the other side's would stick out past it; off: sides alternate only.
  bool into_bays = true;
};

/// A placed tab, in its piece's frame (mm, y up).
struct Tab {
  SeamId seam;   ///< its seam
  int side = 0;  ///< which side of the seam carries it (Seam::sides[side])
  int piece = -1;
  Polygon quad_mm;  ///< counter-clockwise: edge start, outer start, outer end, edge end
  double width_mm = 0;
};

/// plan_tabs' wanted side for a seam whose tab is split in two: each side carries a tab along its own
/// half of the edge, glued under the other side's face along that half. Both labels of the seam then
/// have a tab to sit on, where neither face has room for one.
inline constexpr int kSplitTab = 2;

struct TabPlan {
  /// Per seam, its tab (a split one's half on its side 0) or nullopt when dropped.
  std::vector<std::optional<Tab>> tab_of_seam;
  /// Per seam (empty or sized like tab_of_seam): a split tab's half on side 1, else nullopt.
  std::vector<std::optional<Tab>> second_half_of_seam;
  std::vector<SeamId> dropped;  ///< seams without a tab, increasing

  /// The tab side `side` of seam `seam` carries, or nullptr.
  const Tab* on_side(std::size_t seam, int side) const;
  /// Whether seam `seam` carries a tab on each side (split).
  bool is_split(std::size_t seam) const;
  /// Every placed tab, by seam (a split seam's two halves in side order).
  std::vector<const Tab*> all() const;
};

/// Tabs for `seams` (processed in the order of `order`, or seam order when empty). `wanted_sides` (per
/// seam, may be empty) names the side whose tab is tried first (-1: the planner's choice, which
/// alternates along the outlines); the other side still gets the tab where the wanted one has no room.
/// kSplitTab asks for a split tab, each half at least label_width_mm wide with steep ends; where the
/// halves do not both fit, the seam gets one tab as if nothing was wanted.
TabPlan plan_tabs(std::span<const ScaledPiece> pieces, std::span<const Seam> seams, const TabOptions& options,
                  std::span<const int> order = {}, std::span<const int> wanted_sides = {});

/// The widths a tab on an edge of `edge_length_mm` is tried at, widest first: the full width (at most
/// width_per_length of the edge), then narrower by steps, down to min_width_mm (always the last).
std::vector<double> tab_widths_to_try(double edge_length_mm, const TabOptions& options);

/// How close the two copies of each end of a seam's edge must lie for the seam to be a narrow slit
/// (is_narrow_slit): a tab of min_width_mm with a little to spare, less its slants, fits no closer.
double narrow_slit_gap_mm(const TabOptions& options);

/// Whether `seam` is a narrow slit: its two sides lie in one piece, and the two copies of each end of
/// its edge are closer than a tab of min_width_mm (with a little to spare) needs: neighbours on one
/// outline meeting at the slit's tip with a narrow mouth, or sides facing each other that close along
/// the whole edge. No tab fits there; the maker closes it edge to edge.
bool is_narrow_slit(std::span<const ScaledPiece> pieces, const Seam& seam, const TabOptions& options);

/// The trapezoid on the outer side of outline edge a->b (piece on the left) of width w with slanted
/// ends at angles slant_a, slant_b from the edge; narrowed so that its outer side stays positive.
Polygon tab_trapezoid(Vec2 a, Vec2 b, double width_mm, double slant_a_rad, double slant_b_rad);

}  // namespace foldkit::layout
