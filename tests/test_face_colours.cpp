// Colour and texture loading (face_colours, gltf_reader): the same textured cube as OBJ+MTL, quads,
// .gltf and .glb loads with the same faces, texture coordinates and colours; missing images, PLY
// colours, and glTF files that must be refused like any other mesh.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>

#include "foldkit/error.hpp"
#include "foldkit/unfold/mesh_io.hpp"
#include "mesh_fixtures.hpp"
#include "test_paths.hpp"

using namespace foldkit;
using namespace foldkit::unfold;
namespace fs = std::filesystem;

namespace {

fs::path colour_data(const std::string& name) {
  return test::source_dir() / "tests/data/colour" / name;
}

fs::path write(const fs::path& dir, const std::string& name, const std::string& bytes) {
  fs::path p = dir / name;
  std::ofstream(p, std::ios::binary) << bytes;
  return p;
}

// A face corner's key: where it is and which way its face looks (the cube's corners are shared by
// three faces with different texture coordinates).
using CornerKey = std::array<long, 6>;
CornerKey corner_key(const Mesh& m, int f, int i) {
  const Vec3 p = m.vertices[m.faces[f][i]];
  const Vec3 a = m.vertices[m.faces[f][0]], b = m.vertices[m.faces[f][1]], c = m.vertices[m.faces[f][2]];
  const Vec3 n = normalized(cross(b - a, c - a));
  auto q = [](double x) { return std::lround(x * 1e5); };
  return {q(p.x), q(p.y), q(p.z), q(n.x), q(n.y), q(n.z)};
}

struct CornerInfo {
  Vec2 uv;
  Colour colour;
  bool textured = false;
};

std::map<CornerKey, CornerInfo> corners_of(const Mesh& m) {
  std::map<CornerKey, CornerInfo> out;
  for (int f = 0; f < m.num_faces(); ++f) {
    const Material& mat = m.materials.at(m.face_material.at(f));
    for (int i = 0; i < 3; ++i)
      out[corner_key(m, f, i)] = {m.face_uv.at(f)[i], mat.colour, mat.texture_found};
  }
  return out;
}

void expect_same_colours(const Mesh& a, const Mesh& b) {
  ASSERT_EQ(a.num_faces(), b.num_faces());
  ASSERT_EQ(a.face_uv.size(), a.faces.size());
  ASSERT_EQ(b.face_uv.size(), b.faces.size());
  const auto ca = corners_of(a), cb = corners_of(b);
  ASSERT_EQ(ca.size(), cb.size());
  for (const auto& [key, info] : ca) {
    ASSERT_TRUE(cb.count(key)) << "a corner of " << a.name << " is missing in " << b.name;
    const CornerInfo& other = cb.at(key);
    EXPECT_NEAR(info.uv.x, other.uv.x, 1e-6);
    EXPECT_NEAR(info.uv.y, other.uv.y, 1e-6);
    EXPECT_NEAR(info.colour.r, other.colour.r, 1.0 / 255);
    EXPECT_NEAR(info.colour.g, other.colour.g, 1.0 / 255);
    EXPECT_NEAR(info.colour.b, other.colour.b, 1.0 / 255);
    EXPECT_EQ(info.textured, other.textured);
  }
}

}  // namespace

TEST(FaceColours, ObjWithMtlLoadsTextureCoordinatesAndMaterials) {
  const LoadedMesh loaded = load_mesh(colour_data("cube.obj"));
  const Mesh& m = loaded.mesh;
  ASSERT_EQ(m.num_faces(), 12);
  ASSERT_EQ(m.face_uv.size(), 12u);
  ASSERT_EQ(m.face_material.size(), 12u);
  ASSERT_EQ(m.materials.size(), 2u);
  int textured = 0;
  for (int f = 0; f < 12; ++f)
    textured += m.materials[m.face_material[f]].texture_found;
  EXPECT_EQ(textured, 10);  // five textured sides, the bottom in Kd red
  for (const Material& mat : m.materials) {
    if (mat.texture.empty()) {
      EXPECT_NEAR(mat.colour.r, 0.8, 1.0 / 255);
      EXPECT_NEAR(mat.colour.g, 0.1, 1.0 / 255);
    } else {
      EXPECT_EQ(fs::path(mat.texture), colour_data("glyphs.png").lexically_normal());
      EXPECT_EQ(mat.texture_width_px, 192);
      EXPECT_EQ(mat.texture_height_px, 192);
    }
  }
}

TEST(FaceColours, GltfAndGlbLoadTheSameFacesCoordinatesAndColoursAsTheObj) {
  const Mesh obj = load_mesh(colour_data("cube.obj")).mesh;
  const Mesh gltf = load_mesh(colour_data("cube.gltf")).mesh;
  const Mesh glb = load_mesh(colour_data("cube.glb")).mesh;
  expect_same_colours(obj, gltf);
  expect_same_colours(obj, glb);
  // The .glb carries its image inside; the .gltf names the file beside it.
  bool embedded = false;
  for (const Material& mat : glb.materials)
    embedded = embedded || (!mat.texture_data.empty() && mat.texture_found);
  EXPECT_TRUE(embedded);
  // Split per face in the file, welded into one closed cube by the repairs.
  EXPECT_EQ(gltf.num_vertices(), 8);
  EXPECT_EQ(glb.num_vertices(), 8);
}

TEST(FaceColours, QuadsKeepTheirCornersTextureCoordinatesThroughTriangulation) {
  const LoadedMesh quads = load_mesh(colour_data("cube_quads.obj"));
  expect_same_colours(load_mesh(colour_data("cube.obj")).mesh, quads.mesh);
}

TEST(FaceColours, FacesTurnedByTheRepairsTakeTheirTextureCoordinatesWithThem) {
  // The cube with its top face's triangles written clockwise: re-oriented on load, and each corner must
  // keep its own coordinates.
  const fs::path dir = test::temp_dir("colour_flip");
  std::ifstream in(colour_data("cube.obj"));
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string top1 = "f 5/1 6/2 7/3", top2 = "f 5/1 7/3 8/4";
  ASSERT_NE(text.find(top1), std::string::npos);
  text.replace(text.find(top1), top1.size(), "f 5/1 7/3 6/2");
  text.replace(text.find(top2), top2.size(), "f 5/1 8/4 7/3");
  write(dir, "cube.obj", text);
  fs::copy_file(colour_data("cube.mtl"), dir / "cube.mtl");
  fs::copy_file(colour_data("glyphs.png"), dir / "glyphs.png");
  const LoadedMesh flipped = load_mesh(dir / "cube.obj");
  expect_same_colours(load_mesh(colour_data("cube.obj")).mesh, flipped.mesh);
  fs::remove_all(dir);
}

TEST(FaceColours, AMissingTextureIsOneNoteAndItsFacesPrintInTheirColour) {
  const fs::path dir = test::temp_dir("colour_missing");
  fs::copy_file(colour_data("cube.obj"), dir / "cube.obj");
  fs::copy_file(colour_data("cube.mtl"), dir / "cube.mtl");
  const LoadedMesh loaded = load_mesh(dir / "cube.obj");
  const auto note = std::find_if(loaded.notes.begin(), loaded.notes.end(), [](const std::string& n) {
    return n.find("glyphs.png") != std::string::npos;
  });
  ASSERT_NE(note, loaded.notes.end());
  EXPECT_NE(note->find("missing"), std::string::npos);
  EXPECT_EQ(note->find('\n'), std::string::npos);
  for (const Material& mat : loaded.mesh.materials)
    EXPECT_FALSE(mat.texture_found);
  EXPECT_EQ(loaded.mesh.face_uv.size(), 12u);
  fs::remove_all(dir);
}

TEST(FaceColours, AnObjWithoutMaterialsHasNoColours) {
  const fs::path dir = test::temp_dir("colour_plain");
  const fs::path p =
      write(dir, "tet.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  const Mesh m = load_mesh(p).mesh;
  EXPECT_TRUE(m.face_uv.empty());
  EXPECT_TRUE(m.face_material.empty());
  EXPECT_TRUE(m.materials.empty());
  fs::remove_all(dir);
}

TEST(FaceColours, AMissingMaterialLibraryIsANote) {
  const fs::path dir = test::temp_dir("colour_nomtl");
  const fs::path p = write(dir, "tet.obj",
                           "mtllib none.mtl\nusemtl foo\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                           "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  const LoadedMesh loaded = load_mesh(p);
  EXPECT_TRUE(loaded.mesh.materials.empty());
  ASSERT_FALSE(loaded.notes.empty());
  EXPECT_NE(loaded.notes.back().find("none.mtl not found"), std::string::npos) << loaded.notes.back();
  fs::remove_all(dir);
}

TEST(FaceColours, MaterialsAreNamedAsTheObjsUsemtlNamesThem) {
  const fs::path dir = test::temp_dir("colour_usemtl");
  write(dir, "two.mtl", "newmtl roof tiles\nKd 0.8 0.2 0.1\nnewmtl walls\nKd 0.8 0.2 0.1\n");
  const fs::path p = write(dir, "tet.obj",
                           "mtllib two.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nusemtl roof tiles\n"
                           "f 1 3 2\nf 1 2 4\nusemtl walls\nf 1 4 3\nusemtl roof tiles\nf 2 3 4\n");
  const Mesh m = load_mesh(p).mesh;
  // The same colour under two names stays two materials, each with its faces.
  ASSERT_EQ(m.materials.size(), 2u);
  ASSERT_EQ(m.face_material.size(), 4u);
  const auto name_of = [&](int f) { return m.materials.at(m.face_material[f]).name; };
  EXPECT_EQ(name_of(0), "roof tiles");
  EXPECT_EQ(name_of(1), "roof tiles");
  EXPECT_EQ(name_of(2), "walls");
  EXPECT_EQ(name_of(3), "roof tiles");
  fs::remove_all(dir);
}

TEST(FaceColours, PlyFaceColoursBecomeMaterials) {
  const fs::path dir = test::temp_dir("colour_ply");
  const fs::path p = write(dir, "tet.ply",
                           "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                           "property float z\nelement face 4\nproperty list uchar int vertex_indices\n"
                           "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n"
                           "0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
                           "3 0 2 1 255 0 0\n3 0 1 3 255 0 0\n3 0 3 2 0 0 255\n3 1 2 3 0 255 0\n");
  const Mesh m = load_mesh(p).mesh;
  ASSERT_EQ(m.face_material.size(), 4u);
  EXPECT_EQ(m.materials.size(), 3u);
  EXPECT_EQ(m.face_material[0], m.face_material[1]);
  EXPECT_EQ(m.materials[m.face_material[0]].colour, (Colour{1, 0, 0}));
  EXPECT_EQ(m.materials[m.face_material[3]].colour, (Colour{0, 1, 0}));
  EXPECT_TRUE(m.face_uv.empty());
  fs::remove_all(dir);
}

namespace {

// A glTF document with one triangle primitive from inline (data: URI) buffers.
std::string gltf_with(const std::vector<float>& positions, const std::vector<unsigned short>& indices,
                      const std::string& buffer_uri = "") {
  std::string blob(reinterpret_cast<const char*>(positions.data()), positions.size() * 4);
  const std::size_t pos_bytes = blob.size();
  blob.append(reinterpret_cast<const char*>(indices.data()), indices.size() * 2);
  const std::string b64 = test::base64(blob);
  const std::string uri = buffer_uri.empty() ? "data:application/octet-stream;base64," + b64 : buffer_uri;
  return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
         R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],)"
         R"("buffers":[{"uri":")" +
         uri + R"(","byteLength":)" + std::to_string(blob.size()) +
         R"(}],"bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":)" + std::to_string(pos_bytes) +
         R"(},{"buffer":0,"byteOffset":)" + std::to_string(pos_bytes) + R"(,"byteLength":)" +
         std::to_string(blob.size() - pos_bytes) +
         R"(}],"accessors":[{"bufferView":0,"componentType":5126,"count":)" +
         std::to_string(positions.size() / 3) + R"(,"type":"VEC3","min":[-1,-1,-1],"max":[1,1,1]},)" +
         R"({"bufferView":1,"componentType":5123,"count":)" + std::to_string(indices.size()) +
         R"(,"type":"SCALAR"}]})";
}

std::string error_of(const fs::path& p) {
  try {
    load_mesh(p);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(FaceColours, ANonManifoldGltfIsRefusedExactlyLikeTheSameObj) {
  const fs::path dir = test::temp_dir("colour_nonmanifold");
  // Three triangles on one edge (0-1).
  const std::vector<float> v{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1};
  const std::vector<unsigned short> f{0, 1, 2, 1, 0, 3, 0, 1, 4};
  const std::string gltf_error = error_of(write(dir, "fan.gltf", gltf_with(v, f)));
  const std::string obj_error = error_of(
      write(dir, "fan.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n"));
  ASSERT_NE(gltf_error.find("non-manifold edge"), std::string::npos) << gltf_error;
  // Same problem, same words: only the file name differs.
  EXPECT_EQ(gltf_error.substr(gltf_error.find(':')), obj_error.substr(obj_error.find(':')));
  fs::remove_all(dir);
}

TEST(FaceColours, GltfBuffersThatAreNotRegularFilesAreRefused) {
  const fs::path dir = test::temp_dir("colour_devzero");
  const std::vector<float> v{0, 0, 0, 1, 0, 0, 0, 1, 0};
  const std::vector<unsigned short> f{0, 1, 2};
  for (const std::string uri : {"/dev/zero", "../../../../../../dev/zero", "missing.bin", "."}) {
    const fs::path p = write(dir, "bad.gltf", gltf_with(v, f, uri));
    EXPECT_THROW(load_mesh(p), InputError) << uri;
  }
  fs::remove_all(dir);
}

TEST(FaceColours, BrokenGltfAndGlbFilesAreOneLineInputErrors) {
  const fs::path dir = test::temp_dir("colour_broken");
  std::ifstream in(colour_data("cube.glb"), std::ios::binary);
  const std::string glb((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (const auto& [name, bytes] :
       std::vector<std::pair<std::string, std::string>>{{"a.gltf", "{"},
                                                        {"b.gltf", "{\"asset\":{\"version\":\"2.0\"}}"},
                                                        {"c.glb", glb.substr(0, glb.size() / 2)},
                                                        {"d.glb", "glTF"},
                                                        {"e.gltf", "not json at all"}}) {
    const std::string error = error_of(write(dir, name, bytes));
    EXPECT_FALSE(error.empty()) << name;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
  }
  fs::remove_all(dir);
}

TEST(FaceColours, SpotLoadsWithTextureCoordinatesOnEveryFace) {
  const fs::path spot = test::example_mesh("spot_textured/spot_triangulated.obj");
  if (!fs::exists(spot)) GTEST_SKIP() << spot << " is absent";
  const Mesh m = load_mesh(spot).mesh;
  ASSERT_EQ(m.num_faces(), 5856);
  ASSERT_EQ(m.face_uv.size(), 5856u);
  ASSERT_EQ(m.materials.size(), 1u);
  EXPECT_TRUE(m.materials[0].texture_found);
  // Spot's coordinates stray up to 0.06 outside the image at the seams; the renderer pads there.
  for (const auto& uv : m.face_uv)
    for (Vec2 c : uv) {
      EXPECT_GE(c.x, -0.1);
      EXPECT_LE(c.x, 1.1);
      EXPECT_GE(c.y, -0.1);
      EXPECT_LE(c.y, 1.1);
    }
}

TEST(FaceColours, InspectReportsMaterialsTexturesAndCoverage) {
  const test::CliRun run = test::run_foldkit({"inspect", "--json", colour_data("cube.glb").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("\"materials\""), std::string::npos);
  EXPECT_NE(run.out.find("\"texture_found\": true"), std::string::npos);
  EXPECT_NE(run.out.find("\"textures_missing_count\": 0"), std::string::npos);
  EXPECT_NE(run.out.find("\"faces_with_texture_coordinates_count\": 12"), std::string::npos);
  const fs::path dir = test::temp_dir("colour_inspect");
  fs::copy_file(colour_data("cube.obj"), dir / "cube.obj");
  fs::copy_file(colour_data("cube.mtl"), dir / "cube.mtl");
  const test::CliRun missing = test::run_foldkit({"inspect", (dir / "cube.obj").string()});
  ASSERT_EQ(missing.exit_code, 0) << missing.err;
  EXPECT_NE(missing.out.find("1 missing"), std::string::npos) << missing.out;
  EXPECT_NE(missing.out.find("MISSING"), std::string::npos) << missing.out;
  fs::remove_all(dir);
}
