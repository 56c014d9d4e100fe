// glTF 2.0 through Assimp. Assimp only parses: its output is copied into a polygon soup (no Assimp
// post-processing, so faces arrive as the file has them) and the soup goes through the same repairs and
// checks as every other format. Assimp may only open regular files of bounded size: a hostile .gltf
// could name /dev/zero or a huge file as its buffer.
#include <assimp/DefaultIOSystem.h>
#include <assimp/GltfMaterial.h>
#include <assimp/material.h>
#include <assimp/scene.h>
#include <assimp/DefaultLogger.hpp>
#include <assimp/Importer.hpp>

#include <cstring>

#include "face_colours.hpp"
#include "foldkit/error.hpp"

namespace foldkit::unfold::detail {
namespace {

namespace fs = std::filesystem;

class BoundedIOSystem final : public Assimp::DefaultIOSystem {
 public:
  explicit BoundedIOSystem(std::uintmax_t max_bytes) : max_bytes_(max_bytes) {}
  Assimp::IOStream* Open(const char* file, const char* mode) override {
    std::error_code ec;
    if (!file || std::strchr(mode, 'w') || std::strchr(mode, 'a')) return nullptr;
    if (!fs::is_regular_file(file, ec) || fs::file_size(file, ec) > max_bytes_ || ec) return nullptr;
    return Assimp::DefaultIOSystem::Open(file, mode);
  }

 private:
  std::uintmax_t max_bytes_;
};

Material material_of(const aiScene& scene, const aiMaterial& in, const fs::path& folder) {
  Material m;
  aiString name;
  if (in.Get(AI_MATKEY_NAME, name) == AI_SUCCESS) m.name = name.C_Str();
  aiColor4D c;
  if (in.Get(AI_MATKEY_BASE_COLOR, c) == AI_SUCCESS || in.Get(AI_MATKEY_COLOR_DIFFUSE, c) == AI_SUCCESS)
    m.colour = {c.r, c.g, c.b};
  aiString tex;
  const bool has_texture = in.GetTexture(aiTextureType_BASE_COLOR, 0, &tex) == AI_SUCCESS ||
                           in.GetTexture(aiTextureType_DIFFUSE, 0, &tex) == AI_SUCCESS;
  if (!has_texture || tex.length == 0) return m;
  if (const aiTexture* embedded = scene.GetEmbeddedTexture(tex.C_Str())) {
    // mHeight 0: mWidth bytes of an encoded image (PNG, JPEG); otherwise raw texels, which no exporter
    // writes for glTF and which are not supported.
    if (embedded->mHeight == 0) {
      const auto* bytes = reinterpret_cast<const unsigned char*>(embedded->pcData);
      m.texture_data.assign(bytes, bytes + embedded->mWidth);
    }
    m.texture = std::string("embedded image ") + tex.C_Str();
  } else {
    m.texture = (folder / tex.C_Str()).lexically_normal().string();
  }
  probe_texture(m);
  return m;
}

struct Walk {
  const aiScene& scene;
  PolygonSoup& soup;
  bool any_uv = false;
  std::size_t nodes = 0;
};

// Depth-first over the node tree; a node's meshes are placed by the product of the transforms above it.
void add_node(Walk& walk, const aiNode& node, const aiMatrix4x4& parent, int depth) {
  constexpr int kMaxDepth = 256;
  constexpr std::size_t kMaxNodes = 1'000'000;
  if (depth > kMaxDepth || ++walk.nodes > kMaxNodes) return;
  const aiMatrix4x4 transform = parent * node.mTransformation;
  for (unsigned k = 0; k < node.mNumMeshes; ++k) {
    if (node.mMeshes[k] >= walk.scene.mNumMeshes) continue;
    const aiMesh& mesh = *walk.scene.mMeshes[node.mMeshes[k]];
    if (!(mesh.mPrimitiveTypes & (aiPrimitiveType_TRIANGLE | aiPrimitiveType_POLYGON))) continue;
    // Only the vertices faces use: primitives may share one big vertex array.
    std::vector<int> soup_index(mesh.mNumVertices, -1);
    auto vertex = [&](unsigned v) {
      if (soup_index[v] < 0) {
        const aiVector3D p = transform * mesh.mVertices[v];
        soup_index[v] = static_cast<int>(walk.soup.vertices.size());
        walk.soup.vertices.push_back({p.x, p.y, p.z});
      }
      return soup_index[v];
    };
    const aiVector3D* uv = mesh.HasTextureCoords(0) ? mesh.mTextureCoords[0] : nullptr;
    walk.any_uv = walk.any_uv || uv;
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices < 3) continue;  // points and lines are not surface
      std::vector<int> poly;
      std::vector<Vec2> uvs;
      for (unsigned i = 0; i < face.mNumIndices; ++i) {
        const unsigned index = face.mIndices[i];
        poly.push_back(index < mesh.mNumVertices ? vertex(index) : -1);
        if (uv && index < mesh.mNumVertices) uvs.push_back({uv[index].x, uv[index].y});
      }
      if (uvs.size() != poly.size()) uvs.clear();
      walk.soup.polygons.push_back(std::move(poly));
      walk.soup.polygon_uvs.push_back(std::move(uvs));
      walk.soup.polygon_material.push_back(
          mesh.mMaterialIndex < walk.scene.mNumMaterials ? static_cast<int>(mesh.mMaterialIndex) : -1);
    }
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c)
    if (node.mChildren[c]) add_node(walk, *node.mChildren[c], transform, depth + 1);
}

}  // namespace

PolygonSoup read_gltf(const fs::path& path, const std::string& name, std::uintmax_t max_file_bytes,
                      std::vector<std::string>& notes) {
  Assimp::DefaultLogger::kill();  // Assimp logs to nowhere unless a logger is created: keep it that way
  Assimp::Importer importer;
  importer.SetIOHandler(new BoundedIOSystem(max_file_bytes));  // the importer owns and deletes it
  const aiScene* scene = importer.ReadFile(path.string(), 0);
  if (!scene) {
    std::string why = importer.GetErrorString();
    if (why.size() > 160) why = why.substr(0, 160) + "...";
    throw InputError(name, "unreadable glTF file" + (why.empty() ? std::string() : ": " + why));
  }
  if (!scene->mRootNode) throw InputError(name, "glTF file without a scene");

  PolygonSoup soup;
  for (unsigned m = 0; m < scene->mNumMaterials; ++m)
    soup.materials.push_back(material_of(*scene, *scene->mMaterials[m], path.parent_path()));
  Walk walk{*scene, soup};
  add_node(walk, *scene->mRootNode, aiMatrix4x4(), 0);
  if (!walk.any_uv) soup.polygon_uvs.clear();
  // Only materials some face uses (Assimp adds a default one), numbered in order of first use.
  std::vector<int> renumber(soup.materials.size(), -1);
  std::vector<Material> used;
  for (int& m : soup.polygon_material) {
    if (m < 0) continue;
    if (renumber[m] < 0) {
      renumber[m] = static_cast<int>(used.size());
      used.push_back(std::move(soup.materials[m]));
      if (used.back().name.empty()) used.back().name = "material " + std::to_string(m + 1);
    }
    m = renumber[m];
  }
  soup.materials = std::move(used);
  for (const Material& m : soup.materials)
    if (!m.texture.empty() && !m.texture_found)
      notes.push_back("texture " + m.texture + " of material '" + m.name +
                      "' is missing or unreadable: its faces print in their colour");
  return soup;
}

}  // namespace foldkit::unfold::detail
