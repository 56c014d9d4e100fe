// `foldkit calibrate --device cameo4`: the print-and-cut calibration page (PDF to print) and its cut job
// (short cuts through the printed crosses, relative to the registration marks), checked on the simulated
// device first; `--offset DX,DY[mm]` stores what the user measured, and every later `cut --regmarks` on
// that device applies it.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "cmd_calibrate.hpp"
#include "commands.hpp"
#include "foldkit/devices/calibration.hpp"
#include "foldkit/devices/file_transport.hpp"
#include "foldkit/devices/gpgl.hpp"
#include "foldkit/devices/plan.hpp"
#include "foldkit/devices/print_cut_preview.hpp"
#include "foldkit/devices/render.hpp"
#include "foldkit/devices/send.hpp"
#include "foldkit/devices/simulated_device.hpp"
#include "foldkit/error.hpp"
#include "foldkit/layout/calibration_page.hpp"
#include "foldkit/layout/paper.hpp"
#include "json_report.hpp"
#include "limits.hpp"
#include "profile_options.hpp"
#include "user_config.hpp"

namespace foldkit::cli {
namespace {

// One signed length through the one length parser: "-1.2mm" is minus "1.2mm".
std::optional<double> signed_length_mm(const std::string& text) {
  const bool negative = !text.empty() && text[0] == '-';
  const auto mm = layout::parse_non_negative_length_mm(negative ? text.substr(1) : text);
  if (!mm) return std::nullopt;
  return negative ? -*mm : *mm;
}

// "DX,DY" with a unit after either or after the pair ("0.8,-1.2mm": both mm; no unit: mm).
Vec2 parse_offset(const std::string& text) {
  const auto bad = [&]() {
    return Error("--offset " + text + ": expected DX,DY in mm, e.g. 0.8,-1.2mm", ExitCode::Usage);
  };
  const auto comma = text.find(',');
  if (comma == std::string::npos) throw bad();
  std::string xs = text.substr(0, comma);
  const std::string ys = text.substr(comma + 1);
  // A unit written once, after the pair, is the unit of both numbers.
  const auto unit_at = ys.find_last_not_of("abcdefghijklmnopqrstuvwxyz");
  const auto xs_unit = xs.find_last_not_of("abcdefghijklmnopqrstuvwxyz");
  if (unit_at != std::string::npos && xs_unit == xs.size() - 1) xs += ys.substr(unit_at + 1);
  const auto x = signed_length_mm(xs), y = signed_length_mm(ys);
  if (!x || !y) throw bad();
  if (std::abs(*x) > devices::kMaxPrintCutOffsetMm || std::abs(*y) > devices::kMaxPrintCutOffsetMm) {
    char buf[160];
    std::snprintf(buf, sizeof buf,
                  "--offset %s: at most %.0f mm on each axis (measure again on a freshly loaded sheet)",
                  text.c_str(), devices::kMaxPrintCutOffsetMm);
    throw Error(buf, ExitCode::Usage);
  }
  return {*x, *y};
}

std::string mm_pair(Vec2 v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%+.2f, %+.2f mm", v.x, v.y);
  return buf;
}

void show_offset(const CalibrateArgs& args, const devices::DeviceProfile& device) {
  const auto file = devices::calibration_file(user_config_dir(), device.id);
  const auto stored = devices::load_calibration(file, device.id);
  const Vec2 offset = stored ? stored->offset_mm : Vec2{0, 0};
  if (args.json) {
    std::cout << versioned({{"device", device.id},
                            {"file", file.string()},
                            {"stored", stored.has_value()},
                            {"offset_mm", {offset.x, offset.y}}})
                     .dump(2)
              << "\n";
  } else if (stored) {
    std::printf("%s: print-and-cut offset %s (%s)\n", device.name.c_str(), mm_pair(offset).c_str(),
                file.string().c_str());
  } else {
    std::printf("%s: no print-and-cut offset stored (%s would hold it)\n", device.name.c_str(),
                file.string().c_str());
  }
}

void store_offset(const CalibrateArgs& args, const devices::DeviceProfile& device) {
  const auto file = devices::calibration_file(user_config_dir(), device.id);
  if (args.reset) {
    std::error_code ec;
    std::filesystem::remove(file, ec);
    if (ec) throw OutputError(file.string(), "cannot remove: " + ec.message());
    if (args.json)
      std::cout << versioned({{"device", device.id}, {"file", file.string()}, {"offset_mm", {0, 0}}}).dump(2)
                << "\n";
    else
      std::printf("%s: print-and-cut offset removed (%s)\n", device.name.c_str(), file.string().c_str());
    return;
  }
  const Vec2 offset = parse_offset(args.offset);
  devices::save_calibration(file, {device.id, offset});
  if (args.json) {
    std::cout << versioned(
                     {{"device", device.id}, {"file", file.string()}, {"offset_mm", {offset.x, offset.y}}})
                     .dump(2)
              << "\n";
    return;
  }
  std::printf(
      "%s: print-and-cut offset %s stored in %s; every `foldkit cut --regmarks --device %s` moves its cuts "
      "by it\n",
      device.name.c_str(), mm_pair(offset).c_str(), file.string().c_str(), device.id.c_str());
}

// The page for `device`'s marks on `paper_text`.
layout::CalibrationPage page_for(const devices::DeviceProfile& device, const std::string& paper_text) {
  if (!device.regmarks.supported || device.protocol != devices::Protocol::Gpgl)
    throw Error(device.name + " cannot search registration marks: there is no print-and-cut to calibrate",
                ExitCode::Device);
  const auto paper = layout::parse_paper(paper_text);
  if (!paper)
    throw Error("--paper " + paper_text + ": unknown (" + layout::paper_names() + ")", ExitCode::Usage);
  layout::CalibrationOptions co;
  co.paper_mm = *paper;
  co.regmark.square_mm = device.regmarks.square_mm;
  co.regmark.arm_mm = device.regmarks.arm_length_mm;
  co.regmark.stroke_mm = device.regmarks.stroke_mm;
  co.regmark.inset_mm = device.regmarks.inset_mm;
  return layout::calibration_page(co);
}

struct CalibrationFiles {
  std::string pdf, job, preview;
};

CalibrationFiles files_for(const CalibrateArgs& args, const devices::DeviceProfile& device) {
  const std::string stem = "calibration-" + device.id;
  CalibrationFiles f{args.pdf.empty() ? stem + ".pdf" : args.pdf,
                     args.job.empty() ? stem + ".gpgl" : args.job,
                     args.preview.empty() ? stem + "-cut.png" : args.preview};
  auto ext = [](const std::string& path) {
    std::string e = std::filesystem::path(path).extension().string();
    for (char& c : e)
      c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return e;
  };
  if (ext(f.preview) != ".png")
    throw Error("--preview " + f.preview + ": the preview is a .png", ExitCode::Usage);
  if (const std::string e = ext(f.job); e == ".plt" || e == ".hpgl" || e == ".hpg")
    throw Error("--job " + f.job + ": " + device.name + " speaks GP-GL (use .gpgl)", ExitCode::Usage);
  return f;
}

void print_report(const CalibrateArgs& args, const devices::DeviceProfile& device, const CalibrationFiles& f,
                  const layout::CalibrationPage& page, std::size_t bytes, Vec2 applied) {
  if (args.json) {
    nlohmann::json crosses = nlohmann::json::array();
    for (Vec2 c : page.crosses_mm)
      crosses.push_back({c.x, c.y});
    std::cout << versioned({{"device", device.id},
                            {"pdf", f.pdf},
                            {"job", f.job},
                            {"preview", f.preview},
                            {"crosses_mm", crosses},
                            {"applied_offset_mm", {applied.x, applied.y}},
                            {"byte_count", bytes}})
                     .dump(2)
              << "\n";
    return;
  }
  std::printf(
      "calibration page %s, cut job %s (%zu bytes, %zu crosses), preview %s\n"
      "1. Print %s at 100 %% (no fit to page) and load it on the mat like any print-and-cut sheet.\n"
      "2. Send %s to the %s (e.g. `cat %s > /dev/usb/lp0`).\n"
      "3. At each cross read how far the PRINTED line lies right/down (+) or left/up (-) of the CUT, and\n"
      "   store the mean: foldkit calibrate --device %s --offset DX,DYmm   (--verify cuts a page with it)\n",
      f.pdf.c_str(), f.job.c_str(), bytes, page.crosses_mm.size(), f.preview.c_str(), f.pdf.c_str(),
      f.job.c_str(), device.name.c_str(), f.job.c_str(), device.id.c_str());
  if (args.verify) std::printf("this job applies the stored offset %s\n", mm_pair(applied).c_str());
}

void write_page_and_job(const CalibrateArgs& args, const devices::DeviceProfile& device,
                        const devices::MediaProfile& media) {
  const layout::CalibrationPage page = page_for(device, args.paper);
  const CalibrationFiles files = files_for(args, device);
  devices::PlanOptions plan;
  plan.mat = args.mat;
  plan.regmarks = true;
  plan.score_folds = false;
  plan.overcut_mm = 0;
  // The page measures the device's own error, so the stored correction is left out unless asked for.
  const Vec2 applied = args.verify ? stored_print_cut_offset_mm(device.id) : Vec2{0, 0};
  plan.print_cut_offset_mm = applied;
  const devices::Job job = devices::plan_job(page.sheet, device, media, plan);
  const std::string stream = devices::encode_gpgl(job);

  // The simulated device runs the job before anything is written: a job it refuses is never handed out.
  devices::SimOptions so;
  so.mat = args.mat;
  devices::SimulatedDevice sim(device, so);
  devices::SendOptions send;
  send.protocol = job.protocol;
  devices::send_job(devices::stream_bytes(stream), sim, send);
  sim.close();

  devices::render_sheets({page.sheet}, files.pdf);
  devices::render_print_and_cut(page.sheet, devices::simulated_cuts_mm(sim, device, args.mat), files.preview);
  devices::FileTransport out(files.job);
  devices::send_job(devices::stream_bytes(stream), out, send);
  out.close();
  print_report(args, device, files, page, stream.size(), applied);
}

}  // namespace

void run_calibrate(const CalibrateArgs& args) {
  const devices::ProfileSet profiles = load_cli_profiles(args.profiles);
  const devices::DeviceProfile& device = device_option(profiles, args.device);
  if (args.show) {
    show_offset(args, device);
    return;
  }
  if (!args.offset.empty() || args.reset) {
    store_offset(args, device);
    return;
  }
  write_page_and_job(args, device, media_option(profiles, args.media));
}

void setup_calibrate(CLI::App& app) {
  auto args = std::make_shared<CalibrateArgs>();
  CLI::App* cmd = app.add_subcommand(
      "calibrate",
      "Print-and-cut calibration: a page and cut job to measure the offset, and --offset to store it");
  cmd->add_option("--device", args->device, "Device profile id (see `foldkit profiles`)")->required();
  cmd->add_option("--media", args->media, "Media profile id for the cut")->capture_default_str();
  cmd->add_option("--mat", args->mat, "Mat id of the device (default: its first)");
  cmd->add_option("--paper", args->paper, "Paper of the calibration page")
      ->check(paper_in(kSheetSide))
      ->capture_default_str();
  add_profile_options(*cmd, args->profiles);
  cmd->add_option("-o,--output", args->pdf, "Calibration page to print (default calibration-DEVICE.pdf)");
  cmd->add_option("--job", args->job,
                  "Cut job: a file or a device node such as /dev/usb/lp0 (default calibration-DEVICE.gpgl)");
  cmd->add_option("--preview", args->preview,
                  "The page as printed with the simulated cuts over it (default calibration-DEVICE-cut.png)");
  auto* offset =
      cmd->add_option("--offset", args->offset,
                      "Store the measured correction DX,DY (printed minus cut; mm, x right, y down), "
                      "e.g. 0.8,-1.2mm; applied to every later print-and-cut job on this device");
  cmd->add_flag("--reset", args->reset, "Remove the stored correction of this device")->excludes(offset);
  cmd->add_flag("--show", args->show, "Say which correction is stored for this device")->excludes(offset);
  cmd->add_flag("--verify", args->verify, "Cut the page with the stored correction applied, to check it");
  cmd->add_flag("--json", args->json, "Print a JSON report on stdout");
  cmd->callback([args] { run_calibrate(*args); });
}

}  // namespace foldkit::cli
