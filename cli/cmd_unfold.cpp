// `foldkit unfold MESH -o net.obj [--json]`: the flat net alone, for inspection or other tools.
#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <numeric>
#include <ostream>
#include <string>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "foldkit/devices/atomic_file.hpp"
#include "foldkit/error.hpp"
#include "output_paths.hpp"
#include "unfold_options.hpp"

namespace foldkit::cli {
namespace {

struct UnfoldArgs {
  std::string mesh;
  std::string output;
  bool json = false;
  bool quiet = false;
  UnfoldCliOptions unfold;
};

// One OBJ vertex per group of flat corners joined through folds: corners of one mesh vertex in one
// piece share a vertex where the piece is folded there, and no vertex is shared between pieces.
void write_net_obj(std::ostream& out, const unfold::Mesh& mesh, const unfold::Unfolding& u) {
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
  std::vector<int> index(parent.size(), -1);
  int next = 1;
  out << "# foldkit flat net of " << mesh.name << ": " << nf << " faces, " << u.piece_count << " pieces\n";
  out.precision(17);
  for (int c = 0; c < 3 * nf; ++c) {
    int r = find(c);
    if (index[r] >= 0) continue;
    index[r] = next++;
    Vec2 p = u.flat[r / 3][r % 3];
    out << "v " << p.x << ' ' << p.y << " 0\n";
  }
  int current = -1;
  for (int f = 0; f < nf; ++f) {
    if (u.piece_of_face[f] != current) {
      current = u.piece_of_face[f];
      out << "g piece_" << current << "\n";
    }
    out << "f " << index[find(f * 3)] << ' ' << index[find(f * 3 + 1)] << ' ' << index[find(f * 3 + 2)]
        << "\n";
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
  cmd->callback([args] {
    const bool to_stdout = args->output == "-";
    if (to_stdout && args->json)
      throw Error("--json and the net would both go to standard output (-): choose one", ExitCode::Usage);
    refuse_output_over_inputs("-o", args->output,
                              {args->mesh, args->unfold.cut_file, args->unfold.keep_file});
    finish_unfold_options(args->unfold);
    ProgressLine line(!args->quiet);
    UnfoldRun run = load_and_unfold(args->mesh, args->unfold, line);
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
                       {"faces", u.num_faces()},
                       {"pieces", u.piece_count},
                       {"cut_edges", cut_edges},
                       {"seams", u.seam_count()},
                       {"method", run.result.method},
                       {"seconds", run.result.seconds},
                       {"notes", run.loaded.notes}};
      for (const auto& n : run.result.notes)
        j["notes"].push_back(n);
      if (!args->output.empty()) j["output"] = args->output;
      std::cout << j.dump(2) << "\n";
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
