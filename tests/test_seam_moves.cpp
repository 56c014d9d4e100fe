// Seam moves: fewer cut-tree leaves at nearly flat vertices and fewer cuts on edges too tight for a
// label, the unfolding still one valid piece, forced seams and the curvature rule kept, the same result
// every time however busy the machine.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

#include "foldkit/unfold/curvature.hpp"
#include "foldkit/unfold/dual_graph.hpp"
#include "foldkit/unfold/mesh_io.hpp"
#include "foldkit/unfold/seam_moves.hpp"
#include "foldkit/unfold/search.hpp"
#include "foldkit/unfold/unfold.hpp"
#include "foldkit/unfold/unfolding.hpp"
#include "test_paths.hpp"

using namespace foldkit;
using namespace foldkit::unfold;

namespace {

Mesh load(const std::string& name) {
  return load_mesh(test::example_mesh(name)).mesh;
}

// The search's one overlap-free piece of `mesh`, as a CutTree.
CutTree solved_tree(const UnfoldContext& ctx, const EdgeConstraints& constraints = {}) {
  SearchOptions opt;
  opt.constraints = constraints;
  const SearchResult r = search_unfold(ctx, spanning_forest(*ctx.mesh, ctx.weight, constraints), opt);
  EXPECT_TRUE(r.solved);
  return CutTree(ctx, r.edges);
}

}  // namespace

class SeamMovesOnExamples : public ::testing::TestWithParam<const char*> {};

TEST_P(SeamMovesOnExamples, MostSlitsCloseAndTheUnfoldingStaysOneValidPiece) {
  const Mesh mesh = load(GetParam());
  const UnfoldContext ctx = make_context(mesh);
  CutTree tree = solved_tree(ctx);
  const SeamMoveOptions opt;
  const int before = count_slits(tree, opt.min_gap_per_length);
  const SeamMoveResult r = move_seams(tree, {}, {}, opt);
  EXPECT_EQ(r.slits_before, before);
  EXPECT_EQ(r.slits_after, count_slits(tree, opt.min_gap_per_length));
  EXPECT_GT(before, 10);
  EXPECT_LE(3 * r.slits_after, before) << "closed only " << before - r.slits_after << " of " << before;
  EXPECT_EQ(tree.overlap_count(), 0);
  EXPECT_EQ(tree.piece_count(), 1);
  for (int v = 0; v < mesh.num_vertices(); ++v)
    EXPECT_GE(tree.cut_count(VertexId(v)), ctx.required_cuts[v]) << "vertex " << v;
  const Unfolding u = flatten(mesh, tree.states());
  EXPECT_EQ(u.piece_count, 1);
  EXPECT_EQ(check_unfolding(mesh, u), std::vector<std::string>{});
}

INSTANTIATE_TEST_SUITE_P(Examples, SeamMovesOnExamples, ::testing::Values("spot_350.obj", "bob_350.obj"));

TEST(SeamMoves, ForcedCutsAndFoldsAreKept) {
  const Mesh mesh = load("bob_350.obj");
  const UnfoldContext ctx = make_context(mesh);
  // Forbid cutting, and force, every tenth edge of a first solution's folds and cuts.
  const CutTree first = solved_tree(ctx);
  EdgeConstraints c;
  c.rule.assign(mesh.num_edges(), EdgeRule::Free);
  for (int e = 0; e < mesh.num_edges(); e += 10)
    c.rule[EdgeId(e)] = first.folded(EdgeId(e)) ? EdgeRule::MustFold : EdgeRule::MustCut;
  CutTree tree = solved_tree(ctx, c);
  for (EdgeId e : all_ids<EdgeId>(mesh.num_edges())) {
    if (c.fold(e)) {
      ASSERT_TRUE(tree.folded(e));
    }
    if (c.cut(e)) {
      ASSERT_FALSE(tree.folded(e));
    }
  }
  const SeamMoveResult r = move_seams(tree, c, {}, {});
  EXPECT_GT(r.moves, 0);
  for (EdgeId e : all_ids<EdgeId>(mesh.num_edges())) {
    if (c.fold(e)) {
      EXPECT_TRUE(tree.folded(e)) << "edge " << e.index();
    }
    if (c.cut(e)) {
      EXPECT_FALSE(tree.folded(e)) << "edge " << e.index();
    }
  }
  EXPECT_EQ(tree.overlap_count(), 0);
}

TEST(SeamMoves, AMoveTheCallerRefusesIsNotTaken) {
  const Mesh mesh = load("spot_350.obj");
  const UnfoldContext ctx = make_context(mesh);
  const CutTree solved = solved_tree(ctx);
  CutTree refused = solved, asked = solved;
  SeamMoveOptions opt;
  opt.accept = [](const CutTree&, const std::vector<int>&, const RigidMotion&) { return false; };
  EXPECT_EQ(move_seams(refused, {}, {}, opt).moves, 0);
  EXPECT_TRUE(refused.states() == solved.states());
  // Asked about every move, with the side that moves; one accepted at most.
  int calls = 0;
  opt.accept = [&](const CutTree& t, const std::vector<int>& side, const RigidMotion&) {
    EXPECT_FALSE(side.empty());
    EXPECT_LT(2 * static_cast<int>(side.size()), t.num_faces() + 1) << "the smaller side moves";
    return ++calls == 1;
  };
  EXPECT_EQ(move_seams(asked, {}, {}, opt).moves, 1);
  EXPECT_GT(calls, 1);
  EXPECT_EQ(asked.overlap_count(), 0);
}

TEST(SeamMoves, TheSameTreeGivesTheSameCuts) {
  const Mesh mesh = load("spot_350.obj");
  const UnfoldContext ctx = make_context(mesh);
  CutTree a = solved_tree(ctx);
  CutTree b = a;
  move_seams(a, {}, {}, {});
  move_seams(b, {}, {}, {});
  EXPECT_TRUE(a.states() == b.states());
}

TEST(SeamMoves, TheUnfoldingStageClosesThemUnlessAskedNotTo) {
  const Mesh mesh = load("bob_350.obj");
  UnfoldOptions with, without;
  without.move_seams = false;
  const UnfoldResult a = unfold_mesh(mesh, with), b = unfold_mesh(mesh, without);
  const UnfoldContext ctx = make_context(mesh);
  auto slits = [&](const Unfolding& u) {
    return count_slits(CutTree(ctx, edge_states(u)), kSlitGapPerLength);
  };
  EXPECT_EQ(a.unfolding.piece_count, 1);
  EXPECT_LT(2 * slits(a.unfolding), slits(b.unfolding));
  EXPECT_EQ(check_unfolding(mesh, a.unfolding), std::vector<std::string>{});
}

TEST(SeamMoves, ProgressIsReportedPerSlitTriedWithCountsThatNeverFall) {
  const Mesh mesh = load("spot_350.obj");
  const UnfoldContext ctx = make_context(mesh);
  CutTree tree = solved_tree(ctx);
  SeamMoveOptions opt;
  std::vector<std::pair<long, long>> seen;
  opt.progress = [&seen](long done, long total) { seen.emplace_back(done, total); };
  const SeamMoveResult r = move_seams(tree, {}, {}, opt);
  ASSERT_GE(static_cast<int>(seen.size()), r.slits_before) << "every slit is tried once in the first pass";
  // One total for the whole run (a bar that does not rescale), never reached before the run ends.
  for (std::size_t k = 0; k < seen.size(); ++k) {
    EXPECT_EQ(seen[k].second, seen.front().second) << "report " << k << " changed the total";
    EXPECT_LT(seen[k].first, seen[k].second);
    if (k > 0) {
      EXPECT_GT(seen[k].first, seen[k - 1].first) << "report " << k << " went back";
    }
  }
}

namespace {

// Label grades of `mesh` at the median label room: about half the edges lack room on some side.
std::vector<LabelFit> median_label_fit(const Mesh& mesh) {
  std::vector<double> room = edge_label_room(mesh, 3);
  std::nth_element(room.begin(), room.begin() + room.size() / 2, room.end());
  CutOptions cuts;
  cuts.label_room = room[room.size() / 2];
  return tight_edges(mesh, cuts);
}

}  // namespace

TEST(SeamMoves, TightCutsAreFoldedWhereAMoveAllowsAndTheSlitsGetNoWorse) {
  const Mesh mesh = load("spot_350.obj");
  const UnfoldContext ctx = make_context(mesh);
  const std::vector<LabelFit> fit = median_label_fit(mesh);
  CutTree with = solved_tree(ctx);
  CutTree without = with;
  const SeamMoveResult w = move_seams(with, {}, fit, {});
  move_seams(without, {}, {}, {});
  int folded = 0, tight_cut_without = 0;
  for (EdgeId e : all_ids<EdgeId>(mesh.num_edges())) {
    if (fit[e.index()] != LabelFit::Tight || mesh.edge(e).boundary()) continue;
    tight_cut_without += !without.folded(e);
    folded += !without.folded(e) && with.folded(e);
  }
  EXPECT_GT(w.tight_before, 20);
  EXPECT_GT(folded, 0) << "no tight cut edge folded";
  EXPECT_LT(w.tight_after, tight_cut_without) << "the label cost folds more tight cut edges than slits alone";
  EXPECT_LE(4 * w.tight_after, 3 * w.tight_before);
  EXPECT_LE(w.slits_after, count_slits(without, kSlitGapPerLength) + 1);
  EXPECT_EQ(with.overlap_count(), 0);
  EXPECT_EQ(with.piece_count(), 1);
  for (int v = 0; v < mesh.num_vertices(); ++v)
    EXPECT_GE(with.cut_count(VertexId(v)), ctx.required_cuts[v]) << "vertex " << v;
  EXPECT_EQ(check_unfolding(mesh, flatten(mesh, with.states())), std::vector<std::string>{});
}

TEST(SeamMoves, TheWorkBudgetNotTheClockDecidesWhereThePassStops) {
  const Mesh mesh = load("bob_350.obj");
  const UnfoldContext ctx = make_context(mesh);
  const std::vector<LabelFit> fit = median_label_fit(mesh);
  const CutTree start = solved_tree(ctx);
  CutTree whole = start;
  const SeamMoveResult all = move_seams(whole, {}, fit, {});
  ASSERT_GT(all.moves, 4);
  SeamMoveOptions opt;
  opt.work_limit = all.work / 3;
  CutTree fast = start, slow = start;
  const SeamMoveResult f = move_seams(fast, {}, fit, opt);
  // A machine so busy that every seam tried takes a while: the same moves, the same cuts.
  opt.progress = [](long, long) { std::this_thread::sleep_for(std::chrono::milliseconds(5)); };
  const SeamMoveResult s = move_seams(slow, {}, fit, opt);
  EXPECT_LT(f.moves, all.moves) << "the budget stopped the pass early";
  EXPECT_GE(f.work, opt.work_limit);
  EXPECT_EQ(f.moves, s.moves);
  EXPECT_EQ(f.work, s.work);
  EXPECT_TRUE(fast.states() == slow.states());
  EXPECT_EQ(fast.overlap_count(), 0);
}
