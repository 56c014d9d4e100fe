// glTF 2.0 reading (gltf_document, gltf_reader): node transforms, strips and fans, mirrored nodes,
// interleaved and normalised data, and the hostile documents that must end in one InputError line.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <set>

#include "foldkit/error.hpp"
#include "foldkit/unfold/mesh_io.hpp"
#include "mesh_fixtures.hpp"
#include "test_paths.hpp"

using namespace foldkit;
using namespace foldkit::unfold;
namespace fs = std::filesystem;
using Json = nlohmann::json;
using test::base64;
using test::signed_volume;

namespace {

template <typename T>
std::string bytes_of(const std::vector<T>& v) {
  return std::string(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
}

// A closed tetrahedron, counter-clockwise seen from outside.
const std::vector<float> kTetra{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
const std::vector<std::uint16_t> kTetraFaces{0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};

// A document with one buffer (a data URI) of positions then indices, one mesh with one primitive.
Json document(const std::vector<float>& positions, const std::vector<std::uint16_t>& indices,
              std::uint64_t mode = 4) {
  const std::string blob = bytes_of(positions) + bytes_of(indices);
  const std::size_t pos_bytes = positions.size() * 4;
  Json prim = {{"attributes", {{"POSITION", 0}}}, {"mode", mode}};
  if (!indices.empty()) prim["indices"] = 1;
  return {{"asset", {{"version", "2.0"}}},
          {"scene", 0},
          {"scenes", {{{"nodes", {0}}}}},
          {"nodes", {{{"mesh", 0}}}},
          {"meshes", {{{"primitives", {prim}}}}},
          {"buffers",
           {{{"uri", "data:application/octet-stream;base64," + base64(blob)}, {"byteLength", blob.size()}}}},
          {"bufferViews",
           {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", pos_bytes}},
            {{"buffer", 0},
             {"byteOffset", pos_bytes},
             {"byteLength", std::max<std::size_t>(1, indices.size() * 2)}}}},
          {"accessors",
           {{{"bufferView", 0}, {"componentType", 5126}, {"count", positions.size() / 3}, {"type", "VEC3"}},
            {{"bufferView", 1}, {"componentType", 5123}, {"count", indices.size()}, {"type", "SCALAR"}}}}};
}

class GltfFiles : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = test::temp_dir("gltf_reader"); }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path write(const std::string& name, const std::string& bytes) {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << bytes;
    return p;
  }
  Mesh load(const Json& doc) { return load_mesh(write("m.gltf", doc.dump())).mesh; }
  std::string error_of(const std::string& name, const std::string& bytes) {
    try {
      load_mesh(write(name, bytes));
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
  fs::path dir_;
};

struct Bounds {
  Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
};

Bounds bounds(const Mesh& m) {
  Bounds b;
  for (const Vec3& p : m.vertices) {
    b.lo = {std::min(b.lo.x, p.x), std::min(b.lo.y, p.y), std::min(b.lo.z, p.z)};
    b.hi = {std::max(b.hi.x, p.x), std::max(b.hi.y, p.y), std::max(b.hi.z, p.z)};
  }
  return b;
}

}  // namespace

TEST_F(GltfFiles, NodeTransformsComposeFromTheRootDown) {
  Json doc = document(kTetra, kTetraFaces);
  // Root turns a quarter about z, its child moves by +10 along x in the root's frame (so +10 along y).
  const double h = std::sqrt(0.5);
  doc["nodes"] = {{{"rotation", {0, 0, h, h}}, {"children", {1}}},
                  {{"translation", {10, 0, 0}}, {"mesh", 0}}};
  const Bounds b = bounds(load(doc));
  EXPECT_NEAR(b.lo.x, -1, 1e-6);
  EXPECT_NEAR(b.hi.x, 0, 1e-6);
  EXPECT_NEAR(b.lo.y, 10, 1e-6);
  EXPECT_NEAR(b.hi.y, 11, 1e-6);
}

// Open surfaces: a closed mesh is turned outward by the repairs anyway, an open one keeps the file's side.
TEST_F(GltfFiles, AMirroringNodeKeepsTheFrontOfAnOpenSurfaceOnTheSameSide) {
  Json doc = document({0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 1, 2});
  doc["nodes"][0]["scale"] = {-2, 1, 1};
  const Mesh m = load(doc);
  ASSERT_EQ(m.num_faces(), 1);
  EXPECT_GT(face_normal(m, 0).z, 0.99);
  EXPECT_NEAR(bounds(m).lo.x, -2, 1e-6);
}

TEST_F(GltfFiles, FansAndStripsWindTheirTrianglesAsTheSpecificationSays) {
  // An open square pyramid: the four sides as a fan around the apex (fronts up and out) ...
  const std::vector<float> p{0, 0, 1, -1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
  const Mesh sides = load(document(p, {0, 1, 2, 3, 4, 1}, 6));
  ASSERT_EQ(sides.num_faces(), 4);
  for (int f = 0; f < 4; ++f)
    EXPECT_GT(face_normal(sides, f).z, 0.1) << f;
  // ... and its base as a strip, front down.
  const Mesh base = load(document(p, {1, 4, 2, 3}, 5));
  ASSERT_EQ(base.num_faces(), 2);
  for (int f = 0; f < 2; ++f)
    EXPECT_LT(face_normal(base, f).z, -0.99) << f;
}

TEST_F(GltfFiles, InterleavedPositionsAndNormalisedByteCoordinatesAreRead) {
  Json doc = document(kTetra, kTetraFaces);
  // Positions interleaved with 4 padding bytes (stride 16), coordinates as normalised bytes.
  std::string inter;
  for (std::size_t v = 0; v < 4; ++v) {
    inter += std::string(reinterpret_cast<const char*>(&kTetra[v * 3]), 12);
    inter += std::string(4, '\x7f');
  }
  const std::string uv{'\x00', '\x00', '\xff', '\x00', '\x00', '\xff', '\xff', '\xff'};
  const std::string blob = inter + bytes_of(kTetraFaces) + uv;
  doc["buffers"][0] = {{"uri", "data:application/octet-stream;base64," + base64(blob)},
                       {"byteLength", blob.size()}};
  doc["bufferViews"] = {{{"buffer", 0}, {"byteLength", 64}, {"byteStride", 16}},
                        {{"buffer", 0}, {"byteOffset", 64}, {"byteLength", 24}},
                        {{"buffer", 0}, {"byteOffset", 88}, {"byteLength", 8}}};
  doc["accessors"].push_back(
      {{"bufferView", 2}, {"componentType", 5121}, {"normalized", true}, {"count", 4}, {"type", "VEC2"}});
  doc["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = 2;
  const Mesh m = load(doc);
  EXPECT_EQ(m.num_faces(), 4);
  EXPECT_NEAR(signed_volume(m), 1.0 / 6, 1e-9);
  ASSERT_EQ(m.face_uv.size(), 4u);
  // Vertex 1 has (u, v) = (1, 0) in glTF terms, (1, 1) with v running up.
  for (int f = 0; f < m.num_faces(); ++f)
    for (int i = 0; i < 3; ++i)
      if (m.vertices[m.faces[f][i]].x == 1) {
        EXPECT_NEAR(m.face_uv[f][i].x, 1, 1e-9);
        EXPECT_NEAR(m.face_uv[f][i].y, 1, 1e-9);
      }
}

TEST_F(GltfFiles, HostileDocumentsEndInOneLineNamingTheProblem) {
  const Json good = document(kTetra, kTetraFaces);
  const auto with = [&](const std::function<void(Json&)>& change) {
    Json d = good;
    change(d);
    return d.dump();
  };
  const std::vector<std::pair<std::string, std::string>> cases{
      {"deep nesting", std::string(100000, '[') + std::string(100000, ']')},
      {"version 1", with([](Json& d) { d["asset"]["version"] = "1.0"; })},
      {"version as a number", with([](Json& d) { d["asset"]["version"] = 2; })},
      {"extension names as numbers", with([](Json& d) { d["extensionsRequired"] = {1}; })},
      {"node cycle", with([](Json& d) {
         d["nodes"] = {{{"children", {1}}}, {{"children", {0}}, {"mesh", 0}}};
       })},
      {"node its own child", with([](Json& d) { d["nodes"][0]["children"] = {0}; })},
      {"huge count", with([](Json& d) { d["accessors"][1]["count"] = 4294967295u; })},
      {"negative index", with([](Json& d) { d["meshes"][0]["primitives"][0]["indices"] = -1; })},
      {"index out of range",
       with([](Json& d) { d["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 9; })},
      {"view past its buffer", with([](Json& d) { d["bufferViews"][0]["byteOffset"] = 1u << 31; })},
      {"byteLength over the data", with([](Json& d) { d["buffers"][0]["byteLength"] = 1u << 30; })},
      {"absolute buffer path", with([](Json& d) { d["buffers"][0]["uri"] = "/etc/hostname"; })},
      {"other scheme", with([](Json& d) { d["buffers"][0]["uri"] = "http://example.com/a.bin"; })},
      {"bad base64", with([](Json& d) { d["buffers"][0]["uri"] = "data:;base64,@@@@"; })},
      {"sparse accessor", with([](Json& d) { d["accessors"][0]["sparse"] = Json::object(); })},
      {"integer positions", with([](Json& d) { d["accessors"][0]["componentType"] = 5123; })},
      {"unknown mode", with([](Json& d) { d["meshes"][0]["primitives"][0]["mode"] = 9; })},
      {"vertex index past the positions", with([](Json& d) { d["accessors"][0]["count"] = 2; })},
      {"primitives not an array", with([](Json& d) { d["meshes"][0]["primitives"] = 7; })},
      {"matrix of strings", with([](Json& d) { d["nodes"][0]["matrix"] = Json::array({"a"}); })},
  };
  for (const auto& [what, bytes] : cases) {
    const std::string error = error_of("hostile.gltf", bytes);
    EXPECT_FALSE(error.empty()) << what;
    EXPECT_EQ(error.find('\n'), std::string::npos) << what << ": " << error;
    EXPECT_NE(error.find("hostile.gltf"), std::string::npos) << what << ": " << error;
  }
}

TEST_F(GltfFiles, AGlbWhoseChunksLieAboutTheirLengthIsRefused) {
  const std::string json = document(kTetra, kTetraFaces).dump();
  const auto glb = [&](std::uint32_t total, std::uint32_t chunk) {
    std::string out = "glTF";
    const std::uint32_t header[] = {2, total, chunk, 0x4E4F534A};
    out.append(reinterpret_cast<const char*>(header), sizeof header);
    return out + json;
  };
  const auto size = static_cast<std::uint32_t>(20 + json.size());
  EXPECT_NO_THROW(load_mesh(write("ok.glb", glb(size, static_cast<std::uint32_t>(json.size())))));
  for (const auto& [total, chunk] : std::vector<std::pair<std::uint32_t, std::uint32_t>>{
           {size + 1, static_cast<std::uint32_t>(json.size())},
           {size, 0xFFFFFFF0u},
           {0x8C000000u, 0x8C000000u}}) {
    const std::string error = error_of("lie.glb", glb(total, chunk));
    EXPECT_NE(error.find("GLB"), std::string::npos) << error;
  }
}

TEST_F(GltfFiles, ANodeInstancedOverTheFaceLimitIsRefusedBeforeItsTrianglesAreHeld) {
  Json doc = document(kTetra, kTetraFaces);
  Json nodes = Json::array();
  for (int i = 0; i < 1000; ++i)
    nodes.push_back({{"mesh", 0}, {"translation", {3 * i, 0, 0}}});
  Json roots = Json::array();
  for (int i = 0; i < 1000; ++i)
    roots.push_back(i);
  doc["nodes"] = nodes;
  doc["scenes"][0]["nodes"] = roots;
  LoadOptions options;
  options.face_limit = 3000;
  try {
    load_mesh(write("many.gltf", doc.dump()), options);
    FAIL() << "4,000 triangles loaded under a limit of 3,000";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("3000"), std::string::npos) << e.what();
  }
}

// A second source: Blender 3.4's exporter wrote examples/spot_textured/spot_blender.glb from the OBJ
// beside it. Every corner it has (where it is, where it samples the texture) must be a corner of the OBJ:
// a V not flipped, a transform misapplied or an index misread would move corners off the OBJ's.
TEST(GltfSecondSource, BlendersSpotHasTheObjsCornersAndTexture) {
  const fs::path glb = test::example_mesh("spot_textured/spot_blender.glb");
  const fs::path obj = test::example_mesh("spot_textured/spot_control_mesh.obj");
  ASSERT_TRUE(fs::exists(glb)) << glb;
  const Mesh g = load_mesh(glb).mesh;
  const Mesh o = load_mesh(obj).mesh;
  ASSERT_EQ(g.num_faces(), o.num_faces());
  ASSERT_EQ(g.num_vertices(), o.num_vertices());
  ASSERT_EQ(g.materials.size(), 1u);
  EXPECT_TRUE(g.materials[0].texture_found);
  EXPECT_EQ(g.materials[0].texture_width_px, o.materials[0].texture_width_px);
  ASSERT_EQ(g.face_uv.size(), static_cast<std::size_t>(g.num_faces()));
  const auto key = [](Vec3 p, Vec2 uv) {
    const auto q = [](double x) { return std::lround(x * 1e4); };
    return std::array<long, 5>{q(p.x), q(p.y), q(p.z), q(uv.x), q(uv.y)};
  };
  std::set<std::array<long, 5>> obj_corners;
  for (int f = 0; f < o.num_faces(); ++f)
    for (int i = 0; i < 3; ++i)
      obj_corners.insert(key(o.vertices[o.faces[f][i]], o.face_uv[f][i]));
  int missing = 0;
  for (int f = 0; f < g.num_faces(); ++f)
    for (int i = 0; i < 3; ++i)
      missing += !obj_corners.count(key(g.vertices[g.faces[f][i]], g.face_uv[f][i]));
  EXPECT_EQ(missing, 0) << "of " << 3 * g.num_faces() << " corners";
}
