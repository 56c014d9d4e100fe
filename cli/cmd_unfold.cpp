// `foldkit unfold MESH -o net.obj [--json]`: the flat net alone, for inspection or other tools.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <numeric>
#include <ostream>
#include <string>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "foldkit/devices/atomic_file.hpp"
#include "foldkit/error.hpp"
#include "json_report.hpp"
#include "layout_options.hpp"
#include "output_paths.hpp"
#include "pipeline.hpp"
#include "unfold_options.hpp"

namespace foldkit::cli {
namespace {

struct UnfoldArgs {
  std::string mesh;
  std::string output;
  bool json = false;
  bool quiet = false;
  UnfoldCliOptions unfold;
  LayoutCliOptions layout;
};

// One OBJ vertex per group of flat corners joined through folds: corners of one mesh vertex in one
// piece share a vertex where the piece is folded there, and no vertex is shared between pieces.
std::vector<int> net_vertices(const unfold::Unfolding& u) {
  const int nf = u.num_faces();
  std::vector<int> parent(static_cast<std::size_t>(nf) * 3);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x) {
    while (parent[x] != x)
      x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const unfold::UnfoldEdge& e : u.edges) {
    if (e.cut) continue;
    // Face 0 runs corner i -> i+1; face 1 runs the other way, so its corner j+1 meets face 0's corner i.
    int f = e.face[0], g = e.face[1], i = e.corner[0], j = e.corner[1];
    int a0 = f * 3 + i, a1 = f * 3 + (i + 1) % 3, b0 = g * 3 + (j + 1) % 3, b1 = g * 3 + j;
    parent[find(a0)] = find(b0);
    parent[find(a1)] = find(b1);
  }
  for (std::size_t c = 0; c < parent.size(); ++c)
    parent[c] = find(static_cast<int>(c));
  return parent;
}

// The outline of one input polygon: its triangles' corners (as net vertex ids) around the loop of
// edges that no two of its triangles share. Empty when a cut runs between its triangles (possible only
// for a polygon that is not planar; its triangles then go out one by one).
std::vector<int> polygon_loop(const unfold::Unfolding& u, const std::vector<int>& vertex,
                              const std::vector<int>& faces) {
  if (faces.size() == 1) return {vertex[faces[0] * 3], vertex[faces[0] * 3 + 1], vertex[faces[0] * 3 + 2]};
  std::map<int, int> next;
  for (int f : faces)
    for (int c = 0; c < 3; ++c) {
      const unfold::UnfoldEdge& e = u.edges[u.face_edges[f][c]];
      const int other = e.face[0] == f ? e.face[1] : e.face[0];
      const bool inside = !e.cut && std::find(faces.begin(), faces.end(), other) != faces.end();
      if (inside) continue;
      if (!next.emplace(vertex[f * 3 + c], vertex[f * 3 + (c + 1) % 3]).second) return {};
    }
  std::vector<int> loop{next.begin()->first};
  while (loop.size() <= next.size()) {
    auto it = next.find(loop.back());
    if (it == next.end()) return {};
    if (it->second == loop.front()) break;
    loop.push_back(it->second);
  }
  if (loop.size() != next.size()) return {};
  return loop;
}

// Face k of the net is face k of the input file; only a non-planar polygon that the unfolding cut
// apart is written as its triangles (said in the header).
void write_net_obj(std::ostream& out, const unfold::Mesh& mesh, const unfold::Unfolding& u) {
  const int nf = u.num_faces();
  const std::vector<int> vertex = net_vertices(u);
  int polygons = 0;
  for (int f = 0; f < nf; ++f)
    polygons = std::max(polygons, mesh.polygon_of(f) + 1);
  std::vector<std::vector<int>> faces_of(polygons);
  for (int f = 0; f < nf; ++f)
    faces_of[mesh.polygon_of(f)].push_back(f);
  std::vector<std::vector<int>> loops;
  int folded = 0;
  for (const auto& faces : faces_of) {
    if (faces.empty()) continue;
    std::vector<int> loop = polygon_loop(u, vertex, faces);
    if (!loop.empty()) {
      loops.push_back(std::move(loop));
      continue;
    }
    ++folded;
    for (int f : faces)
      loops.push_back({vertex[f * 3], vertex[f * 3 + 1], vertex[f * 3 + 2]});
  }
  std::vector<int> index(vertex.size(), -1);
  int next = 1;
  out << "# foldkit flat net of " << mesh.name << ": " << loops.size() << " faces, " << u.piece_count
      << " pieces\n";
  if (folded > 0)
    out << "# " << folded
        << " non-planar input face(s) cut apart and written as their triangles: later faces shift\n";
  out.precision(17);
  for (const auto& loop : loops)
    for (int r : loop) {
      if (index[r] >= 0) continue;
      index[r] = next++;
      const Vec2 p = u.flat[r / 3][r % 3];
      out << "v " << p.x << ' ' << p.y << " 0\n";
    }
  int current = -1;
  for (const auto& loop : loops) {
    const int piece = u.piece_of_face[loop.front() / 3];
    if (piece != current) {
      current = piece;
      out << "g piece_" << current << "\n";
    }
    out << "f";
    for (int r : loop)
      out << ' ' << index[r];
    out << "\n";
  }
}

}  // namespace

void setup_unfold(CLI::App& app) {
  auto args = std::make_shared<UnfoldArgs>();
  CLI::App* cmd = app.add_subcommand("unfold", "Unfold a mesh and write the flat net as OBJ");
  cmd->add_option("mesh", args->mesh, "Mesh file (.obj, .off, .stl, .ply, .gltf, .glb)")->required();
  cmd->add_option("-o,--output", args->output,
                  "Flat net to write (.obj, or - for standard output); face k is face k of the input");
  cmd->add_flag("--json", args->json, "Print a JSON summary on stdout");
  cmd->add_flag("-q,--quiet", args->quiet, "No progress line");
  add_unfold_options(*cmd, args->unfold);
  // With --size the net is cut into the parts `make` would lay out on that paper.
  add_layout_options(*cmd, args->layout);
  cmd->callback([args] {
    const bool to_stdout = args->output == "-";
    if (to_stdout && args->json)
      throw Error("--json and the net would both go to standard output (-): choose one", ExitCode::Usage);
    refuse_output_over_inputs("-o", args->output,
                              {args->mesh, args->unfold.cut_file, args->unfold.keep_file});
    finish_unfold_options(args->unfold);
    const layout::LayoutOptions layout_options = to_layout_options(args->layout);
    ProgressLine line(!args->quiet);
    UnfoldRun run = load_and_unfold(args->mesh, args->unfold, line);
    choose_and_note_parts(run.loaded.mesh, run.result, layout_options);
    line.clear();
    const unfold::Unfolding& u = run.result.unfolding;
    if (!args->output.empty())
      devices::write_file_atomically(args->output,
                                     [&](std::ostream& out) { write_net_obj(out, run.loaded.mesh, u); });
    int cut_edges = 0;
    for (const auto& e : u.edges)
      cut_edges += e.cut ? 1 : 0;
    if (args->json) {
      nlohmann::json j{{"file", args->mesh},
                       {"face_count", u.num_faces()},
                       {"piece_count", u.piece_count},
                       {"cut_edge_count", cut_edges},
                       {"seam_count", u.seam_count()},
                       {"method", run.result.method},
                       {"unfold_s", run.result.seconds},
                       {"notes", run.loaded.notes}};
      for (const auto& n : run.result.notes)
        j["notes"].push_back(n);
      if (!args->output.empty()) j["output"] = args->output;
      std::cout << versioned(j).dump(2) << "\n";
    } else {
      for (const auto& n : run.loaded.notes)
        std::cerr << "note: " << n << "\n";
      for (const auto& n : run.result.notes)
        std::cerr << "note: " << n << "\n";
      // With -o - the net is on standard output: the summary must not be mixed into it.
      std::fprintf(to_stdout ? stderr : stdout,
                   "%s: %d faces -> %d piece%s, %d cut edges (%d seams), %.3f s (%s)%s%s\n",
                   args->mesh.c_str(), u.num_faces(), u.piece_count, u.piece_count == 1 ? "" : "s", cut_edges,
                   u.seam_count(), run.result.seconds, run.result.method.c_str(),
                   args->output.empty() ? "" : " -> ", args->output.c_str());
    }
  });
}

}  // namespace foldkit::cli
