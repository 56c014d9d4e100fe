// `foldkit unfold MESH -o net.obj`: the written net keeps face order, is flat, congruent, unmirrored,
// grouped by piece with no vertex shared between pieces.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "foldkit/geom/predicates.hpp"
#include "foldkit/unfold/mesh_io.hpp"
#include "test_paths.hpp"

using namespace foldkit;
namespace fs = std::filesystem;

namespace {

struct Net {
  std::vector<Vec3> v;
  std::vector<std::array<int, 3>> f;  // 0-based
  std::vector<int> group_of_face;
};

Net read_net(const fs::path& path) {
  Net net;
  std::ifstream in(path);
  std::string line;
  int group = -1;
  std::map<std::string, int> groups;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string tag;
    s >> tag;
    if (tag == "v") {
      Vec3 p;
      s >> p.x >> p.y >> p.z;
      net.v.push_back(p);
    } else if (tag == "g") {
      std::string name;
      s >> name;
      group = groups.emplace(name, static_cast<int>(groups.size())).first->second;
    } else if (tag == "f") {
      std::array<int, 3> f{};
      s >> f[0] >> f[1] >> f[2];
      for (int& i : f)
        --i;
      net.f.push_back(f);
      net.group_of_face.push_back(group);
    }
  }
  return net;
}

}  // namespace

TEST(CliUnfold, TheNetKeepsFaceOrderAndIsFlatCongruentAndUnmirrored) {
  const fs::path dir = test::temp_dir("cli_unfold");
  const fs::path mesh_file = test::example_mesh("penguin_500.obj");
  auto run = test::run_foldkit({"unfold", mesh_file.string(), "-o", (dir / "net.obj").string(), "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  auto summary = nlohmann::json::parse(run.out);
  unfold::Mesh mesh = unfold::load_mesh(mesh_file).mesh;
  EXPECT_EQ(summary["faces"], mesh.num_faces());
  EXPECT_GE(summary["pieces"].get<int>(), 1);
  EXPECT_GT(summary["cut_edges"].get<int>(), 0);
  EXPECT_TRUE(summary.contains("seconds"));

  Net net = read_net(dir / "net.obj");
  ASSERT_EQ(net.f.size(), mesh.faces.size());
  std::set<int> groups(net.group_of_face.begin(), net.group_of_face.end());
  EXPECT_EQ(static_cast<int>(groups.size()), summary["pieces"].get<int>());
  std::vector<int> group_of_vertex(net.v.size(), -1);
  for (std::size_t k = 0; k < net.f.size(); ++k) {
    auto c = mesh.corners(static_cast<int>(k));
    Triangle2 t;
    for (int i = 0; i < 3; ++i) {
      const Vec3& p = net.v[net.f[k][i]];
      EXPECT_EQ(p.z, 0.0);
      t[i] = {p.x, p.y};
      int& g = group_of_vertex[net.f[k][i]];
      EXPECT_TRUE(g < 0 || g == net.group_of_face[k]) << "vertex shared between pieces";
      g = net.group_of_face[k];
    }
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(norm(t[(i + 1) % 3] - t[i]), norm(c[(i + 1) % 3] - c[i]),
                  1e-9 * norm(c[(i + 1) % 3] - c[i]));
    EXPECT_GT(signed_area(t), 0) << "face " << k << " mirrored";
  }
  // Corners joined by folds share a vertex: far fewer vertices than three per face.
  EXPECT_LT(net.v.size(), net.f.size() * 2);
}

TEST(CliUnfold, ABadMeshGivesOneLineAndNoOutputFile) {
  const fs::path dir = test::temp_dir("cli_unfold_bad");
  std::ofstream(dir / "broken.obj") << "v 0 0 0\nv 1 0 0\nf 1 2 3\n";
  auto run = test::run_foldkit({"unfold", (dir / "broken.obj").string(), "-o", (dir / "net.obj").string()});
  EXPECT_EQ(run.exit_code, 3) << run.err;
  EXPECT_FALSE(run.signalled);
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  EXPECT_FALSE(fs::exists(dir / "net.obj"));
}

TEST(CliUnfold, EveryTrickyMeshUnfolds) {
  auto shared = test::shared_meshes();
  if (!shared) GTEST_SKIP() << "../shared/meshes not present";
  for (const auto& entry : fs::directory_iterator(*shared / "tricky")) {
    auto run = test::run_foldkit({"unfold", entry.path().string(), "--json", "--method", "mst"});
    EXPECT_EQ(run.exit_code, 0) << entry.path() << ": " << run.err;
  }
}

TEST(CliUnfold, SeamListsUseTheFilesOwnVertexNumbers) {
  const fs::path dir = test::temp_dir("cli-seams");
  const std::string mesh = test::example_mesh("bob_128.obj").string();
  // The first face of bob_128.obj as written, 1-based: all three of its edges are edges of the file.
  std::ifstream in(mesh);
  std::string line;
  while (std::getline(in, line) && line.rfind("f ", 0) != 0) {
  }
  std::istringstream face(line.substr(2));
  int a = 0, b = 0, c = 0;
  face >> a >> b >> c;
  std::ofstream(dir / "cut.txt") << a << " " << b << "\n" << b << " " << c << "\n";
  auto run = test::run_foldkit({"unfold", mesh, "-o", (dir / "net.obj").string(), "--cut",
                                (dir / "cut.txt").string(), "--json", "-q"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  // Counted from 0, the same numbers name other vertices: not edges of the file, refused with exit 3.
  run = test::run_foldkit({"unfold", mesh, "-o", (dir / "net2.obj").string(), "--cut",
                           (dir / "cut.txt").string(), "--index-base", "0", "-q"});
  EXPECT_EQ(run.exit_code, 3) << run.err;
  EXPECT_NE(run.err.find("cut.txt: line 1: " + std::to_string(a) + "-" + std::to_string(b) + " is not an edge of"),
            std::string::npos)
      << run.err;
  EXPECT_FALSE(fs::exists(dir / "net2.obj"));
}
