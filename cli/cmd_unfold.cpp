// `foldkit unfold MESH -o net.obj [--json]`: the flat net alone, for inspection or other tools.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <numeric>
#include <optional>
#include <ostream>
#include <string>

#include <nlohmann/json.hpp>

#include "cmd_unfold.hpp"
#include "commands.hpp"
#include "foldkit/devices/atomic_file.hpp"
#include "foldkit/error.hpp"
#include "foldkit/unfold/net_obj.hpp"
#include "json_report.hpp"
#include "output_paths.hpp"
#include "pipeline.hpp"
#include "print_cuts.hpp"

namespace foldkit::cli {
namespace {

// The summary on stdout (or stderr when the net goes to stdout): notes, then one line.
void print_summary(const UnfoldArgs& args, const UnfoldRun& run, int cut_edges) {
  const unfold::Unfolding& u = run.result.unfolding;
  for (const auto& n : run.loaded.notes)
    std::cerr << "note: " << n << "\n";
  for (const auto& n : run.result.notes)
    std::cerr << "note: " << n << "\n";
  // With -o - the net is on standard output: the summary must not be mixed into it.
  std::fprintf(args.output == "-" ? stderr : stdout,
               "%s: %d faces -> %d piece%s, %d cut edges (%d seams), %.3f s (%s)%s%s\n", args.mesh.c_str(),
               u.num_faces(), u.piece_count, u.piece_count == 1 ? "" : "s", cut_edges, u.seam_count(),
               run.result.seconds, run.result.method.c_str(), args.output.empty() ? "" : " -> ",
               args.output.c_str());
}

// At a fixed size, the scale of the net and the room every part was fitted to (at the gap the parts
// were chosen at, which may be closer than asked where that saved a sheet): what a script needs to check
// the parts against the paper (tests/tools/net_check.py).
struct PartRoom {
  double mm_per_unit = 0;
  Vec2 room_mm;
};

std::optional<PartRoom> part_room(const unfold::Unfolding& u, layout::LayoutOptions o,
                                  const std::optional<layout::LayoutResult>& laid_out) {
  if (!o.size_mm || o.fit || !(u.model_extent > 0)) return std::nullopt;
  if (laid_out) o.pack.spacing_mm = laid_out->spacing_mm;
  return PartRoom{*o.size_mm / u.model_extent, layout::piece_room_mm(o)};
}

nlohmann::json summary_json(const UnfoldArgs& args, const UnfoldRun& run, int cut_edges,
                            const std::optional<PartRoom>& room) {
  const unfold::Unfolding& u = run.result.unfolding;
  nlohmann::json j{{"file", args.mesh},
                   {"face_count", u.num_faces()},
                   {"piece_count", u.piece_count},
                   {"cut_edge_count", cut_edges},
                   {"seam_count", u.seam_count()},
                   {"method", run.result.method},
                   {"unfold_s", run.result.seconds},
                   {"notes", run.loaded.notes}};
  for (const auto& n : run.result.notes)
    j["notes"].push_back(n);
  if (!args.output.empty()) j["output"] = args.output;
  if (room) {
    j["scale_mm_per_unit"] = room->mm_per_unit;
    j["part_room_mm"] = {room->room_mm.x, room->room_mm.y};
  }
  return j;
}

}  // namespace

void run_unfold(UnfoldArgs args) {
  if (args.output == "-" && args.json)
    throw Error("--json and the net would both go to standard output (-): choose one", ExitCode::Usage);
  refuse_output_over_inputs("-o", args.output, {args.mesh, args.unfold.cut_file, args.unfold.keep_file});
  finish_unfold_options(args.unfold);
  const layout::LayoutOptions asked_layout = to_layout_options(args.layout);
  layout::check_options(asked_layout);
  ProgressLine line(!args.quiet);
  // The cuts of the parts `make` would print at this size (choose_and_note_parts below).
  UnfoldRun run = load_and_unfold(args.mesh, args.unfold, line,
                                  [&](const unfold::LoadedMesh& loaded, unfold::UnfoldOptions& o) {
                                    o.cuts = cuts_for_print(loaded.mesh, asked_layout, o.cuts);
                                  });
  // The parts of make's default colour options: a coloured model keeps the gap its bleed needs.
  const layout::LayoutOptions layout_options =
      with_bleed_gap(asked_layout, run.loaded.mesh, layout::FillOptions{});
  std::optional<layout::LayoutResult> laid_out;
  try {
    laid_out = choose_and_note_parts(
        run, layout_options,
        bleed_room(choose_options_of(args.layout), run.loaded.mesh, layout::FillOptions{}));
  } catch (const LayoutError& e) {
    throw naming_mesh(args.mesh, e);
  }
  line.clear();
  const unfold::Unfolding& u = run.result.unfolding;
  if (!args.output.empty())
    devices::write_file_atomically(
        args.output, [&](std::ostream& out) { unfold::write_net_obj(out, run.loaded.mesh, u); });
  int cut_edges = 0;
  for (const auto& e : u.edges)
    cut_edges += e.cut ? 1 : 0;
  if (args.json)
    std::cout << versioned(summary_json(args, run, cut_edges, part_room(u, layout_options, laid_out))).dump(2)
              << "\n";
  else
    print_summary(args, run, cut_edges);
}

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
  cmd->callback([args] { run_unfold(*args); });
}

}  // namespace foldkit::cli
