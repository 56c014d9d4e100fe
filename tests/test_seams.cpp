// Seams chosen by the user: edge lists are read strictly, and unfold_mesh honours them.
#include <gtest/gtest.h>

#include <fstream>

#include "foldkit/error.hpp"
#include "foldkit/unfold/mesh_io.hpp"
#include "foldkit/unfold/seams.hpp"
#include "foldkit/unfold/unfold.hpp"
#include "test_paths.hpp"

using namespace foldkit;
using namespace foldkit::unfold;

namespace {
std::filesystem::path write(const std::string& text) {
  auto path = test::temp_dir("seams") / "edges.txt";
  std::ofstream(path) << text;
  return path;
}
}  // namespace

TEST(Seams, AnEdgeListAllowsCommentsBlankLinesAndCommas) {
  auto edges = read_edge_list(write("# seams\n1 2\n\n3,4  # back\n"));
  ASSERT_EQ(edges.size(), 2u);
  EXPECT_EQ(edges[1], (std::array<int, 2>{3, 4}));
}

TEST(Seams, AMalformedLineIsAnInputErrorNamingTheFileAndLine) {
  auto path = write("1 2\n3 x\n");
  try {
    read_edge_list(path);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path.string());
    EXPECT_NE(std::string(e.what()).find("line 2"), std::string::npos) << e.what();
  }
  EXPECT_THROW(read_edge_list(write("1 2 3\n")), InputError);
  EXPECT_THROW(read_edge_list(write("-1 2\n")), InputError);
  EXPECT_THROW(read_edge_list("/nonexistent/edges.txt"), InputError);
}

TEST(Seams, ForcedCutsStayCutAndKeptEdgesStayFolded) {
  Mesh mesh = load_mesh(test::example_mesh("spot_350.obj")).mesh;
  UnfoldOptions options;
  options.method = Method::Mst;
  // Cut a few long edges (the minimum-perimeter tree would fold them) and keep a few short ones.
  for (int e = 0; e < 30; e += 3)
    options.seams.force_cut.push_back(mesh.edges[e].v);
  options.seams.forbid_cut.push_back(mesh.edges[1].v);
  options.seams.forbid_cut.push_back(mesh.edges[4].v);
  UnfoldResult r = unfold_mesh(mesh, options);
  for (int e = 0; e < 30; e += 3)
    EXPECT_TRUE(r.unfolding.edges[e].cut) << e;
  EXPECT_FALSE(r.unfolding.edges[1].cut);
  EXPECT_FALSE(r.unfolding.edges[4].cut);
  EXPECT_TRUE(check_unfolding(mesh, r.unfolding).empty());
}

TEST(Seams, ImpossibleSeamsAreUsageErrors) {
  Mesh mesh = load_mesh(test::example_mesh("spot_128.obj")).mesh;
  SeamConstraints not_an_edge;
  not_an_edge.force_cut.push_back({0, 0});
  EXPECT_THROW(resolve_seams(mesh, not_an_edge), Error);
  SeamConstraints both;
  both.force_cut.push_back(mesh.edges[5].v);
  both.forbid_cut.push_back(mesh.edges[5].v);
  EXPECT_THROW(resolve_seams(mesh, both), Error);
  SeamConstraints loop;  // every edge around vertex 0 kept: a closed ring of folds
  for (const MeshEdge& e : mesh.edges)
    if (e.v[0] == 0 || e.v[1] == 0) loop.forbid_cut.push_back(e.v);
  EXPECT_THROW(resolve_seams(mesh, loop), Error);
  SeamConstraints out_of_range;
  out_of_range.forbid_cut.push_back({1, 1'000'000});
  EXPECT_THROW(resolve_seams(mesh, out_of_range), Error);
}

TEST(Seams, AnEdgeListMustBeARegularFileOfBoundedSize) {
  // `--cut /dev/zero` grew memory at about 1 GB per 3 s (issue 10).
  try {
    read_edge_list("/dev/zero");
    FAIL() << "read /dev/zero";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "/dev/zero: not a regular file");
  }
  const auto big = test::temp_dir("seams") / "big.txt";
  std::ofstream(big) << "# sparse\n";
  std::filesystem::resize_file(big, std::uintmax_t{65} << 20);
  try {
    read_edge_list(big);
    FAIL() << "read a 65 MB edge list";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("over the limit of 67108864 bytes"), std::string::npos) << e.what();
  }
  std::filesystem::remove(big);
}
