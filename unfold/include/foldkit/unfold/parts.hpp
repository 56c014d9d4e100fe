#pragma once
// Parts that fit the sheet. An unfolder that reaches one piece (the point of the seed) often gives a
// piece larger than a sheet at the size the user wants; rather than refuse, the piece is cut along
// fold edges into as few parts as a greedy growth finds, each fitting the room the sheet offers. Flat
// faces are never separated. The input unfolding is left alone: the result is a new unfolding of the
// same mesh whose cuts are the old cuts plus the new ones, so every part is a sub-tree of an old piece
// and overlaps nothing; then seams may move inside a part (PartOptions::move_seams), each move tested
// for overlaps and for the part's room.
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "foldkit/error.hpp"

#include "foldkit/geom/vec.hpp"
#include "foldkit/unfold/dual_graph.hpp"
#include "foldkit/unfold/mesh.hpp"
#include "foldkit/unfold/seam_moves.hpp"
#include "foldkit/unfold/unfolding.hpp"

namespace foldkit::unfold {

/// How parts grow over a piece's folds: breadth-first along the fold tree from the piece's first face,
/// or round (from one end of the piece's long axis, nearest faces first: compact parts that nest), or
/// whichever of the two gives fewer parts.
enum class PartGrowth { Fewest, Tree, Round };

/// The moves inside a partition's parts (PartOptions::seam_moves) find what they can well within this
/// work (torus_1000 at 150 mm: under 2 million); the bound keeps a pathological mesh from costing every
/// candidate partition seconds.
inline constexpr long kPartSeamMoveWork = 20'000'000;
inline SeamMoveOptions part_seam_moves() {
  SeamMoveOptions o;
  o.work_limit = kPartSeamMoveWork;
  return o;
}

struct PartOptions {
  /// The rectangle (mm) a part without its tabs must fit at its best rotation: the printable room of a
  /// sheet less what tabs, spacing and registration marks take (the layout says how much).
  Vec2 room_mm;
  double mm_per_unit = 1;  ///< the scale the model is printed at
  /// Parts are grown to fit room_mm scaled by this (1: as large as the sheet allows; smaller parts pack
  /// better when cut from a spindly net).
  double room_fraction = 1.0;
  /// When both sides are set (> 0): the rectangle (mm) parts are grown to instead of room_mm scaled by
  /// room_fraction, e.g. one tile of a sheet cut into halves or sixths, so that parts grown to it tile a
  /// sheet. It must lie within room_mm at some rotation; room_mm still says which pieces need a split.
  Vec2 grow_room_mm{0, 0};
  PartGrowth growth = PartGrowth::Fewest;
  /// Two faces across a seam whose sides lie closer than this (mm) at both ends of the edge never grow
  /// into one part: there the seam would be a narrow slit that takes no glue tab, between two parts it
  /// takes one. 0: parts may hold slits.
  double slit_gap_mm = 0;
  /// Pieces to cut to the room scaled by room_fraction even though they fit the room whole (the parts
  /// left alone on a last sheet, cut smaller to fill the gaps of the sheets before).
  std::vector<int> also_split;
  /// After a split, seams move inside every part (seam_moves.hpp) where a move keeps the part within the
  /// room it was grown to: with the rest of the piece cut away, many a move that closes a slit no longer
  /// overlaps (350-1,000 faces at 150 mm: seams without a tab 6.0% -> 5.7%). The unfolder's own moves
  /// ran on the whole piece; these cost a few milliseconds to a second per partition.
  bool move_seams = true;
  SeamMoveOptions seam_moves = part_seam_moves();
  /// What the moves must keep: the unfolding's forced cuts and folds (--cut/--keep; the folds inside
  /// flat faces are kept from the unfolding itself). `cuts` grades the seams' labels (tight_edges) as
  /// the unfolder did, so that a move never trades a slit for a label without room.
  EdgeConstraints constraints;
  CutOptions cuts;
};

struct PartsResult {
  Unfolding unfolding;
  int split_pieces = 0;  ///< pieces that were too large
  int new_pieces = 0;    ///< parts they were cut into
};

/// A flat face alone is larger than the room for a part: no split helps. Carries the numbers, so that the
/// caller can word the size as its user sets it (the CLI: --size).
class PartTooLarge : public LayoutError {
 public:
  PartTooLarge(int triangles, Vec2 room_mm, double asked_mm, double largest_mm)
      : LayoutError(message(triangles, room_mm, asked_mm, largest_mm, "size")),
        triangles_(triangles),
        room_mm_(room_mm),
        asked_mm_(asked_mm),
        largest_mm_(largest_mm) {}
  /// The message with the model size called `size_name`.
  std::string message(const std::string& size_name) const {
    return message(triangles_, room_mm_, asked_mm_, largest_mm_, size_name);
  }
  double largest_mm() const { return largest_mm_; }

 private:
  static std::string message(int triangles, Vec2 room_mm, double asked_mm, double largest_mm,
                             const std::string& size_name);
  int triangles_;
  Vec2 room_mm_;
  double asked_mm_, largest_mm_;
};

/// Cuts every piece that does not fit options.room_mm at options.mm_per_unit into parts that fit the
/// room scaled by options.room_fraction, growing each part over the piece's folds, whole flat faces at
/// a time, for as long as it fits, then merging neighbouring parts that fit together, then moving seams
/// inside the parts (options.move_seams). Throws PartTooLarge
/// when a flat face alone is larger than the room, naming the largest model size that fits.
PartsResult split_into_parts(const Mesh& mesh, const Unfolding& unfolding, const PartOptions& options);

/// Slits that the moves inside the parts left (seam_moves.hpp), closed across parts: a fold at a slit's
/// end is cut, which splits its part, and the side cut off joins a neighbouring part along a seam between
/// them, where the neighbour with it stays overlap-free and fits options.room_mm, both labels of the new
/// cut fit beside it (options.cuts), options.constraints and the flat faces are kept, and the slits get
/// fewer. As many parts as before; parts change shape, so the caller judges the packing again.
Unfolding close_slits_across_parts(const Mesh& mesh, const Unfolding& parts, const PartOptions& options);

/// Parts joined back together along seams between them, where `may_join(a, b)` allows it for parts a
/// and b of `parts` (e.g. parts that share a sheet): the smallest pairs first, each along one seam edge
/// where the joined part stays overlap-free, fits options.room_mm scaled by options.room_fraction at
/// options.mm_per_unit, keeps options.constraints' cuts and adds no slit
/// (options.seam_moves.min_gap_per_length). Fewer parts are fewer seams a builder must match across
/// parts; the caller judges the packing again. At most `most_joins` joins, the first in that order: the
/// caller may take fewer where all cost a sheet.
Unfolding join_parts(const Mesh& mesh, const Unfolding& parts, const PartOptions& options,
                     const std::function<bool(int, int)>& may_join,
                     int most_joins = std::numeric_limits<int>::max());

/// Compact parts grown over the surface instead of cut from a net: every flat face of `unfolding` a part
/// of its own (options.constraints' forced folds kept), then joined as join_parts joins them (smallest
/// pairs first, overlap-free, within options.room_mm scaled by options.room_fraction, no new slit) until
/// no join is left; then the seams between patches move off edges too narrow for their labels
/// (options.cuts grades them), a side of a few faces changing patch where it still fits and adds no slit.
/// A part is then a patch of neighbouring faces, round on the model, whose net stays close to its
/// outline on the surface: where a one-piece net is spindly, such parts fill a sheet far better
/// (knight_500 at 150 mm on A4: 2 sheets in 5 parts cut from the net, 1 sheet in 27 patches), at the
/// price of more parts and seams. None where the forced folds alone overlap.
std::optional<Unfolding> patch_parts(const Mesh& mesh, const Unfolding& unfolding,
                                     const PartOptions& options);

/// The forced cuts and folds any change to the parts of `u` must keep: `given` (one rule per edge, or none),
/// and a fold on every edge inside a flat face.
EdgeConstraints move_constraints(const Unfolding& u, const EdgeConstraints& given);

/// Per face, the flat face it belongs to (faces joined by UnfoldEdge::inside_face), numbered from 0.
std::vector<int> flat_face_of(const Unfolding& unfolding);

}  // namespace foldkit::unfold
