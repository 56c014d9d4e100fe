// `foldkit cut MESH --device cameo4 --media cardstock-220`: load -> unfold -> lay out -> plan -> encode ->
// send, to a USB cutter, a file or device node (-o), or the simulated device (--dry-run, or no --device).
#include <algorithm>
#include <atomic>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <tuple>

#include <nlohmann/json.hpp>

#include "choices.hpp"
#include "cmd_cut.hpp"
#include "colour_options.hpp"
#include "commands.hpp"
#include "foldkit/devices/atomic_file.hpp"
#include "foldkit/devices/file_transport.hpp"
#include "foldkit/devices/gpgl.hpp"
#include "foldkit/devices/hpgl.hpp"
#include "foldkit/devices/plan.hpp"
#include "foldkit/devices/print_cut_preview.hpp"
#include "foldkit/devices/printed_marks.hpp"
#include "foldkit/devices/render.hpp"
#include "foldkit/devices/send.hpp"
#include "foldkit/devices/simulated_device.hpp"
#include "foldkit/devices/usb_transport.hpp"
#include "foldkit/error.hpp"
#include "installed_data.hpp"
#include "interrupt.hpp"
#include "json_report.hpp"
#include "layout_options.hpp"
#include "limits.hpp"
#include "output_paths.hpp"
#include "pipeline.hpp"
#include "profile_options.hpp"
#include "sim_faults.hpp"
#include "user_config.hpp"

namespace foldkit::cli {
namespace {

// plan_job, with a job that leaves the cutting area only because of the stored print-and-cut offset
// saying so: the user did not move the parts, the calibration did.
devices::Job plan_with_offset(const Sheet& sheet, const devices::DeviceProfile& device,
                              const devices::MediaProfile& media, const devices::PlanOptions& plan) {
  try {
    return devices::plan_job(sheet, device, media, plan);
  } catch (const DeviceError& e) {
    if (plan.print_cut_offset_mm == Vec2{0, 0}) throw;
    devices::PlanOptions without = plan;
    without.print_cut_offset_mm = {0, 0};
    try {
      (void)devices::plan_job(sheet, device, media, without);
    } catch (const DeviceError&) {
      throw e;  // the job does not fit even without the offset: the offset is not the cause
    }
    char note[200];
    std::snprintf(note, sizeof note,
                  " (only with the print-and-cut offset %+.2f, %+.2f mm `foldkit calibrate` stored for %s: "
                  "check it with `foldkit calibrate --device %s --show`)",
                  plan.print_cut_offset_mm.x, plan.print_cut_offset_mm.y, device.id.c_str(),
                  device.id.c_str());
    throw DeviceError(e.what() + std::string(note));
  }
}

std::uint16_t parse_usb_id(const std::string& text, const char* option) {
  std::size_t used = 0;
  unsigned long v = 0;
  try {
    v = std::stoul(text, &used, 16);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || text.empty() || v > 0xffff)
    throw Error(std::string(option) + " " + text + ": expected a hexadecimal USB id such as 1137",
                ExitCode::Usage);
  return static_cast<std::uint16_t>(v);
}

std::string duration(double s) {
  char buf[32];
  const long t = std::lround(s);
  if (t >= 60)
    std::snprintf(buf, sizeof buf, "%ldm%02lds", t / 60, t % 60);
  else
    std::snprintf(buf, sizeof buf, "%lds", t);
  return buf;
}

std::string lower_ext(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

struct SheetReport {
  devices::JobStats stats;
  std::size_t bytes = 0;
  std::string target;
  std::optional<double> simulated_cut_mm, simulated_travel_mm;
  std::vector<std::string> notes;
};

// The checks the parser cannot make alone, before any profile is looked up or work done. Returns whether
// the job goes to the simulated device.
bool check_cut_request(const CutArgs& args) {
  const bool simulated = args.dry_run || (args.device.empty() && args.output.empty());
  if (!args.sim_faults.empty() && !simulated)
    throw Error("--sim-fault needs the simulated device (--dry-run)", ExitCode::Usage);
  if (args.dry_run && !args.output.empty())
    throw Error(
        "--dry-run sends the job to the simulated device and -o writes it to a file: choose one "
        "(the simulated device's rendering goes to --preview)",
        ExitCode::Usage);
  if (args.device.empty() && !args.output.empty())
    throw Error("-o needs --device: the stream's language and units depend on the plotter", ExitCode::Usage);
  if (!args.preview.empty() && !simulated)
    throw Error("--preview is the simulated device's rendering: add --dry-run (and drop -o)",
                ExitCode::Usage);
  if (!args.overlay.empty() && !simulated)
    throw Error("--overlay draws the simulated device's cut over the print: add --dry-run (and drop -o)",
                ExitCode::Usage);
  if (!args.overlay.empty() && lower_ext(args.overlay) != ".png")
    throw Error("--overlay " + args.overlay + ": the overlay is a .png", ExitCode::Usage);
  if ((args.output == "-" || args.preview == "-") && args.json)
    throw Error("--json and the output would both go to standard output (-): choose one", ExitCode::Usage);
  return simulated;
}

std::vector<std::filesystem::path> cut_inputs(const CutArgs& args) {
  std::vector<std::filesystem::path> inputs{args.mesh, args.unfold.cut_file, args.unfold.keep_file};
  inputs.insert(inputs.end(), args.profiles.begin(), args.profiles.end());
  return inputs;
}

// -o names a file in the device's language (or a device node, or -).
void check_output_language(const CutArgs& args, const devices::DeviceProfile& device) {
  if (args.output.empty() || args.dry_run) return;
  const std::string ext = lower_ext(args.output);
  const bool hpgl_ext = ext == ".plt" || ext == ".hpgl" || ext == ".hpg";
  if (!hpgl_ext && ext != ".gpgl" && devices::resolve_output(args.output).kind == devices::OutputKind::File)
    throw Error("-o " + args.output +
                    ": a job is written to .plt, .hpgl or .hpg (HP-GL), .gpgl (GP-GL), a device node such "
                    "as /dev/usb/lp0, or - (standard output)",
                ExitCode::Usage);
  if ((hpgl_ext && device.protocol != devices::Protocol::Hpgl) ||
      (ext == ".gpgl" && device.protocol != devices::Protocol::Gpgl))
    throw Error("-o " + args.output + ": " + device.name + " speaks " +
                    (device.protocol == devices::Protocol::Gpgl ? "GP-GL (use .gpgl)" : "HP-GL (use .plt)"),
                ExitCode::Usage);
}

void override_usb_ids(const CutArgs& args, devices::DeviceProfile& device) {
  if (!args.usb_vid.empty()) device.usb_vendor = parse_usb_id(args.usb_vid, "--usb-vid");
  if (!args.usb_pid.empty()) device.usb_product = parse_usb_id(args.usb_pid, "--usb-pid");
}

// The layout options, with the registration marks the device is told to look for: the profile's
// geometry, unless the command line gives one (which the device is then told too).
layout::LayoutOptions cut_layout_options(const CutArgs& args, devices::DeviceProfile& device) {
  layout::LayoutOptions layout_options = to_layout_options(args.layout);
  layout::RegMarkOptions& marks = layout_options.regmark;
  devices::RegMarkSetup& device_marks = device.regmarks;
  if (args.regmark_arm_given)
    device_marks.arm_length_mm = marks.arm_mm;
  else
    marks.arm_mm = device_marks.arm_length_mm;
  if (args.regmark_inset_given)
    device_marks.inset_mm = marks.inset_mm;
  else
    marks.inset_mm = device_marks.inset_mm;
  // The square is the sensor's, not a setting: another size is printed as asked and then refused by
  // the planner, before anything is sent.
  if (!args.regmark_square_given) marks.square_mm = device_marks.square_mm;
  marks.stroke_mm = device_marks.stroke_mm;
  return layout_options;
}

devices::PlanOptions plan_options(const CutArgs& args, const layout::LayoutOptions& layout_options,
                                  const devices::DeviceProfile& device, const devices::StrokeFont* font) {
  devices::PlanOptions plan;
  plan.mat = args.mat;
  plan.draw_labels = args.labels;
  plan.font = font;
  plan.regmarks = layout_options.regmarks;
  // Print-and-cut applies what `foldkit calibrate --offset` stored for this device.
  if (plan.regmarks) plan.print_cut_offset_mm = stored_print_cut_offset_mm(device.id);
  plan.overcut_mm = args.overcut_mm;
  for (const auto& [name, method] : devices::fold_method_choices())
    if (args.fold_method == name) plan.fold_method = method;
  return plan;
}

// Everything the sheets of one cut share.
struct CutSession {
  const CutArgs& args;
  const devices::DeviceProfile& device;
  const devices::MediaProfile& media;
  const devices::PlanOptions& plan;
  const std::vector<Sheet>& sheets;
  const devices::SimFaults& faults;
  bool simulated = false;
  std::string preview;           ///< the simulated device's rendering; empty: none
  devices::RenderOptions print;  ///< the sheet as `make` prints it, for --overlay
  ProgressLine& line;
};

// Waits for the user to load sheet i (not before the first of a single-sheet job).
void wait_for_sheet(const CutSession& s, std::size_t i) {
  if (i == 0 && (s.args.sheet != 0 || s.sheets.size() == 1)) return;
  s.line.clear();
  std::cerr << "Load sheet " << i + 1 << " of " << s.sheets.size() << " and press Enter (Ctrl-C stops) ";
  std::string ignored;
  if (!std::getline(std::cin, ignored))
    throw Error("stopped before sheet " + std::to_string(i + 1), ExitCode::Interrupted);
}

// "sheet 2/3: " in front of progress of a job of several sheets.
std::string sheet_label(const CutSession& s, std::size_t i) {
  return s.sheets.size() > 1 ? "sheet " + std::to_string(i + 1) + "/" + std::to_string(s.sheets.size()) + ": "
                             : "";
}

devices::SendOptions send_options(const CutSession& s, const devices::Job& job, const std::string& label) {
  devices::SendOptions send;
  send.protocol = job.protocol;
  send.estimated_s = job.stats.estimated_s;
  send.ready_timeout = std::chrono::milliseconds(std::lround(s.args.ready_timeout_s * 1000));
  if (job.protocol == devices::Protocol::Gpgl) send.abort_tail = devices::gpgl_abort_tail(job);
  ProgressLine& line = s.line;
  send.progress = [&line, label](const devices::SendProgress& p) {
    if (p.waiting_for == devices::DeviceState::Paused) {
      line.update(label + "waiting: the device is paused or not ready (press its pause key; Ctrl-C stops)");
      return;
    }
    if (p.waiting_for == devices::DeviceState::Busy) {
      line.update(label + "waiting for the device to take more data");
      return;
    }
    line.update(label + "sent " +
                std::to_string(100 * p.bytes_sent / std::max<std::size_t>(p.bytes_total, 1)) + "%, " +
                std::to_string(p.strokes_done) + "/" + std::to_string(p.strokes_total) + " strokes, ~" +
                duration(p.seconds_left) + " left");
  };
  return send;
}

std::unique_ptr<devices::SimulatedDevice> open_simulated(const CutSession& s, std::size_t i,
                                                         const devices::Job& job) {
  devices::SimOptions so;
  so.mat = s.args.mat;
  so.faults = s.faults;
  so.sheet_mm = s.sheets[i].size_mm;
  so.printed_marks = devices::printed_marks(s.sheets[i]);
  for (const devices::Pass& p : job.passes)
    so.mounted[p.holder] = p.tool;
  return std::make_unique<devices::SimulatedDevice>(s.device, so);
}

// Where sheet i goes: the simulated device, a file or device node (-o), or the cutter on USB.
std::unique_ptr<devices::Transport> open_transport(const CutSession& s, std::size_t i,
                                                   const devices::Job& job,
                                                   const devices::SendOptions& send) {
  if (s.simulated) return open_simulated(s, i, job);
  if (!s.args.output.empty()) {
    // A device node is a cutter too: each sheet after the first needs fresh media.
    if (devices::resolve_output(s.args.output).kind == devices::OutputKind::Node) wait_for_sheet(s, i);
    // A device node that stops taking data is a busy cutter: the same bound as over USB.
    return std::make_unique<devices::FileTransport>(sheet_output_path(s.args.output, i), send.ready_timeout);
  }
  const devices::DeviceProfile& device = s.device;
  if (device.usb_vendor == 0)
    throw DeviceError(device.name +
                      " has no USB id: use -o /dev/usb/lp0 (or a serial port), or --usb-vid and --usb-pid");
  wait_for_sheet(s, i);
  devices::UsbSelector sel;
  sel.id = {device.usb_vendor, device.usb_product, device.name};
  devices::UsbOptions usb;
  // HP-GL cutters and Graphtec's own GP-GL have no ESC 0x05 status query.
  usb.gpgl_status =
      device.protocol == devices::Protocol::Gpgl && device.gpgl_family != devices::GpglFamily::Graphtec;
  usb.ready_timeout = send.ready_timeout;
  return devices::open_usb_cutter(sel, usb);
}

// Sends the stream; a failure on the simulated device says how far a real one would have got, and why.
devices::SendResult send_sheet(const CutSession& s, std::size_t i, const std::string& stream,
                               devices::Transport& transport, devices::SimulatedDevice* sim,
                               const devices::SendOptions& send, const ScopedCancel& cancel_on_signal,
                               const std::string& label, const std::string& target) {
  devices::SendResult result;
  try {
    result = devices::send_job(devices::stream_bytes(stream), transport, send);
    transport.close();
  } catch (const DeviceError& e) {
    if (!sim) throw;
    s.line.clear();
    std::string what = e.what();
    if (!sim->marks_problem().empty()) what += " (" + sim->marks_problem() + ")";
    if (!s.preview.empty()) {
      const auto partial = sheet_output_path(s.preview, i);
      sim->render(partial);
      what += "; " + std::to_string(sim->strokes().size()) + " strokes were done, partial picture in " +
              partial.string();
    }
    throw DeviceError(what);
  }
  s.line.clear();
  if (result.cancelled) {
    const bool term = cancel_on_signal.signal() == SIGTERM;
    throw Error(std::string(term ? "stopped by SIGTERM" : "stopped by Ctrl-C") + " after " +
                    std::to_string(result.strokes_done) + " of " + std::to_string(result.strokes_total) +
                    " strokes of " + (label.empty() ? "the sheet" : label.substr(0, label.size() - 2)) +
                    " (" + target +
                    "): the tool was raised and the job ended; the pieces cut so far "
                    "are usable, the rest of the sheet is not cut",
                term ? ExitCode::Terminated : ExitCode::Interrupted);
  }
  return result;
}

// What the simulated device did with sheet i: the figures, its rendering and the overlay.
void finish_simulated(const CutSession& s, std::size_t i, const devices::SimulatedDevice& sim,
                      SheetReport& rep) {
  if (sim.model().from_profile)
    rep.notes.push_back("no built-in model of the " + s.device.name +
                        ": the simulated device checked the job against its profile only");
  rep.simulated_cut_mm = sim.down_length_mm();
  rep.simulated_travel_mm = sim.travel_mm();
  if (!s.preview.empty()) sim.render(sheet_output_path(s.preview, i));
  if (!s.args.overlay.empty())
    devices::render_print_and_cut(s.sheets[i], devices::simulated_cuts_mm(sim, s.device, s.args.mat),
                                  sheet_output_path(s.args.overlay, i), s.print);
}

// Sheet i: planned and bounds-checked before a byte is sent, encoded, sent, reported.
SheetReport cut_sheet(const CutSession& s, std::size_t i) {
  s.line.update("planning sheet " + std::to_string(i + 1));
  const devices::Job job = plan_with_offset(s.sheets[i], s.device, s.media, s.plan);
  const std::string stream =
      job.protocol == devices::Protocol::Gpgl ? devices::encode_gpgl(job) : devices::encode_hpgl(job);
  SheetReport rep;
  rep.stats = job.stats;
  rep.bytes = stream.size();
  rep.notes = job.notes;
  if (s.plan.print_cut_offset_mm != Vec2{0, 0}) {
    char note[160];
    std::snprintf(note, sizeof note,
                  "cuts moved by %+.2f, %+.2f mm: the print-and-cut offset `foldkit calibrate` stored",
                  s.plan.print_cut_offset_mm.x, s.plan.print_cut_offset_mm.y);
    rep.notes.push_back(note);
  }
  const std::string label = sheet_label(s, i);
  devices::SendOptions send = send_options(s, job, label);
  std::unique_ptr<devices::Transport> transport = open_transport(s, i, job, send);
  auto* sim = s.simulated ? static_cast<devices::SimulatedDevice*>(transport.get()) : nullptr;
  rep.target = transport->describe();
  std::atomic<bool> cancel{false};
  const ScopedCancel cancel_on_signal(cancel);
  send.cancel = &cancel;
  send_sheet(s, i, stream, *transport, sim, send, cancel_on_signal, label, rep.target);
  if (sim) finish_simulated(s, i, *sim, rep);
  return rep;
}

nlohmann::json cut_json(const CutArgs& args, const CutSession& s, const std::vector<SheetReport>& reports) {
  nlohmann::json js = nlohmann::json::array();
  for (const SheetReport& r : reports) {
    nlohmann::json j{{"target", r.target},
                     {"byte_count", r.bytes},
                     {"stroke_count", r.stats.strokes},
                     {"cut_length_mm", r.stats.cut_length_mm},
                     {"travel_before_mm", r.stats.travel_before_mm},
                     {"travel_after_mm", r.stats.travel_after_mm},
                     {"estimated_s", r.stats.estimated_s},
                     {"notes", r.notes}};
    if (r.simulated_cut_mm) j["simulated_tool_down_mm"] = *r.simulated_cut_mm;
    if (r.simulated_travel_mm) j["simulated_travel_mm"] = *r.simulated_travel_mm;
    js.push_back(j);
  }
  return versioned({{"file", args.mesh},
                    {"device", s.device.id},
                    {"media", s.media.id},
                    {"simulated", s.simulated},
                    {"sheets", js}});
}

void print_cut_summary(const CutArgs& args, const CutSession& s, const std::vector<SheetReport>& reports) {
  // With -o - the job is on standard output: the summary must not be mixed into it.
  std::FILE* const report = args.output == "-" || args.preview == "-" ? stderr : stdout;
  for (const SheetReport& r : reports) {
    for (const auto& n : r.notes)
      std::cerr << "note: " << n << "\n";
    std::fprintf(
        report,
        "%s -> %s: %zu strokes, tool down %.0f mm, pen-up travel %.0f mm (%.0f mm in sheet order), ~%s\n",
        args.mesh.c_str(), r.target.c_str(), r.stats.strokes, r.stats.cut_length_mm, r.stats.travel_after_mm,
        r.stats.travel_before_mm, duration(r.stats.estimated_s).c_str());
  }
  if (s.simulated && !s.preview.empty())
    std::fprintf(report, "rendering of the simulated cut: %s%s\n", s.preview.c_str(),
                 reports.size() > 1 ? " (one per sheet)" : "");
  if (!args.overlay.empty())
    std::fprintf(report, "the simulated cut over the print: %s%s\n", args.overlay.c_str(),
                 reports.size() > 1 ? " (one per sheet)" : "");
}

// The preview's name: --preview, else <mesh>-cut.png for the simulated device.
std::string preview_path(const CutArgs& args, bool simulated) {
  if (!args.preview.empty()) return args.preview;
  return simulated ? std::filesystem::path(args.mesh).stem().string() + "-cut.png" : "";
}

}  // namespace

void run_cut(CutArgs args) {
  const devices::SimFaults faults = parse_faults(args.sim_faults);
  const devices::ProfileSet profiles = load_cli_profiles(args.profiles);
  const bool simulated = check_cut_request(args);
  const std::vector<std::filesystem::path> inputs = cut_inputs(args);
  refuse_output_over_inputs("-o", args.output, inputs);
  refuse_output_over_inputs("--preview", args.preview, inputs);
  refuse_output_over_inputs("--overlay", args.overlay, inputs);
  // A typical two-holder cutter stands in when no device is named.
  devices::DeviceProfile device = device_option(profiles, args.device.empty() ? "cameo4" : args.device);
  const devices::MediaProfile& media = media_option(profiles, args.media);
  override_usb_ids(args, device);
  check_output_language(args, device);
  if (args.device.empty() && !args.json)
    std::cerr << "foldkit: no --device given: sending to a simulated " << device.name
              << " (nothing is cut; name a device to cut for real)\n";
  finish_unfold_options(args.unfold);
  const layout::LayoutOptions layout_options = cut_layout_options(args, device);
  // Pen labels need the font: a missing one is found out before the pipeline, not after it.
  std::optional<devices::StrokeFont> font;
  if (args.labels) font = load_label_font();
  ProgressLine line(!args.quiet && !args.json);
  // The colour options move pieces (the bleed widens their spacing): taken so that a cut matches the
  // coloured sheet `make` printed with the same options.
  const PipelineRun run = load_unfold_layout(args.mesh, args.unfold, layout_options, line,
                                             to_fill_options(args.colour), choose_options_of(args.layout));
  const std::vector<Sheet>& sheets = run.layout.sheets;
  if (args.sheet > static_cast<int>(sheets.size()))
    throw Error("--sheet " + std::to_string(args.sheet) + ": the layout has " +
                    std::to_string(sheets.size()) + " sheet(s)",
                ExitCode::Usage);
  const devices::PlanOptions plan = plan_options(args, layout_options, device, font ? &*font : nullptr);
  CutSession s{args, device, media, plan, sheets, faults, simulated, preview_path(args, simulated), {}, line};
  for (std::size_t i = 1; i < sheets.size(); ++i) {
    refuse_output_over_inputs("-o", sheet_output_path(args.output, i), inputs);
    refuse_output_over_inputs("--preview", sheet_output_path(s.preview, i), inputs);
    refuse_output_over_inputs("--overlay", sheet_output_path(args.overlay, i), inputs);
  }
  // The overlay prints the sheet as `make` does with the same colour options.
  apply_colour_render_options(
      args.colour, std::any_of(sheets.begin(), sheets.end(), [](const Sheet& x) { return !x.fills.empty(); }),
      s.print);
  std::vector<SheetReport> reports;
  for (std::size_t i = 0; i < sheets.size(); ++i)
    if (args.sheet == 0 || i + 1 == static_cast<std::size_t>(args.sheet)) reports.push_back(cut_sheet(s, i));
  line.clear();
  if (args.json)
    std::cout << cut_json(args, s, reports).dump(2) << "\n";
  else
    print_cut_summary(args, s, reports);
}

void setup_cut(CLI::App& app) {
  auto args = std::make_shared<CutArgs>();
  CLI::App* cmd = app.add_subcommand(
      "cut",
      "Unfold a mesh, lay it out and send it to a cutting plotter (or a file, or the simulated device)");
  cmd->add_option("mesh", args->mesh, "Mesh file (.obj, .off, .stl, .ply, .gltf, .glb)")->required();
  cmd->add_option("--device", args->device, "Device profile id (see `foldkit profiles`); none: simulated");
  cmd->add_option("--media", args->media, "Media profile id (see `foldkit profiles`)")->capture_default_str();
  cmd->add_option("--mat", args->mat, "Mat id of the device (default: its first)");
  cmd->add_flag("--dry-run", args->dry_run,
                "Send to the simulated device: check every command, write its rendering and job statistics");
  cmd->add_option("-o,--output", args->output,
                  "Write the stream instead of sending: job.plt / job.hpgl (HP-GL), job.gpgl (GP-GL), or a "
                  "device node such as /dev/usb/lp0");
  cmd->add_option("--preview", args->preview,
                  "Rendering of what the simulated device cut, scored and drew (.png or .svg); default "
                  "<mesh>-cut.png with --dry-run");
  cmd->add_option("--overlay", args->overlay,
                  "With --dry-run: the sheet as `make` prints it (.png) with what the simulated device cut "
                  "drawn over it in red, so a cut that misses its print shows (one file per sheet)");
  add_profile_options(*cmd, args->profiles);
  cmd->add_option("--usb-vid", args->usb_vid, "USB vendor id (hex) overriding the profile's");
  cmd->add_option("--usb-pid", args->usb_pid, "USB product id (hex) overriding the profile's");
  cmd->add_flag("--draw-labels", args->labels,
                "Draw edge numbers and labels with a pen in the second holder");
  const std::vector<std::string> fold_methods = choice_names(devices::fold_method_choices());
  cmd->add_option("--fold-method", args->fold_method,
                  "How folds are marked: " + joined(fold_methods) + " (default: profile and media)")
      ->check(CLI::IsMember(fold_methods));
  add_length_option(*cmd, "--overcut", args->overcut_mm, "Closed cuts continue this far past their start",
                    kOvercut);
  cmd->add_option("--sheet", args->sheet, "Only this sheet (1-based); default all")
      ->check(number_in(1, kMaxSheets));
  cmd->add_option("--ready-timeout", args->ready_timeout_s,
                  "Longest wait for a busy or paused device before giving up, seconds")
      ->check(number_in(0.1, 3600, "s"))
      ->capture_default_str();
  cmd->add_option("--sim-fault", args->sim_faults,
                  "Make the simulated device fail: not-ready, no-media, marks-not-found, disconnect=BYTES, "
                  "stall=BYTES (repeatable)");
  cmd->add_flag("--json", args->json, "Print a JSON report on stdout");
  cmd->add_flag("-q,--quiet", args->quiet, "No progress line");
  add_layout_options(*cmd, args->layout);
  add_colour_options(*cmd, args->colour);
  add_unfold_options(*cmd, args->unfold);

  cmd->callback([args, cmd] {
    args->regmark_arm_given = cmd->count("--regmark-arm") > 0;
    args->regmark_inset_given = cmd->count("--regmark-inset") > 0;
    args->regmark_square_given = cmd->count("--regmark-square") > 0;
    run_cut(*args);
  });
}

}  // namespace foldkit::cli
