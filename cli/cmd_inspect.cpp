// `foldkit inspect MESH [--json] [--max-faces N]`: what the loader made of a mesh file, before unfolding.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "cmd_inspect.hpp"
#include "commands.hpp"
#include "foldkit/unfold/mesh_io.hpp"
#include "foldkit/unfold/mesh_stats.hpp"
#include "json_report.hpp"
#include "length_option.hpp"

namespace foldkit::cli {
namespace {

// What a builder needs to know before printing in colour: which materials, which images were found,
// and how much of the surface has texture coordinates.
struct ColourReport {
  int faces_with_uv = 0;
  double uv_area_fraction = 0;  ///< surface area of the faces with coordinates over the whole area
  int textures_found = 0, textures_missing = 0;
};

ColourReport colour_report(const unfold::Mesh& m) {
  ColourReport r;
  double with = 0, total = 0;
  for (int f = 0; f < m.num_faces(); ++f) {
    const double a = unfold::face_area(m, f);
    total += a;
    const int mat = m.face_material.empty() ? -1 : m.face_material[f];
    const bool textured = !m.face_uv.empty() && mat >= 0 && !m.materials[mat].texture.empty();
    if (!m.face_uv.empty()) r.faces_with_uv += 1;
    if (textured) with += a;
  }
  r.uv_area_fraction = total > 0 ? with / total : 0;
  for (const auto& mat : m.materials)
    if (!mat.texture.empty()) (mat.texture_found ? r.textures_found : r.textures_missing) += 1;
  return r;
}

std::string hex(Colour c) {
  auto byte = [](double v) { return static_cast<int>(std::lround(std::clamp(v, 0.0, 1.0) * 255)); };
  char buf[16];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", byte(c.r), byte(c.g), byte(c.b));
  return buf;
}

std::vector<int> faces_per_material(const unfold::Mesh& m) {
  std::vector<int> count(m.materials.size(), 0);
  for (int mat : m.face_material)
    if (mat >= 0) count[mat] += 1;
  return count;
}

nlohmann::json to_json(const unfold::LoadedMesh& loaded, const unfold::MeshStats& s) {
  nlohmann::json j;
  j["file"] = loaded.mesh.name;
  j["face_count"] = s.faces;
  j["original_face_count"] = loaded.original_faces;
  j["file_quad_count"] = loaded.file_quads;
  j["file_ngon_count"] = loaded.file_ngons;
  j["vertex_count"] = s.vertices;
  j["edge_count"] = s.edges;
  j["boundary_edge_count"] = s.boundary_edges;
  j["boundary_loop_count"] = s.boundary_loops;
  j["component_count"] = s.components;
  j["genus"] = s.genus;
  j["euler_characteristic"] = s.euler_characteristic;
  j["closed"] = s.closed;
  j["orientable"] = s.orientable;
  j["vertex_classes"] = {{"elliptic_count", s.elliptic_vertices},
                         {"hyperbolic_count", s.hyperbolic_vertices},
                         {"flat_count", s.flat_vertices},
                         {"boundary_count", s.boundary_vertices}};
  // In the file's own units, whatever they are: the suffix says so.
  j["bounding_box"] = {{"min_units", {s.bbox_min.x, s.bbox_min.y, s.bbox_min.z}},
                       {"max_units", {s.bbox_max.x, s.bbox_max.y, s.bbox_max.z}}};
  j["surface_area_units2"] = s.surface_area;
  nlohmann::json comps = nlohmann::json::array();
  for (const auto& c : s.per_component)
    comps.push_back({{"face_count", c.faces},
                     {"vertex_count", c.vertices},
                     {"edge_count", c.edges},
                     {"boundary_loop_count", c.boundary_loops},
                     {"genus", c.genus},
                     {"closed", c.closed}});
  j["components"] = comps;
  const ColourReport colour = colour_report(loaded.mesh);
  nlohmann::json materials = nlohmann::json::array();
  const std::vector<int> used = faces_per_material(loaded.mesh);
  for (std::size_t i = 0; i < loaded.mesh.materials.size(); ++i) {
    const auto& mat = loaded.mesh.materials[i];
    nlohmann::json jm{{"name", mat.name}, {"colour", hex(mat.colour)}, {"face_count", used[i]}};
    if (!mat.texture.empty()) {
      jm["texture"] = mat.texture;
      jm["texture_found"] = mat.texture_found;
      jm["texture_embedded"] = !mat.texture_data.empty();
      if (mat.texture_found) jm["texture_size_px"] = {mat.texture_width_px, mat.texture_height_px};
    }
    materials.push_back(jm);
  }
  j["materials"] = materials;
  j["faces_with_texture_coordinates_count"] = colour.faces_with_uv;
  j["textured_area_fraction"] = colour.uv_area_fraction;
  j["textures_found_count"] = colour.textures_found;
  j["textures_missing_count"] = colour.textures_missing;
  j["notes"] = loaded.notes;
  return versioned(j);
}

std::string table(const unfold::LoadedMesh& loaded, const unfold::MeshStats& s) {
  std::ostringstream out;
  auto row = [&](const std::string& key, const std::string& value) {
    out << "  " << key << std::string(key.size() < 18 ? 18 - key.size() : 1, ' ') << value << "\n";
  };
  auto yes_no = [](bool b) { return std::string(b ? "yes" : "no"); };
  out << loaded.mesh.name << "\n";
  row("faces", std::to_string(s.faces) + (loaded.original_faces != s.faces
                                              ? " (" + std::to_string(loaded.original_faces) + " in the file)"
                                              : ""));
  if (loaded.file_quads + loaded.file_ngons > 0)
    row("polygons", std::to_string(loaded.file_quads) + " quads, " + std::to_string(loaded.file_ngons) +
                        " n-gons: each flat one unfolds whole");
  row("vertices", std::to_string(s.vertices));
  row("edges", std::to_string(s.edges));
  row("boundary loops", std::to_string(s.boundary_loops));
  row("components", std::to_string(s.components));
  std::string genus = std::to_string(s.genus);
  if (s.components > 1) {
    genus += " (";
    for (std::size_t i = 0; i < s.per_component.size(); ++i)
      genus += (i ? " + " : "") + std::to_string(s.per_component[i].genus);
    genus += ")";
  }
  row("genus", genus);
  row("closed", yes_no(s.closed));
  row("orientable", yes_no(s.orientable));
  row("elliptic vertices", std::to_string(s.elliptic_vertices));
  row("hyperbolic", std::to_string(s.hyperbolic_vertices));
  row("flat", std::to_string(s.flat_vertices));
  row("boundary vertices", std::to_string(s.boundary_vertices));
  char box[256];
  std::snprintf(box, sizeof box, "(%.6g, %.6g, %.6g) .. (%.6g, %.6g, %.6g)", s.bbox_min.x, s.bbox_min.y,
                s.bbox_min.z, s.bbox_max.x, s.bbox_max.y, s.bbox_max.z);
  row("bounding box", box);
  const unfold::Mesh& m = loaded.mesh;
  const std::vector<int> used = faces_per_material(m);
  for (std::size_t i = 0; i < m.materials.size(); ++i) {
    const auto& mat = m.materials[i];
    std::string value = "'" + mat.name + "' " + hex(mat.colour) + ", " + std::to_string(used[i]) + " faces";
    if (!mat.texture.empty()) {
      value += ", texture " + mat.texture;
      value += mat.texture_found ? " (" + std::to_string(mat.texture_width_px) + "x" +
                                       std::to_string(mat.texture_height_px) + ")"
                                 : " (MISSING: prints in the colour)";
    }
    row(i == 0 ? "materials" : "", value);
  }
  if (!m.materials.empty() || !m.face_uv.empty()) {
    const ColourReport colour = colour_report(m);
    char coverage[128];
    std::snprintf(coverage, sizeof coverage, "%d of %d faces, %.0f%% of the area textured",
                  colour.faces_with_uv, m.num_faces(), 100 * colour.uv_area_fraction);
    row("texture coords", coverage);
    row("textures", std::to_string(colour.textures_found) + " found, " +
                        std::to_string(colour.textures_missing) + " missing");
  }
  for (const auto& note : loaded.notes)
    out << "  note: " << note << "\n";
  return out.str();
}

}  // namespace

void run_inspect(const InspectArgs& args) {
  unfold::LoadOptions options;
  options.max_faces = args.max_faces;
  const unfold::LoadedMesh loaded = unfold::load_mesh(args.mesh, options);
  const unfold::MeshStats stats = unfold::compute_mesh_stats(loaded.mesh);
  if (args.json) {
    std::cout << to_json(loaded, stats).dump(2) << "\n";
  } else {
    std::cout << table(loaded, stats);
  }
}

void setup_inspect(CLI::App& app) {
  auto args = std::make_shared<InspectArgs>();
  CLI::App* cmd = app.add_subcommand("inspect", "Load a mesh and report its topology and curvature");
  cmd->add_option("mesh", args->mesh, "Mesh file (.obj, .off, .stl, .ply, .gltf, .glb)")->required();
  cmd->add_flag("--json", args->json, "Print the report as JSON");
  cmd->add_option("--max-faces", args->max_faces, "Decimate to at most N faces first")
      ->check(number_in(4, 100e6, "faces"));
  cmd->callback([args] { run_inspect(*args); });
}

}  // namespace foldkit::cli
