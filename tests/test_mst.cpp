// The [SP05] baseline on real meshes: every result satisfies the unfolding invariants.
#include <gtest/gtest.h>

#include <filesystem>

#include "foldkit/error.hpp"
#include "foldkit/unfold/mesh_io.hpp"
#include "foldkit/unfold/mst.hpp"
#include "foldkit/unfold/overlap.hpp"
#include "test_paths.hpp"

using namespace foldkit;
using namespace foldkit::unfold;
namespace fs = std::filesystem;

namespace {

// Every face in exactly one piece, every glued seam has exactly one partner edge (the other side of
// the same mesh edge, in a face that exists), and check_unfolding finds nothing.
void expect_valid(const Mesh& mesh, const Unfolding& u) {
  ASSERT_EQ(u.num_faces(), mesh.num_faces());
  std::vector<int> count(u.piece_count, 0);
  for (int p : u.piece_of_face) {
    ASSERT_GE(p, 0);
    ASSERT_LT(p, u.piece_count);
    ++count[p];
  }
  for (int c : count)
    EXPECT_GT(c, 0);
  std::vector<int> sides(mesh.edges.size(), 0);
  for (int f = 0; f < mesh.num_faces(); ++f)
    for (int e : u.face_edges[f])
      ++sides[e];
  for (int e = 0; e < mesh.num_edges(); ++e)
    EXPECT_EQ(sides[e], u.edges[e].boundary() ? 1 : 2) << mesh.name << " edge " << e;
  auto problems = check_unfolding(mesh, u);
  EXPECT_TRUE(problems.empty()) << mesh.name << ": " << problems.front();
}

}  // namespace

TEST(Mst, ExampleMeshesUnfoldWithoutOverlapsIntoFewPieces) {
  for (const char* name :
       {"spot_128.obj", "spot_350.obj", "fish_350.obj", "bob_350.obj", "penguin_500.obj"}) {
    Mesh mesh = load_mesh(test::example_mesh(name)).mesh;
    Unfolding u = unfold_mst(mesh);
    expect_valid(mesh, u);
    EXPECT_LT(u.piece_count, mesh.num_faces() / 8) << name;
  }
}

TEST(Mst, ForcedFoldsThatOverlapAreAClearError) {
  Mesh mesh = load_mesh(test::example_mesh("spot_350.obj")).mesh;
  EdgeConstraints keep_all;
  keep_all.rule.assign(mesh.num_edges(), EdgeRule::Free);
  auto tree = spanning_forest(mesh, min_perimeter_weights(mesh));
  for (EdgeId e : all_ids<EdgeId>(mesh.num_edges()))
    if (tree[e] == EdgeState::Fold) keep_all.rule[e] = EdgeRule::MustFold;
  EXPECT_THROW(unfold_mst(mesh, keep_all), Error);
}

TEST(Mst, FoldPathJoinsTwoFacesThroughFoldEdgesOnly) {
  Mesh mesh = load_mesh(test::example_mesh("bob_128.obj")).mesh;
  auto cut = spanning_forest(mesh, min_perimeter_weights(mesh));
  FoldForest forest = fold_forest(mesh, cut);
  auto path = fold_path(forest, 3, 100);
  ASSERT_FALSE(path.empty());
  int at = 3;
  for (EdgeId e : path) {
    ASSERT_EQ(cut[e], EdgeState::Fold);
    const MeshEdge& me = mesh.edge(e);
    ASSERT_TRUE(me.face[0] == at || me.face[1] == at);
    at = me.face[0] == at ? me.face[1] : me.face[0];
  }
  EXPECT_EQ(at, 100);
}

TEST(Mst, EveryCorpusMeshUpTo2000FacesAndEveryTrickyMeshUnfoldsValidly) {
  auto shared = test::shared_meshes();
  if (!shared) GTEST_SKIP() << "../shared/meshes not present: corpus sweep skipped";
  std::vector<fs::path> files = test::corpus_meshes(2000);
  for (const auto& entry : fs::directory_iterator(*shared / "tricky"))
    files.push_back(entry.path());
  ASSERT_GT(files.size(), 50u);
  for (const auto& file : files) {
    SCOPED_TRACE(file.string());
    Mesh mesh = load_mesh(file).mesh;
    expect_valid(mesh, unfold_mst(mesh));
  }
}
