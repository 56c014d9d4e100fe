// `foldkit inspect MESH [--json] [--max-faces N]`: what the loader made of a mesh file, before unfolding.
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "foldkit/unfold/mesh_io.hpp"
#include "foldkit/unfold/mesh_stats.hpp"

namespace foldkit::cli {
namespace {

struct InspectArgs {
  std::string mesh;
  bool json = false;
  std::optional<int> max_faces;
};

nlohmann::json to_json(const unfold::LoadedMesh& loaded, const unfold::MeshStats& s) {
  nlohmann::json j;
  j["file"] = loaded.mesh.name;
  j["faces"] = s.faces;
  j["original_faces"] = loaded.original_faces;
  j["vertices"] = s.vertices;
  j["edges"] = s.edges;
  j["boundary_edges"] = s.boundary_edges;
  j["boundary_loops"] = s.boundary_loops;
  j["components"] = s.components;
  j["genus"] = s.genus;
  j["euler_characteristic"] = s.euler_characteristic;
  j["closed"] = s.closed;
  j["orientable"] = s.orientable;
  j["vertex_classes"] = {{"elliptic", s.elliptic_vertices},
                         {"hyperbolic", s.hyperbolic_vertices},
                         {"flat", s.flat_vertices},
                         {"boundary", s.boundary_vertices}};
  j["bounding_box"] = {{"min", {s.bbox_min.x, s.bbox_min.y, s.bbox_min.z}},
                       {"max", {s.bbox_max.x, s.bbox_max.y, s.bbox_max.z}}};
  j["surface_area"] = s.surface_area;
  nlohmann::json comps = nlohmann::json::array();
  for (const auto& c : s.per_component)
    comps.push_back({{"faces", c.faces},
                     {"vertices", c.vertices},
                     {"edges", c.edges},
                     {"boundary_loops", c.boundary_loops},
                     {"genus", c.genus},
                     {"closed", c.closed}});
  j["per_component"] = comps;
  j["notes"] = loaded.notes;
  return j;
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
  for (const auto& note : loaded.notes)
    out << "  note: " << note << "\n";
  return out.str();
}

}  // namespace

void setup_inspect(CLI::App& app) {
  auto args = std::make_shared<InspectArgs>();
  CLI::App* cmd = app.add_subcommand("inspect", "Load a mesh and report its topology and curvature");
  cmd->add_option("mesh", args->mesh, "Mesh file (.obj, .off, .stl, .ply)")->required();
  cmd->add_flag("--json", args->json, "Print the report as JSON");
  cmd->add_option("--max-faces", args->max_faces, "Decimate to at most N faces first")
      ->check(CLI::PositiveNumber);
  cmd->callback([args] {
    unfold::LoadOptions options;
    options.max_faces = args->max_faces;
    const unfold::LoadedMesh loaded = unfold::load_mesh(args->mesh, options);
    const unfold::MeshStats stats = unfold::compute_mesh_stats(loaded.mesh);
    if (args->json) {
      std::cout << to_json(loaded, stats).dump(2) << "\n";
    } else {
      std::cout << table(loaded, stats);
    }
  });
}

}  // namespace foldkit::cli
