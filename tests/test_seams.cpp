// Seams chosen by the user: edge lists are read strictly, and unfold_mesh honours them.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

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
  auto edges = read_edge_list(write("# seams\n1 2\n\n3,4  # back\n"), 1);
  ASSERT_EQ(edges.size(), 2u);
  EXPECT_EQ(edges[1].v, (std::array<int, 2>{2, 3})) << "1-based as written, 0-based inside";
  EXPECT_EQ(edges[1].line, 4);
  EXPECT_EQ(read_edge_list(write("0 5\n"), 0)[0].v, (std::array<int, 2>{0, 5}));
}

TEST(Seams, AMalformedLineIsAnInputErrorNamingTheFileAndLine) {
  auto path = write("1 2\n3 x\n");
  try {
    read_edge_list(path, 1);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path.string());
    EXPECT_NE(std::string(e.what()).find("line 2"), std::string::npos) << e.what();
  }
  EXPECT_THROW(read_edge_list(write("1 2 3\n"), 1), InputError);
  EXPECT_THROW(read_edge_list(write("-1 2\n"), 0), InputError);
  EXPECT_THROW(read_edge_list(write("0 2\n"), 1), InputError) << "no vertex 0 when counting from 1";
  EXPECT_THROW(read_edge_list("/nonexistent/edges.txt", 1), InputError);
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
  try {
    resolve_seams(mesh, both);
    FAIL() << "an edge both cut and kept was accepted";
  } catch (const SeamError& e) {
    EXPECT_EQ(e.exit_code(), ExitCode::Usage);
    EXPECT_EQ(std::string(e.what()).find("--"), std::string::npos)
        << "the library names no flag: " << e.what();
    EXPECT_EQ(e.message({"--cut", "--keep"}), "edge " + std::to_string(mesh.edges[5].v[0]) + "-" +
                                                  std::to_string(mesh.edges[5].v[1]) +
                                                  " is both in --cut and in --keep");
  }
}

TEST(Seams, AnEdgeListMustBeARegularFileOfBoundedSize) {
  // `--cut /dev/zero` grew memory at about 1 GB per 3 s (issue 10).
  try {
    read_edge_list("/dev/zero", 1);
    FAIL() << "read /dev/zero";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "/dev/zero: not a regular file");
  }
  const auto big = test::temp_dir("seams") / "big.txt";
  std::ofstream(big) << "# sparse\n";
  std::filesystem::resize_file(big, std::uintmax_t{65} << 20);
  try {
    read_edge_list(big, 1);
    FAIL() << "read a 65 MB edge list";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("over the limit of 67108864 bytes"), std::string::npos) << e.what();
  }
  std::filesystem::remove(big);
}

namespace {

// The polygons of an OBJ or OFF file exactly as written (0-based vertex indices), read independently of
// the loader, and its vertex positions.
struct FileFaces {
  std::vector<Vec3> vertices;
  std::vector<std::vector<int>> polygons;
};

FileFaces read_file_faces(const std::filesystem::path& path) {
  FileFaces f;
  std::ifstream in(path);
  std::string line;
  const bool off = path.extension() == ".off";
  if (off) {
    std::getline(in, line);  // OFF
    int nv = 0, nf = 0, ne = 0;
    in >> nv >> nf >> ne;
    f.vertices.resize(nv);
    for (Vec3& p : f.vertices)
      in >> p.x >> p.y >> p.z;
    f.polygons.resize(nf);
    for (auto& poly : f.polygons) {
      int k = 0;
      in >> k;
      poly.resize(k);
      for (int& v : poly)
        in >> v;
    }
    return f;
  }
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::string tag;
    ls >> tag;
    if (tag == "v") {
      Vec3 p;
      ls >> p.x >> p.y >> p.z;
      f.vertices.push_back(p);
    } else if (tag == "f") {
      std::vector<int> poly;
      for (std::string corner; ls >> corner;)
        poly.push_back(std::stoi(corner) - 1);
      f.polygons.push_back(poly);
    }
  }
  return f;
}

// Every edge of the file's polygons, named by the file's numbers, maps onto mesh edges whose ends sit
// where the file puts those two vertices.
void expect_every_file_edge_maps_onto_the_same_edge(const std::filesystem::path& path) {
  SCOPED_TRACE(path.string());
  const LoadedMesh loaded = load_mesh(path);
  const FileFaces file = read_file_faces(path);
  std::vector<FileEdge> edges;
  for (const auto& poly : file.polygons)
    for (std::size_t i = 0; i < poly.size(); ++i)
      edges.push_back({{poly[i], poly[(i + 1) % poly.size()]}, static_cast<int>(edges.size() + 1)});
  ASSERT_GT(edges.size(), 100u);
  EXPECT_GE(to_mesh_edges(loaded, edges, "edges.txt", loaded.index_base).size(), edges.size());
  for (const FileEdge& named : edges) {
    const auto mapped = to_mesh_edges(loaded, {named}, "edges.txt", loaded.index_base);
    ASSERT_FALSE(mapped.empty());
    for (const auto& m : mapped) {
      const Vec3 a = file.vertices[named.v[0]], b = file.vertices[named.v[1]];
      const Vec3 p = loaded.mesh.vertices[m[0]], q = loaded.mesh.vertices[m[1]];
      const bool same =
          (norm(a - p) < 1e-5 && norm(b - q) < 1e-5) || (norm(a - q) < 1e-5 && norm(b - p) < 1e-5);
      ASSERT_TRUE(same) << "file edge " << named.v[0] << "-" << named.v[1] << " (0-based)";
    }
  }
}

}  // namespace

TEST(Seams, EveryEdgeOfARealMeshNamedByTheFilesNumbersIsThatEdge) {
  // The loader renumbers vertices by first use: read in its numbering, 34 of bunny_128's 40 real edges
  // were refused and pairs that are no edge of the file were accepted and cut (issue 10).
  expect_every_file_edge_maps_onto_the_same_edge(test::example_mesh("bob_128.obj"));
  expect_every_file_edge_maps_onto_the_same_edge(test::example_mesh("spot_350.obj"));
  const auto corpus = test::shared_meshes();
  if (!corpus) GTEST_SKIP() << "bunny_128 and the 0-based OFF seed bunny need the shared corpus (../shared)";
  expect_every_file_edge_maps_onto_the_same_edge(*corpus / "bunny_128.obj");
  expect_every_file_edge_maps_onto_the_same_edge(*corpus / "seedbunny_128.off");
}

TEST(Seams, APairThatIsNotAnEdgeOfTheFileIsAnInputErrorNamingTheLineInTheFilesNumbers) {
  const LoadedMesh loaded = load_mesh(test::example_mesh("bob_128.obj"));
  const FileFaces file = read_file_faces(test::example_mesh("bob_128.obj"));
  // Vertex 1 and the vertex farthest from it cannot share an edge.
  int far = 0;
  for (int v = 0; v < static_cast<int>(file.vertices.size()); ++v)
    if (norm(file.vertices[v] - file.vertices[0]) > norm(file.vertices[far] - file.vertices[0])) far = v;
  const auto list = write("# first line\n" + std::to_string(file.polygons[0][0] + 1) + " " +
                          std::to_string(file.polygons[0][1] + 1) + "\n1 " + std::to_string(far + 1) + "\n");
  const auto edges = read_edge_list(list, 1);
  try {
    to_mesh_edges(loaded, edges, list.string(), 1);
    FAIL() << "accepted a pair that is no edge";
  } catch (const InputError& e) {
    EXPECT_EQ(e.exit_code(), ExitCode::Input);
    EXPECT_EQ(std::string(e.what()), list.string() + ": line 3: 1-" + std::to_string(far + 1) +
                                         " is not an edge of " + test::example_mesh("bob_128.obj").string());
  }
}

TEST(Seams, ADiagonalOfAFileQuadIsNotAnEdgeOfTheFile) {
  // Triangulation adds the diagonal to the mesh; the user can name only what the file has.
  const auto dir = test::temp_dir("seams-quad");
  const auto path = dir / "box.obj";
  std::ofstream(path) << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                         "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";
  const LoadedMesh loaded = load_mesh(path);
  EXPECT_EQ(to_mesh_edges(loaded, {{{0, 1}, 1}}, "e.txt", 1).size(), 1u);
  for (const auto& pair : {std::array{0, 2}, std::array{1, 3}}) {
    try {
      to_mesh_edges(loaded, {{pair, 1}}, "e.txt", 1);
      ADD_FAILURE() << "diagonal " << pair[0] << "-" << pair[1] << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("is not an edge of"), std::string::npos) << e.what();
    }
  }
}

TEST(Seams, ObjLineElementsInTheMeshFileAreReadAsSeams) {
  // bob_128 with an `l` polyline along the first face's edges and one more file edge.
  std::ifstream in(test::example_mesh("bob_128.obj"));
  std::string text((std::istreambuf_iterator<char>(in)), {});
  const FileFaces file = read_file_faces(test::example_mesh("bob_128.obj"));
  const auto& f0 = file.polygons[0];
  const auto& f5 = file.polygons[5];
  text += "l " + std::to_string(f0[0] + 1) + " " + std::to_string(f0[1] + 1) + " " +
          std::to_string(f0[2] + 1) + "\n";
  text += "l " + std::to_string(f5[0] + 1) + "/1 " + std::to_string(f5[1] + 1) + "/2\n";
  const auto path = test::temp_dir("seams-l") / "bob_l.obj";
  std::ofstream(path) << text;
  const LoadedMesh loaded = load_mesh(path);
  ASSERT_EQ(loaded.file_seams.size(), 3u);
  EXPECT_EQ(loaded.file_seams[0].v, (std::array{f0[0], f0[1]}));
  EXPECT_EQ(loaded.file_seams[2].v, (std::array{f5[0], f5[1]}));
  UnfoldOptions options;
  options.method = Method::Mst;
  options.seams.force_cut = to_mesh_edges(loaded, loaded.file_seams, path.string(), 1);
  const UnfoldResult r = unfold_mesh(loaded.mesh, options);
  const EdgeConstraints constraints = resolve_seams(loaded.mesh, options.seams);
  int cut = 0;
  for (int e = 0; e < loaded.mesh.num_edges(); ++e)
    if (constraints.cut(EdgeId(e))) {
      EXPECT_TRUE(r.unfolding.edges[e].cut) << e;
      ++cut;
    }
  EXPECT_EQ(cut, 3);
  EXPECT_TRUE(check_unfolding(loaded.mesh, r.unfolding).empty());
}

TEST(Seams, ALineElementThatIsNoEdgeIsRefusedWithTheMeshFileAndLine) {
  const auto path = test::temp_dir("seams-l-bad") / "tet.obj";
  std::ofstream(path) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\nl 1 5\n";
  EXPECT_THROW(load_mesh(path), InputError) << "vertex 5 does not exist";
  std::ofstream(path)
      << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 5 5 5\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\nl 1 5\n";
  const LoadedMesh loaded = load_mesh(path);
  try {
    to_mesh_edges(loaded, loaded.file_seams, path.string(), 1);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), path.string() + ": line 10: 1-5 is not an edge of " + path.string());
  }
}
