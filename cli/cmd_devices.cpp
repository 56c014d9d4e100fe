// `foldkit devices [--json] [--usb-id VID:PID[=NAME]]...`: the cutter models foldkit knows and the
// cutters connected over USB. Finding none is an answer, not an error.
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "foldkit/devices/usb_errors.hpp"
#include "foldkit/devices/usb_transport.hpp"
#include "foldkit/error.hpp"

namespace foldkit::cli {
namespace {

struct DevicesArgs {
  bool json = false;
  std::vector<std::string> usb_ids;
};

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

void run_devices(const DevicesArgs& args) {
  std::vector<devices::UsbId> known = devices::builtin_usb_ids();
  for (const auto& text : args.usb_ids) {
    auto id = devices::parse_usb_id(text);
    if (!id)
      throw Error("--usb-id " + text + ": expected VID:PID in hex, e.g. 0b4d:1150 or 0b4d:1150=Name",
                  ExitCode::Usage);
    // A user-given id names a model the table lacks, or renames one it has.
    std::erase_if(
        known, [&](const devices::UsbId& k) { return k.vendor == id->vendor && k.product == id->product; });
    known.push_back(*id);
  }

  std::vector<devices::FoundDevice> found;
  std::optional<std::string> usb_problem;
  try {
    found = devices::find_usb_cutters(known);
  } catch (const DeviceError& e) {
    usb_problem = e.what();
  }

  if (args.json) {
    nlohmann::json j;
    j["known_models"] = nlohmann::json::array();
    for (const auto& k : known)
      j["known_models"].push_back(
          {{"vendor", hex4(k.vendor)}, {"product", hex4(k.product)}, {"model", k.model}});
    j["usb"] = nlohmann::json::array();
    for (const auto& f : found)
      j["usb"].push_back({{"vendor", hex4(f.id.vendor)},
                          {"product", hex4(f.id.product)},
                          {"model", f.id.model},
                          {"known_model", f.known_model},
                          {"bus", f.bus},
                          {"address", f.address},
                          {"access", access_name(f.access)}});
    j["usb_error"] = usb_problem ? nlohmann::json(*usb_problem) : nlohmann::json(nullptr);
    std::cout << j.dump(2) << "\n";
    return;
  }

  std::cout << "Known cutter models (" << known.size() << "):\n";
  for (const auto& k : known)
    std::cout << "  " << hex4(k.vendor) << ":" << hex4(k.product) << "  " << k.model << "\n";
  std::cout << "\nCutters on USB:\n";
  if (usb_problem) std::cout << "  cannot scan USB: " << *usb_problem << "\n";
  if (!usb_problem && found.empty()) {
    std::cout << "  no cutter found (plug it in and switch it on; docs/usb.md explains permissions)\n";
  }
  for (const auto& f : found) {
    char where[40];
    std::snprintf(where, sizeof where, "bus %03u address %03u", f.bus, f.address);
    std::cout << "  " << hex4(f.id.vendor) << ":" << hex4(f.id.product) << "  " << f.id.model << "  "
              << where;
    if (f.access == devices::UsbAccess::PermissionDenied) {
      std::cout << "  permission denied: install profiles/udev/" << devices::kUdevRulesFile
                << " (docs/usb.md)";
    }
    std::cout << "\n";
  }
}

}  // namespace

void setup_devices(CLI::App& app) {
  auto args = std::make_shared<DevicesArgs>();
  auto* cmd = app.add_subcommand("devices",
                                 "List the cutter models foldkit knows and the cutters connected over USB");
  cmd->add_flag("--json", args->json, "Print JSON instead of a table");
  cmd->add_option("--usb-id", args->usb_ids,
                  "Also look for this model: VID:PID in hex, optionally =NAME (repeatable)");
  cmd->callback([args] { run_devices(*args); });
}

}  // namespace foldkit::cli
