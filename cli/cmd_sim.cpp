// `foldkit sim FILE --device cameo4`: replays an existing .gpgl / .plt stream (written by foldkit or by
// another program) on the simulated machine and reports what it would cut, with the same checks as a
// dry run.
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cmd_sim.hpp"
#include "commands.hpp"
#include "foldkit/devices/job.hpp"
#include "foldkit/devices/send.hpp"
#include "foldkit/devices/simulated_device.hpp"
#include "foldkit/error.hpp"
#include "foldkit/layout/paper.hpp"
#include "json_report.hpp"
#include "limits.hpp"
#include "profile_options.hpp"
#include "sim_faults.hpp"

namespace foldkit::cli {
namespace {

// A cutter job is a few MB at most; anything larger is not a job and is refused before it is read.
constexpr std::uintmax_t kMaxStreamBytes = 64u << 20;

std::string read_stream(const std::string& path) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec) throw InputError(path, "cannot read: " + ec.message());
  if (size > kMaxStreamBytes)
    throw InputError(path, "is " + std::to_string(size >> 20) + " MiB; a cutter job is at most " +
                               std::to_string(kMaxStreamBytes >> 20) + " MiB");
  std::ifstream in(path, std::ios::binary);
  std::stringstream buf;
  buf << in.rdbuf();
  if (!in && !in.eof()) throw InputError(path, "read failed");
  return buf.str();
}

void check_language(const std::string& path, const devices::DeviceProfile& device) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const bool hpgl_ext = ext == ".plt" || ext == ".hpgl" || ext == ".hpg";
  if ((hpgl_ext && device.protocol != devices::Protocol::Hpgl) ||
      (ext == ".gpgl" && device.protocol != devices::Protocol::Gpgl))
    throw InputError(path, "is " + std::string(hpgl_ext ? "HP-GL" : "GP-GL") + " but the " + device.name +
                               " speaks " + (device.protocol == devices::Protocol::Gpgl ? "GP-GL" : "HP-GL"));
}

}  // namespace

void run_sim(const SimArgs& args) {
  const devices::SimFaults faults = parse_faults(args.sim_faults);
  const auto paper = layout::parse_paper(args.paper);
  if (!paper)
    throw Error("--paper " + args.paper + ": unknown paper (use " + layout::paper_names() + ")",
                ExitCode::Usage);
  const devices::ProfileSet profiles = load_cli_profiles(args.profiles);
  const devices::DeviceProfile& device = device_option(profiles, args.device);
  check_language(args.file, device);
  const std::string stream = read_stream(args.file);

  devices::SimOptions so;
  so.mat = args.mat;
  so.faults = faults;
  so.sheet_mm = *paper;
  devices::SimulatedDevice sim(device, so);
  devices::SendOptions send;
  send.protocol = device.protocol;
  send.poll_interval = std::chrono::milliseconds(1);
  send.ready_timeout = std::chrono::milliseconds(200);
  try {
    devices::send_job(devices::stream_bytes(stream), sim, send);
    sim.close();
  } catch (const DeviceError& e) {
    std::string what = args.file + ": " + e.what();
    if (!sim.marks_problem().empty()) what += " (" + sim.marks_problem() + ")";
    if (!args.preview.empty()) {
      sim.render(args.preview);
      what += "; " + std::to_string(sim.strokes().size()) + " strokes were done, partial picture in " +
              args.preview;
    }
    throw DeviceError(what);
  }
  if (!args.preview.empty()) sim.render(args.preview);
  const Box2 b = sim.cut_bounds_mm();
  const std::string checked_against =
      sim.model().from_profile ? "its profile (no built-in model)" : "its built-in machine model";
  if (args.json) {
    nlohmann::json j{{"file", args.file},
                     {"device", device.id},
                     {"checked_against", sim.model().from_profile ? "profile" : "model"},
                     {"byte_count", stream.size()},
                     {"stroke_count", sim.strokes().size()},
                     {"tool_down_mm", sim.down_length_mm()},
                     {"travel_mm", sim.travel_mm()}};
    if (!b.empty()) j["bounds_mm"] = {b.min.x, b.min.y, b.max.x, b.max.y};
    std::cout << versioned(j).dump(2) << "\n";
    return;
  }
  std::printf("%s on the simulated %s (checked against %s): %zu strokes, tool down %.0f mm, travel %.0f mm",
              args.file.c_str(), device.name.c_str(), checked_against.c_str(), sim.strokes().size(),
              sim.down_length_mm(), sim.travel_mm());
  if (!b.empty())
    std::printf(", on the sheet %.1f..%.1f x %.1f..%.1f mm", b.min.x, b.max.x, b.min.y, b.max.y);
  std::printf("\n");
  if (!args.preview.empty()) std::printf("rendering: %s\n", args.preview.c_str());
}

void setup_sim(CLI::App& app) {
  auto args = std::make_shared<SimArgs>();
  CLI::App* cmd = app.add_subcommand(
      "sim", "Replay a .gpgl or .plt job on the simulated cutter and report what it would cut");
  cmd->add_option("file", args->file, "The job: .gpgl (GP-GL) or .plt / .hpgl (HP-GL)")->required();
  cmd->add_option("--device", args->device, "Device profile id whose machine runs the job")->required();
  cmd->add_option("--mat", args->mat, "Mat loaded (default: the machine's first)");
  cmd->add_option("--paper", args->paper, "The sheet loaded: " + layout::paper_names())
      ->check(paper_in(kSheetSide))
      ->capture_default_str();
  cmd->add_option("--preview", args->preview, "Rendering of what was cut (.png or .svg)");
  cmd->add_option("--sim-fault", args->sim_faults,
                  "Make the simulated device fail: not-ready, no-media, marks-not-found, disconnect=BYTES, "
                  "stall=BYTES (repeatable)");
  add_profile_options(*cmd, args->profiles);
  cmd->add_flag("--json", args->json, "Print a JSON report on stdout");

  cmd->callback([args] { run_sim(*args); });
}

}  // namespace foldkit::cli
