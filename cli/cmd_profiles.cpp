// `foldkit profiles`: the device and media profiles --device and --media can name.
#include <cstdio>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "cmd_profiles.hpp"
#include "commands.hpp"
#include "foldkit/devices/profile.hpp"
#include "json_report.hpp"
#include "profile_options.hpp"

namespace foldkit::cli {
namespace {

std::string tools(const devices::DeviceProfile& d) {
  std::string out;
  for (const devices::Tool& t : d.tools)
    out += (out.empty() ? "" : ", ") + std::string(devices::tool_kind_name(t.kind)) + "@" +
           std::to_string(t.holder);
  return out;
}

std::string usb(const devices::DeviceProfile& d) {
  if (d.usb_vendor == 0) return "-";
  char buf[16];
  std::snprintf(buf, sizeof buf, "%04x:%04x", d.usb_vendor, d.usb_product);
  return buf;
}

// The USB id as the devices command gives it: four hex digits each, null without one.
nlohmann::json usb_json(unsigned id, const devices::DeviceProfile& d) {
  if (d.usb_vendor == 0) return nullptr;
  char buf[8];
  std::snprintf(buf, sizeof buf, "%04x", id);
  return buf;
}

nlohmann::json tools_json(const devices::DeviceProfile& d) {
  nlohmann::json out = nlohmann::json::array();
  for (const devices::Tool& t : d.tools)
    out.push_back({{"kind", devices::tool_kind_name(t.kind)}, {"holder", t.holder}});
  return out;
}

nlohmann::json settings_json(const devices::ToolSettings& s) {
  return {{"force_gf", s.force_gf}, {"speed_mm_per_s", s.speed_mm_s}, {"pass_count", s.passes}};
}

std::string settings(const devices::ToolSettings& s) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.0f gf %.0f mm/s x%d", s.force_gf, s.speed_mm_s, s.passes);
  return buf;
}

}  // namespace

void run_profiles(const ProfilesArgs& args) {
  const devices::ProfileSet set = load_cli_profiles(args.files);
  if (args.json) {
    nlohmann::json devs = nlohmann::json::array(), media = nlohmann::json::array();
    for (const auto& d : set.devices) {
      nlohmann::json mats = nlohmann::json::array();
      for (const auto& m : d.mats)
        mats.push_back({{"id", m.id}, {"width_mm", m.width_mm}, {"length_mm", m.length_mm}});
      devs.push_back({{"id", d.id},
                      {"name", d.name},
                      {"protocol", devices::protocol_name(d.protocol)},
                      {"vendor", usb_json(d.usb_vendor, d)},
                      {"product", usb_json(d.usb_product, d)},
                      {"area_mm", {d.area_width_mm, d.area_max_length_mm}},
                      {"mats", mats},
                      {"holder_count", d.holders},
                      {"tools", tools_json(d)},
                      {"regmarks_supported", d.regmarks.supported},
                      {"sources", d.sources},
                      {"file", d.file.string()}});
    }
    for (const auto& m : set.media)
      media.push_back({{"id", m.id},
                       {"name", m.name},
                       {"thickness_mm", m.thickness_mm},
                       {"cut", settings_json(m.cut)},
                       {"score", settings_json(m.score)},
                       {"draw", settings_json(m.draw)},
                       {"file", m.file.string()}});
    nlohmann::json dirs = nlohmann::json::array();
    for (const auto& dir : cli_profile_dirs())
      dirs.push_back(dir.string());
    std::cout << versioned({{"profile_dirs", dirs}, {"devices", devs}, {"media", media}}).dump(2) << "\n";
    return;
  }
  std::printf("Devices (--device):\n  %-14s %-24s %-5s %-10s %-16s %-8s %s\n", "ID", "NAME", "LANG", "USB",
              "AREA mm", "REGMARKS", "TOOLS (kind@holder)");
  for (const auto& d : set.devices) {
    char area[32];
    std::snprintf(area, sizeof area, "%.1f x %.0f", d.area_width_mm, d.area_max_length_mm);
    std::printf("  %-14s %-24s %-5s %-10s %-16s %-8s %s\n", d.id.c_str(), d.name.c_str(),
                devices::protocol_name(d.protocol), usb(d).c_str(), area, d.regmarks.supported ? "yes" : "no",
                tools(d).c_str());
  }
  std::printf("\nMedia (--media):\n  %-15s %-20s %-24s %-24s %s\n", "ID", "NAME", "CUT", "SCORE", "FOLDS");
  for (const auto& m : set.media) {
    std::printf("  %-15s %-20s %-24s %-24s %s\n", m.id.c_str(), m.name.c_str(), settings(m.cut).c_str(),
                settings(m.score).c_str(),
                m.fold_method ? devices::fold_method_name(*m.fold_method) : "device default");
  }
}

void setup_profiles(CLI::App& app) {
  auto args = std::make_shared<ProfilesArgs>();
  CLI::App* cmd = app.add_subcommand("profiles", "List the cutting-plotter device and media profiles");
  add_profile_options(*cmd, args->files);
  cmd->add_flag("--json", args->json, "Print JSON on stdout");
  cmd->callback([args] { run_profiles(*args); });
}

}  // namespace foldkit::cli
