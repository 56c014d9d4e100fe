// `foldkit devices [--json] [--usb-id VID:PID[=NAME]]... [--profile FILE]...`: the device profiles and
// cutter models foldkit knows, and the cutters connected over USB with the --device that drives each.
// Finding none is an answer, not an error.
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cmd_devices.hpp"
#include "commands.hpp"
#include "foldkit/devices/profile.hpp"
#include "foldkit/devices/usb_errors.hpp"
#include "foldkit/devices/usb_transport.hpp"
#include "foldkit/error.hpp"
#include "json_report.hpp"
#include "profile_options.hpp"

namespace foldkit::cli {
namespace {

std::string hex4(std::uint16_t v) {
  char text[8];
  std::snprintf(text, sizeof text, "%04x", v);
  return text;
}

const char* access_name(devices::UsbAccess a) {
  switch (a) {
    case devices::UsbAccess::Ok:
      return "ok";
    case devices::UsbAccess::PermissionDenied:
      return "permission denied";
    case devices::UsbAccess::Unknown:
      break;
  }
  return "unknown";
}

// The profile that drives a vendor/product pair, or nullptr.
const devices::DeviceProfile* profile_for(const devices::ProfileSet& set, std::uint16_t vendor,
                                          std::uint16_t product) {
  for (const auto& d : set.devices)
    if (d.usb_vendor == vendor && d.usb_product == product) return &d;
  return nullptr;
}

// Known ids: the built-in table, then the profiles (their names win), then --usb-id.
void add_or_rename(std::vector<devices::UsbId>& known, const devices::UsbId& id) {
  for (auto& k : known) {
    if (k.vendor == id.vendor && k.product == id.product) {
      k.model = id.model;
      return;
    }
  }
  known.push_back(id);
}

// What run_devices reports: the ids it looks for, the profiles and what the USB scan found.
struct DeviceScan {
  devices::ProfileSet profiles;
  std::vector<devices::UsbId> known;
  std::vector<devices::FoundDevice> found;
  std::optional<std::string> usb_problem;
};

DeviceScan scan_devices(const DevicesArgs& args) {
  DeviceScan scan;
  scan.profiles = load_cli_profiles(args.profile_files);
  scan.known = devices::builtin_usb_ids();
  for (const auto& d : scan.profiles.devices)
    if (d.usb_vendor != 0) add_or_rename(scan.known, {d.usb_vendor, d.usb_product, d.name});
  for (const auto& text : args.usb_ids) {
    auto id = devices::parse_usb_id(text);
    if (!id)
      throw Error("--usb-id " + text + ": expected VID:PID in hex, e.g. 0b4d:1150 or 0b4d:1150=Name",
                  ExitCode::Usage);
    // A user-given id names a model the table lacks, or renames one it has.
    add_or_rename(scan.known, *id);
  }
  try {
    scan.found = devices::find_usb_cutters(scan.known);
  } catch (const DeviceError& e) {
    scan.usb_problem = e.what();
  }
  return scan;
}

nlohmann::json scan_json(const DeviceScan& scan) {
  nlohmann::json j;
  j["known_models"] = nlohmann::json::array();
  for (const auto& k : scan.known)
    j["known_models"].push_back(
        {{"vendor", hex4(k.vendor)}, {"product", hex4(k.product)}, {"model", k.model}});
  j["profiles"] = nlohmann::json::array();
  for (const auto& d : scan.profiles.devices)
    j["profiles"].push_back(
        {{"id", d.id},
         {"name", d.name},
         {"protocol", devices::protocol_name(d.protocol)},
         {"vendor", d.usb_vendor ? nlohmann::json(hex4(d.usb_vendor)) : nlohmann::json()},
         {"product", d.usb_vendor ? nlohmann::json(hex4(d.usb_product)) : nlohmann::json()}});
  j["usb_devices"] = nlohmann::json::array();
  for (const auto& f : scan.found) {
    const auto* profile = profile_for(scan.profiles, f.id.vendor, f.id.product);
    j["usb_devices"].push_back({{"vendor", hex4(f.id.vendor)},
                                {"product", hex4(f.id.product)},
                                {"model", f.id.model},
                                {"known_model", f.known_model},
                                {"bus", f.bus},
                                {"address", f.address},
                                {"access", access_name(f.access)},
                                {"profile", profile ? nlohmann::json(profile->id) : nlohmann::json()}});
  }
  j["usb_error"] = scan.usb_problem ? nlohmann::json(*scan.usb_problem) : nlohmann::json(nullptr);
  return j;
}

// One found cutter: where it is, the --device that drives it, and what to do about permissions.
void print_found(const DeviceScan& scan, const devices::FoundDevice& f) {
  char where[40];
  std::snprintf(where, sizeof where, "bus %03u address %03u", f.bus, f.address);
  std::cout << "  " << hex4(f.id.vendor) << ":" << hex4(f.id.product) << "  " << f.id.model << "  " << where;
  if (const auto* profile = profile_for(scan.profiles, f.id.vendor, f.id.product)) {
    std::cout << "  --device " << profile->id;
  } else {
    std::cout << "  no profile: pick a similar --device and add --usb-vid " << hex4(f.id.vendor)
              << " --usb-pid " << hex4(f.id.product);
  }
  if (f.access == devices::UsbAccess::PermissionDenied) {
    std::cout << "  permission denied: install profiles/udev/" << devices::kUdevRulesFile << " (docs/usb.md)";
  }
  std::cout << "\n";
}

void print_scan(const DeviceScan& scan) {
  std::cout << "Device profiles (--device):\n";
  for (const auto& d : scan.profiles.devices) {
    char line[160];
    std::snprintf(line, sizeof line, "  %-14s %-28s %-5s %s\n", d.id.c_str(), d.name.c_str(),
                  devices::protocol_name(d.protocol),
                  d.usb_vendor ? (hex4(d.usb_vendor) + ":" + hex4(d.usb_product)).c_str() : "no USB id");
    std::cout << line;
  }
  std::cout << "\nKnown USB cutter models (" << scan.known.size() << "):\n";
  for (const auto& k : scan.known)
    std::cout << "  " << hex4(k.vendor) << ":" << hex4(k.product) << "  " << k.model << "\n";
  std::cout << "\nCutters on USB:\n";
  if (scan.usb_problem) std::cout << "  cannot scan USB: " << *scan.usb_problem << "\n";
  if (!scan.usb_problem && scan.found.empty()) {
    std::cout << "  no cutter found (plug it in and switch it on; docs/usb.md explains permissions)\n";
  }
  for (const auto& f : scan.found)
    print_found(scan, f);
}

}  // namespace

void run_devices(const DevicesArgs& args) {
  const DeviceScan scan = scan_devices(args);
  if (args.json)
    std::cout << versioned(scan_json(scan)).dump(2) << "\n";
  else
    print_scan(scan);
}

void setup_devices(CLI::App& app) {
  auto args = std::make_shared<DevicesArgs>();
  auto* cmd = app.add_subcommand(
      "devices",
      "List the device profiles and cutter models foldkit knows, and the cutters connected over USB");
  cmd->add_flag("--json", args->json, "Print JSON instead of a table");
  add_profile_options(*cmd, args->profile_files);
  cmd->add_option("--usb-id", args->usb_ids,
                  "Also look for this model: VID:PID in hex, optionally =NAME (repeatable)");
  cmd->callback([args] { run_devices(*args); });
}

}  // namespace foldkit::cli
