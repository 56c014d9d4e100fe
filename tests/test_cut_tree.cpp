// CutTree: after any sequence of cuts, stitches and subtree moves the incremental state must equal the
// state rebuilt from scratch from the same edge states (pieces, overlapping pairs, cut counts per
// vertex), and every flat triangle must stay congruent to its face and glued to its fold neighbours.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <random>
#include <set>

#include "foldkit/unfold/cut_tree.hpp"
#include "foldkit/unfold/dual_graph.hpp"
#include "foldkit/unfold/mesh_io.hpp"
#include "foldkit/unfold/overlap.hpp"
#include "test_paths.hpp"

using namespace foldkit;
using namespace foldkit::unfold;

namespace {

std::set<std::pair<int, int>> pairs_of(const CutTree& t) {
  std::set<std::pair<int, int>> s;
  for (int f : t.overlapping_faces())
    for (int g : t.overlap_partners(f))
      s.insert({std::min(f, g), std::max(f, g)});
  return s;
}

// Pieces as a partition: the piece ids may differ, the grouping may not.
std::vector<int> canonical_pieces(const CutTree& t) {
  std::map<int, int> rename;
  std::vector<int> out(t.num_faces());
  for (int f = 0; f < t.num_faces(); ++f)
    out[f] = rename.emplace(t.piece(FaceId(f)), static_cast<int>(rename.size())).first->second;
  return out;
}

void expect_consistent(const CutTree& t) {
  const Mesh& m = t.mesh();
  CutTree fresh(t.context(), t.states());
  EXPECT_TRUE(t.states() == fresh.states()) << "the folds were not a forest";
  EXPECT_EQ(t.piece_count(), fresh.piece_count());
  EXPECT_EQ(canonical_pieces(t), canonical_pieces(fresh));
  EXPECT_EQ(t.overlap_count(), static_cast<int>(pairs_of(t).size()));
  EXPECT_EQ(pairs_of(t), pairs_of(fresh));
  std::vector<int> cuts(m.num_vertices(), 0);
  for (int e = 0; e < m.num_edges(); ++e)
    if (!t.folded(EdgeId(e))) ++cuts[m.edges[e].v[0]], ++cuts[m.edges[e].v[1]];
  for (int v = 0; v < m.num_vertices(); ++v)
    ASSERT_EQ(t.cut_count(VertexId(v)), cuts[v]) << "vertex " << v;
  const double tol = 1e-9 * t.context().cell_size;
  for (int f = 0; f < m.num_faces(); ++f) {
    const Triangle2& tri = t.flat(FaceId(f));
    ASSERT_GT(signed_area(tri), 0) << "face " << f << " mirrored";
    auto p = m.corners(f);
    for (int i = 0; i < 3; ++i)
      ASSERT_NEAR(norm(tri[(i + 1) % 3] - tri[i]), norm(p[(i + 1) % 3] - p[i]), tol) << "face " << f;
  }
  auto pos = [&](int f, int v) {
    for (int i = 0; i < 3; ++i)
      if (m.faces[f][i] == v) return t.flat(FaceId(f))[i];
    return Vec2{};
  };
  for (int e = 0; e < m.num_edges(); ++e) {
    if (!t.folded(EdgeId(e))) continue;
    const auto& me = m.edges[e];
    ASSERT_EQ(t.piece(me.face_id(0)), t.piece(me.face_id(1)));
    for (int v : me.v)
      ASSERT_LT(norm(pos(me.face[0], v) - pos(me.face[1], v)), tol) << "fold edge " << e;
  }
}

Mesh load(const std::string& name) {
  return load_mesh(test::example_mesh(name)).mesh;
}

}  // namespace

TEST(CutTree, OverlapsOfTheMinimumPerimeterTreeMatchTheWholeUnfoldingCheck) {
  const Mesh mesh = load("spot_350.obj");
  const UnfoldContext ctx = make_context(mesh);
  CutTree tree(ctx, spanning_forest(mesh, ctx.weight));
  EXPECT_EQ(tree.piece_count(), 1);
  std::vector<Triangle2> flat(mesh.num_faces());
  std::vector<int> piece(mesh.num_faces());
  for (int f = 0; f < mesh.num_faces(); ++f)
    flat[f] = tree.flat(FaceId(f)), piece[f] = tree.piece(FaceId(f));
  std::set<std::pair<int, int>> expected;
  for (auto p : overlapping_pairs(flat, piece, ctx.eps))
    expected.insert({p.a, p.b});
  EXPECT_GT(expected.size(), 0u) << "a spanning tree of spot overlaps (unfolding-notes.md)";
  EXPECT_EQ(pairs_of(tree), expected);
  expect_consistent(tree);
}

TEST(CutTree, RandomCutsStitchesAndMovesKeepTheIncrementalStateExact) {
  for (const char* name : {"bob_350.obj", "penguin_500.obj"}) {
    SCOPED_TRACE(name);
    const Mesh mesh = load(name);
    const UnfoldContext ctx = make_context(mesh);
    CutTree tree(ctx, spanning_forest(mesh, ctx.weight));
    std::mt19937_64 rng(11);
    std::vector<int> side;
    int cuts = 0, stitches = 0, moves = 0;
    for (int round = 0; round < 600; ++round) {
      const EdgeId e(std::uniform_int_distribution<int>(0, mesh.num_edges() - 1)(rng));
      const auto& me = mesh.edge(e);
      if (me.boundary()) continue;
      if (!tree.folded(e)) {
        if (tree.piece(me.face_id(0)) == tree.piece(me.face_id(1))) continue;
        tree.stitch(e);
        ++stitches;
      } else if (round % 3 == 0) {
        tree.cut(e);
        ++cuts;
      } else {
        tree.smaller_side(e, side);
        std::vector<EdgeId> attach;
        for (int f : side)
          for (EdgeId a : mesh.edges_of(FaceId(f)))
            if (a != e && !tree.folded(a) && !mesh.edge(a).boundary() &&
                !tree.in_side(tree.across(a, FaceId(f))) &&
                tree.piece(tree.across(a, FaceId(f))) == tree.piece(FaceId(f)))
              attach.push_back(a);
        if (attach.empty()) continue;
        const EdgeId a = attach[std::uniform_int_distribution<std::size_t>(0, attach.size() - 1)(rng)];
        const int before = tree.overlap_count() - tree.cross_overlaps(side);
        const int predicted = tree.reattach_cost(side, a, 1 << 30);
        tree.reattach(side, e, a);
        EXPECT_EQ(tree.overlap_count(), before + predicted) << "reattach_cost predicts the move";
        ++moves;
      }
      if (round % 100 == 99) {
        expect_consistent(tree);
        if (HasFatalFailure()) return;
      }
    }
    EXPECT_GT(cuts, 10);
    EXPECT_GT(stitches, 10);
    EXPECT_GT(moves, 10);
    expect_consistent(tree);
  }
}

TEST(CutTree, StitchCostPredictsTheOverlapsAStitchAdds) {
  const Mesh mesh = load("fish_350.obj");
  const UnfoldContext ctx = make_context(mesh);
  // Many small patches, as the GA starts from.
  CutTree tree(ctx, spanning_forest(mesh, ctx.weight, {}, 0.3));
  ASSERT_GT(tree.piece_count(), 10);
  int checked = 0;
  for (EdgeId e : all_ids<EdgeId>(mesh.num_edges())) {
    const auto& me = mesh.edge(e);
    if (me.boundary() || tree.folded(e) || tree.piece(me.face_id(0)) == tree.piece(me.face_id(1))) continue;
    const int before = tree.overlap_count(), pieces = tree.piece_count();
    const int cost = tree.stitch_cost(e, 1 << 30);
    tree.stitch(e);
    EXPECT_EQ(tree.overlap_count(), before + cost);
    EXPECT_EQ(tree.piece_count(), pieces - 1);
    ++checked;
  }
  EXPECT_GT(checked, 10);
  expect_consistent(tree);
}

TEST(CutTree, CurvatureRuleForbidsFoldingASaddleDownToOneCutAndTheGeometryAgrees) {
  // A hexagonal fan whose rim waves up and down: its centre is a saddle (angle sum above 2 pi), so its
  // star lies flat only when cut along at least two spokes.
  std::vector<Vec3> v{{0, 0, 0}};
  for (int i = 0; i < 6; ++i) {
    const double a = i * std::numbers::pi / 3;
    v.push_back({std::cos(a), std::sin(a), (i % 2 ? 0.6 : -0.6)});
  }
  std::vector<std::array<int, 3>> f;
  for (int i = 0; i < 6; ++i)
    f.push_back({0, 1 + i, 1 + (i + 1) % 6});
  const Mesh mesh = make_mesh(v, f, "saddle");
  const UnfoldContext ctx = make_context(mesh);
  ASSERT_EQ(ctx.required_cuts[0], 2);
  std::vector<int> spokes;
  for (int e = 0; e < mesh.num_edges(); ++e)
    if (!mesh.edges[e].boundary()) spokes.push_back(e);
  ASSERT_EQ(spokes.size(), 6u);
  // Cut two opposite spokes: two fans of three faces, each flat without overlap.
  EdgeStates state(mesh.num_edges(), EdgeState::Cut);
  for (int e : spokes)
    state[EdgeId(e)] = EdgeState::Fold;
  const int cut_a = spokes[0];
  int cut_b = -1;
  for (int e : spokes)
    if (e != cut_a && mesh.edges[e].face[0] != mesh.edges[cut_a].face[0] &&
        mesh.edges[e].face[0] != mesh.edges[cut_a].face[1] &&
        mesh.edges[e].face[1] != mesh.edges[cut_a].face[0] &&
        mesh.edges[e].face[1] != mesh.edges[cut_a].face[1])
      cut_b = e;
  ASSERT_GE(cut_b, 0);
  state[EdgeId(cut_a)] = state[EdgeId(cut_b)] = EdgeState::Cut;
  CutTree tree(ctx, state);
  ASSERT_EQ(tree.piece_count(), 2);
  EXPECT_EQ(tree.cut_count(VertexId(0)), 2);
  EXPECT_EQ(tree.overlap_count(), 0);
  EXPECT_FALSE(tree.curvature_allows_fold(EdgeId(cut_a)));
  EXPECT_FALSE(tree.curvature_allows_fold(EdgeId(cut_b)));
  // Folding one anyway wraps more than a full turn around the centre: the overlap test sees it.
  tree.stitch(EdgeId(cut_a));
  EXPECT_EQ(tree.cut_count(VertexId(0)), 1);
  EXPECT_GT(tree.overlap_count(), 0);
  expect_consistent(tree);
}
