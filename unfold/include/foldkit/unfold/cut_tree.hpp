#pragma once
// The working state shared by the search, the GA and the rearrangement: one EdgeState per mesh edge
// (the folds form a spanning forest of the dual graph), every face laid flat in its piece, the
// overlapping pairs of faces within each piece, and the number of cut edges at every vertex.
// Every operation (cut an edge, stitch two pieces, move a subtree to another edge) updates all of
// it incrementally: only the faces that move are re-placed and re-tested against an OverlapIndex.
#include <cstdint>
#include <vector>

#include "foldkit/geom/predicates.hpp"
#include "foldkit/geom/rigid.hpp"
#include "foldkit/unfold/dual_graph.hpp"
#include "foldkit/unfold/edge_state.hpp"
#include "foldkit/unfold/ids.hpp"
#include "foldkit/unfold/mesh.hpp"
#include "foldkit/unfold/overlap_index.hpp"

namespace foldkit::unfold {

/// What every CutTree of one mesh shares, computed once (read-only, safe to share between threads).
struct UnfoldContext {
  const Mesh* mesh = nullptr;
  /// Each face laid flat on its own: corner 0 at the origin, corner 1 on +x, counter-clockwise.
  std::vector<Triangle2> canonical;
  /// Cut edges each vertex needs to avoid a local overlap (the seed's curvature rule): 2 at a
  /// hyperbolic vertex, 1 at an elliptic or flat one, 0 on an open boundary.
  std::vector<int> required_cuts;
  /// Cut weight per edge (cut_weights): light edges are folded first, heavy ones are the cuts preferred.
  std::vector<double> weight;
  /// Overlap depth tolerance (model units; half of overlap_tolerance, so that whatever the final
  /// whole-unfolding check calls an overlap the search has seen too) and grid cell size.
  double eps = 0;
  double cell_size = 1;
};

/// Builds the shared context of `mesh` (which must outlive it), its weights from `cuts`.
UnfoldContext make_context(const Mesh& mesh, const CutOptions& cuts = {});

/// The incremental unfolding state. A value type: copying it gives an independent state.
class CutTree {
 public:
  /// Lays out the forest given by `state` (one per edge; boundary edges are always cut; an edge that
  /// would close a cycle is cut) and finds every overlapping pair.
  CutTree(const UnfoldContext& context, EdgeStates state);

  const UnfoldContext& context() const { return *ctx_; }
  const Mesh& mesh() const { return *ctx_->mesh; }
  int num_faces() const { return static_cast<int>(piece_.size()); }
  bool folded(EdgeId e) const { return state_[e] == EdgeState::Fold; }
  /// The state of every edge, the form flatten() and the constructor take.
  const EdgeStates& states() const { return state_; }
  int piece(FaceId f) const { return piece_[f.index()]; }
  int piece_size(int p) const { return piece_size_[p]; }
  int piece_count() const { return piece_count_; }
  const Triangle2& flat(FaceId f) const { return index_.triangle(f.index()); }
  int cut_count(VertexId v) const { return cut_count_[v.index()]; }

  /// Number of overlapping pairs of faces (same piece, interiors overlap).
  int overlap_count() const { return overlap_pairs_; }
  /// Faces with at least one overlap partner, in no particular order.
  const std::vector<int>& overlapping_faces() const { return hot_; }
  const std::vector<int>& overlap_partners(int f) const { return partners_[f]; }

  /// The other face across edge e of face f (-1 across a boundary).
  FaceId across(EdgeId e, FaceId f) const;
  /// True when folding edge e keeps both its vertices at or above their required cut count.
  bool curvature_allows_fold(EdgeId e) const;
  /// True when cutting fold edge `cut` and folding cut edge `fold` (one move) keeps both vertices of
  /// `fold` at or above their required cut count: otherwise the move overlaps there for certain.
  bool curvature_allows_move(EdgeId cut, EdgeId fold) const;
  /// The motion taking the copy of edge e in face `moving` onto its copy in face `fixed` (how a move
  /// or a stitch glues them).
  RigidMotion glue_motion(EdgeId e, int moving, int fixed) const;

  /// Tree edges on the fold path between faces f and g of the same piece.
  std::vector<EdgeId> path(FaceId f, FaceId g);

  /// Cuts fold edge e: the smaller side becomes a new piece and loses its overlaps with the other side.
  void cut(EdgeId e);
  /// Number of overlapping pairs stitching cut edge e (between two pieces) would add, counting no
  /// further than `limit` + 1. The state is unchanged.
  int stitch_cost(EdgeId e, int limit);
  /// Folds cut edge e between two pieces: the smaller piece moves rigidly onto the other.
  void stitch(EdgeId e);

  /// Faces on the smaller side of fold edge e (e is treated as cut), written to `side`; afterwards
  /// in_side(f) tells membership until the next call.
  void smaller_side(EdgeId e, std::vector<int>& side);
  bool in_side(FaceId f) const { return side_mark_[f.index()] == side_stamp_; }
  /// Overlapping pairs between `side` (from smaller_side) and the rest of its piece.
  int cross_overlaps(const std::vector<int>& side) const;
  /// Overlapping pairs between `side`, moved rigidly so that its copy of cut edge `attach` meets the
  /// rest's copy, and the rest of its piece; counting stops past `limit`.
  int reattach_cost(const std::vector<int>& side, EdgeId attach, int limit);
  /// Cuts `cut_edge` and folds `attach`, moving `side` (from smaller_side(cut_edge)).
  void reattach(const std::vector<int>& side, EdgeId cut_edge, EdgeId attach);

 private:
  // Construction steps: every piece laid flat breadth-first from its lowest face (returns the triangles),
  // the cut edges at every vertex, every triangle into the overlap index with its overlapping pairs.
  std::vector<Triangle2> lay_out_pieces();
  void place_fold_neighbours(int f, int piece, std::vector<Triangle2>& tri, std::vector<int>& queue);
  void count_cuts();
  void index_all(const std::vector<Triangle2>& tri);
  bool folded(int e) const { return state_[EdgeId(e)] == EdgeState::Fold; }
  int across(int e, int f) const { return across(EdgeId(e), FaceId(f)).index(); }
  bool in_side(int f) const { return side_mark_[f] == side_stamp_; }
  Vec2 corner_position(int f, int v) const;
  void add_pair(int f, int g);
  void remove_pair(int f, int g);
  void collect_piece(int f, std::vector<int>& faces);
  int new_piece_id();
  void rebuild_parents();
  void move_faces(const std::vector<int>& faces, const RigidMotion& m, int new_piece);

  const UnfoldContext* ctx_;
  EdgeStates state_;
  std::vector<int> cut_count_;
  std::vector<int> piece_;
  std::vector<int> piece_size_;
  std::vector<int> free_pieces_;
  int piece_count_ = 0;
  OverlapIndex index_;
  std::vector<std::vector<int>> partners_;
  int overlap_pairs_ = 0;
  std::vector<int> hot_, hot_pos_;
  // Forest paths: parent face, edge to the parent and depth, rebuilt lazily after a change.
  std::vector<int> parent_, parent_edge_, depth_;
  bool parents_dirty_ = true;
  // Scratch for smaller_side.
  std::vector<std::uint32_t> side_mark_;
  std::uint32_t side_stamp_ = 0, mark_counter_ = 0;
  std::vector<int> queue_a_, queue_b_, moved_, via_;
};

}  // namespace foldkit::unfold
