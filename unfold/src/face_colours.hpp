#pragma once
// Internal to unfold/: colour and texture coordinates as readers report them, turned into the soup's
// per-polygon attributes and materials; texture images probed; glTF read (gltf_reader).
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "mesh_io_soup.hpp"

namespace foldkit::unfold::detail {

/// What OpenMesh's OBJ and PLY readers report, face by face (indices are the soup's polygons).
struct RawColours {
  std::vector<std::vector<Vec2>> face_uvs;           ///< per polygon, its corners' coordinates (or empty)
  std::vector<std::optional<Colour>> face_colour;    ///< OBJ Kd of the face's material, PLY face colour
  std::vector<int> face_texture;                     ///< OpenMesh's texture index of the material, -1 none
  std::map<int, std::string> texture_names;          ///< texture index -> map_Kd as written in the MTL
  std::vector<std::optional<Colour>> vertex_colour;  ///< PLY vertex colours
  std::vector<std::string> material_names;           ///< OBJ `usemtl` names
  std::vector<int> face_material_name;               ///< per polygon, index into material_names or -1
};

/// Sets soup.polygon_uvs, polygon_material and materials from `raw`: one material per distinct
/// (colour, texture); texture names resolved against `texture_dir` and probed. Appends one note per
/// texture that cannot be read (the faces then print in their colour). Faces of a PLY with vertex
/// colours only take the mean of their corners' colours.
void attach_raw_colours(RawColours raw, const std::filesystem::path& texture_dir, PolygonSoup& soup,
                        std::vector<std::string>& notes);

/// Reads the header of the material's texture (texture_data, else the file): sets texture_found and size.
void probe_texture(Material& material);

/// The `mtllib` file an OBJ names first, resolved against the OBJ's folder; nullopt when none.
std::optional<std::filesystem::path> obj_material_library(const std::string& obj_text,
                                                          const std::filesystem::path& obj_path);

/// What reading a glTF may cost.
struct GltfLimits {
  std::uintmax_t max_file_bytes = 0;  ///< per buffer or image file it refers to
  int face_limit = 0;                 ///< triangles in all
};

/// A .gltf (`bytes`, with its buffers and images beside `path` or in data: URIs) or .glb: every mesh
/// of the default scene under its node's transform, TEXCOORD_0, baseColorFactor and baseColorTexture.
/// Throws InputError(name, ...) for anything malformed or over `limits`.
PolygonSoup read_gltf(const std::string& bytes, const std::filesystem::path& path, const std::string& name,
                      const GltfLimits& limits, std::vector<std::string>& notes);

}  // namespace foldkit::unfold::detail
