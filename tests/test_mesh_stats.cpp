// Topology summary: counts, boundary loops, components and genus on built and real meshes.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>

#include "foldkit/unfold/mesh_io.hpp"
#include "foldkit/unfold/mesh_stats.hpp"
#include "test_paths.hpp"

using namespace foldkit;
using namespace foldkit::unfold;

namespace {

// A unit cube without its top: 5 squares, 10 triangles, one boundary loop.
Mesh open_box() {
  std::vector<Vec3> v{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  std::vector<std::array<int, 3>> f{{0, 2, 1}, {0, 3, 2}, {0, 1, 5}, {0, 5, 4}, {1, 2, 6},
                                    {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
  return make_mesh(v, f, "box");
}

Mesh two_tetrahedra() {
  std::vector<Vec3> v{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {5, 0, 0}, {6, 0, 0}, {5, 1, 0}, {5, 0, 1}};
  std::vector<std::array<int, 3>> f{{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2},
                                    {4, 6, 5}, {4, 5, 7}, {5, 6, 7}, {4, 7, 6}};
  return make_mesh(v, f, "two");
}

}  // namespace

TEST(MeshStats, OpenBoxHasOneBoundaryLoopAndGenusZero) {
  const MeshStats s = compute_mesh_stats(open_box());
  EXPECT_EQ(s.faces, 10);
  EXPECT_EQ(s.vertices, 8);
  EXPECT_EQ(s.edges, 17);
  EXPECT_EQ(s.boundary_edges, 4);
  EXPECT_EQ(s.boundary_loops, 1);
  EXPECT_EQ(s.components, 1);
  EXPECT_EQ(s.genus, 0);
  EXPECT_FALSE(s.closed);
  EXPECT_EQ(s.boundary_vertices, 4);
  EXPECT_EQ(s.elliptic_vertices, 4);
  EXPECT_DOUBLE_EQ(s.surface_area, 5.0);
  EXPECT_EQ(s.bbox_max.z, 1.0);
}

TEST(MeshStats, TwoTetrahedraAreTwoClosedComponents) {
  const MeshStats s = compute_mesh_stats(two_tetrahedra());
  EXPECT_EQ(s.components, 2);
  ASSERT_EQ(s.per_component.size(), 2u);
  for (const auto& c : s.per_component) {
    EXPECT_EQ(c.euler_characteristic, 2);
    EXPECT_TRUE(c.closed);
    EXPECT_EQ(c.genus, 0);
  }
  EXPECT_EQ(face_components(two_tetrahedra())[7], 1);
}

TEST(MeshStats, BundledBobIsATorusAndSpotASphere) {
  EXPECT_EQ(compute_mesh_stats(load_mesh(test::example_mesh("bob_128.obj")).mesh).genus, 1);
  const MeshStats spot = compute_mesh_stats(load_mesh(test::example_mesh("spot_128.obj")).mesh);
  EXPECT_EQ(spot.genus, 0);
  EXPECT_TRUE(spot.closed);
  EXPECT_EQ(spot.elliptic_vertices + spot.hyperbolic_vertices + spot.flat_vertices, spot.vertices);
}

TEST(MeshStats, GenusOfCorpusMeshesMatchesTheirNames) {
  if (!test::shared_meshes()) GTEST_SKIP() << "../shared/meshes not present";
  const std::map<std::string, int> genus{{"bob_350.obj", 1},
                                         {"double_torus_128.obj", 2},
                                         {"threeholes_128.obj", 3},
                                         {"spot_350.obj", 0},
                                         {"torus_128.obj", 1}};
  for (const auto& [name, g] : genus)
    EXPECT_EQ(compute_mesh_stats(load_mesh(*test::shared_meshes() / name).mesh).genus, g) << name;
}

TEST(MeshStats, AgreesWithTheCorpusManifestUpTo500Faces) {
  if (!test::shared_meshes()) GTEST_SKIP() << "../shared/meshes not present";
  std::ifstream manifest(*test::shared_meshes() / "MANIFEST.md");
  std::string line;
  int checked = 0;
  while (std::getline(manifest, line)) {
    // Rows: | file | faces | vertices | closed | genus | ...
    std::vector<std::string> cells;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, '|'))
      cells.push_back(cell);
    if (cells.size() < 6) continue;
    auto trim = [](std::string s) {
      s.erase(0, s.find_first_not_of(' '));
      s.erase(s.find_last_not_of(' ') + 1);
      return s;
    };
    const std::string file = trim(cells[1]);
    if (file.size() < 5 || file.substr(file.size() - 4) != ".obj") continue;
    const auto path = *test::shared_meshes() / file;
    if (!std::filesystem::exists(path)) continue;
    int faces = 0;
    try {
      faces = std::stoi(trim(cells[2]));
    } catch (...) {
      continue;
    }
    if (faces > 500 || trim(cells[4]) != "yes") continue;
    const MeshStats s = compute_mesh_stats(load_mesh(path).mesh);
    EXPECT_EQ(s.faces, faces) << file;
    EXPECT_EQ(s.vertices, std::stoi(trim(cells[3]))) << file;
    EXPECT_TRUE(s.closed) << file;
    EXPECT_EQ(s.genus, std::stoi(trim(cells[5]))) << file;
    ++checked;
  }
  EXPECT_GT(checked, 20);
}
