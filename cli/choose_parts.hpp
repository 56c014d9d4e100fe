#pragma once
// The stage above unfold and layout that picks the parts: when the model does not fit the sheet as
// it unfolded, the unfolding is cut into parts that fit the printable room (unfold::split_into_parts),
// a few candidate partitions are packed without labels (a cheap estimate), the best one or two get the
// full layout, and the one with the fewest sheets (then fewest parts, then roundest) is kept with its
// layout. Neither unfold nor layout sees the other's result flow back.
#include <optional>
#include <vector>

#include "foldkit/layout/layout.hpp"
#include "foldkit/unfold/mesh.hpp"
#include "foldkit/unfold/parts.hpp"
#include "foldkit/unfold/unfold.hpp"
#include "foldkit/unfold/unfolding.hpp"

namespace foldkit::cli {

struct ChosenParts {
  unfold::Unfolding unfolding;  ///< the parts (the input unfolding when nothing had to be split)
  int split_pieces = 0;         ///< pieces that were too large for the sheet
  int new_pieces = 0;           ///< parts they were cut into
  /// The layout of `unfolding` with the options given, when the choice needed one (a split was tried).
  std::optional<layout::LayoutResult> layout;
  /// The parts are patches grown over the surface (unfold::patch_parts), every piece cut anew: parts cut
  /// from the too large pieces needed more sheets.
  bool patches = false;
};

/// Ways to open the slits a partition's parts hold: none; each such part grown again around its slits;
/// each cut at one fold per slit (unfold::cut_open_at_slits); or whichever of the two leaves fewer flaws.
enum class SlitOpening { None, Regrown, Cut, Better };

/// What the choice may do beyond picking a partition.
struct ChooseOptions {
  /// Parts that share a sheet are joined back along seams between them where that costs no sheet:
  /// fewer parts, fewer seams to match across parts. Off: the partitions as split.
  bool join_on_a_sheet = true;
  /// Besides parts cut from the unfolding's pieces, patches grown over the surface are tried
  /// (unfold::patch_parts): more parts, but compact ones that fill a sheet where a spindly net's do not.
  bool patches = true;
  /// How parts that hold slits (seams too narrow for a glue tab) are opened, so that each slit runs
  /// between two parts and takes a tab, where that costs no sheet, no label and at most a part per tab.
  SlitOpening open_slits = SlitOpening::Better;
  /// When set (below the layout's spacing), a layout worth it (closer_spacing_worth_trying) is chosen
  /// again with the pieces this far apart; that choice is kept when it saves a sheet with at most 1% of
  /// its labels more flaws, and not over issue 12's 2% unless the first had as many. Unset: the
  /// layout's spacing holds everywhere.
  std::optional<double> closer_spacing_mm;
};

/// The gap parts may close to where that saves a sheet, unless a spacing was asked for: half the
/// default, still a clean cut apart for a knife or a cutter.
inline constexpr double kCloserSpacing_mm = 1;

/// The fullest a sheet fewer may need to be filled for a closer spacing to be tried: the packer filled
/// bumpy_528's parts at 250 mm to 69.6% on a sheet fewer at 1 mm apart, and no run up to 1,000 faces
/// that needed more saved a sheet at 1 mm (`bench --layout`, session 39).
inline constexpr double kCloserSpacingReach = 0.72;

/// Whether `held`, a layout of parts that takes more sheets than any partition needs (`least`,
/// least_sheets), is worth choosing again with its parts kCloserSpacing_mm apart: a sheet fewer would
/// be filled to at most kCloserSpacingReach, and its flaws (flaws()) are within issue 12's bar of 2% of
/// its labels. Past that bar a closer choice may add no flaw at all to be kept, and none did: of the six
/// such runs up to 1,000 faces (1,000-face meshes at 150 mm, plane_1000 and wingnut_1000 at 250 mm),
/// the two that saved a sheet left 13% and 153% more flaws, and trying them cost plane_1000 and
/// wingnut_1000 at 250 mm 60 s of CPU where 25 s now give the same sheets (session 40).
bool closer_spacing_worth_trying(const layout::LayoutResult& held, long least);

/// The parts a layout with `options` should be given: the unfolding itself with --fit, --no-split or
/// when every piece fits; otherwise the best of the candidate partitions. `parts` says what every split
/// keeps to (its seam moves, forced cuts and folds, cuts: part_options_of); the room, scale and growth
/// are set here. Throws LayoutError.
ChosenParts choose_parts(const unfold::Mesh& mesh, const unfold::Unfolding& unfolding,
                         const layout::LayoutOptions& options, const unfold::PartOptions& parts = {},
                         const ChooseOptions& choose = {});

/// What a seam without a glue tab counts for in flaws, in labels that may be misread. The maker has no
/// way round a missing tab but to butt the edges and tape them from behind, a joint that shows and
/// gives; a label touching a line still mostly reads, and its number is printed on the other side too.
/// Counted alike, openings that put tabs on 1,000-face meshes at 150 mm were refused for the labels
/// their new seams crowd where faces are a few millimetres across, and those meshes' labels need a
/// larger size anyway (the remedy says which).
inline constexpr int kSeamWithoutTabFlaws = 2;

/// What a builder stumbles on: labels that may be misread (crossing a line or touching another), and
/// seams without a glue tab at kSeamWithoutTabFlaws each. Candidates are judged by it.
int flaws(const layout::LayoutResult& r);

/// What a split into parts keeps from the options `mesh` was unfolded with: the forced cuts and folds
/// (--cut/--keep), the cuts' label grading, whether seams move.
unfold::PartOptions part_options_of(const unfold::Mesh& mesh, const unfold::UnfoldOptions& unfolded);

/// Inside each flat face of `u` (every partition keeps it whole), a convex polygon in mm at
/// `mm_per_unit`: the face itself when convex, else its largest triangle (layout::shape_sheet_bound).
std::vector<layout::Polygon> flat_face_cores_mm(const unfold::Unfolding& u, double mm_per_unit);

/// The room for a part (layout::piece_room_mm) when the sheet is cut into `tiles` equal tiles: 2 or 3
/// across its longer side, 4 or 6 also in two across the shorter; each tile keeps the border for tabs and
/// spacing, so parts grown to it lie `tiles` to a sheet. 1 (or less): the whole room.
Vec2 tile_room_mm(const layout::LayoutOptions& o, int tiles);

/// The fewest sheets parts and tabs taking `used_mm2` can fill: their area over the printable area of `o`,
/// rounded up (at least 1). No partition needs fewer.
long area_sheet_bound(const layout::LayoutOptions& o, double used_mm2);

/// The shape bound of the flat faces of `u` at the size of `o` (layout::shape_sheet_bound of
/// flat_face_cores_mm); 0 without a size.
long flat_face_sheet_bound(const unfold::Unfolding& u, const layout::LayoutOptions& o);

/// The fewest sheets any partition of `u` can take with `o`: the larger of the area bound for parts and
/// tabs taking `used_mm2` and the shape bound of the flat faces.
long least_sheets(const unfold::Unfolding& u, const layout::LayoutOptions& o, double used_mm2);

}  // namespace foldkit::cli
