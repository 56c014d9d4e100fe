#pragma once
// `foldkit devices`: the device profiles and cutter models foldkit knows, and the cutters on USB.
#include <string>
#include <vector>

namespace foldkit::cli {

/// What `foldkit devices` was asked; the parser fills it, run_devices does the work.
struct DevicesArgs {
  bool json = false;
  std::vector<std::string> usb_ids;        ///< --usb-id VID:PID[=NAME]
  std::vector<std::string> profile_files;  ///< --profile
};

/// Scans USB for the known cutter models and prints profiles, models and what it found on stdout (JSON
/// with --json). Finding none is an answer, not an error. Throws Error (usage) or InputError (profiles).
void run_devices(const DevicesArgs& args);

}  // namespace foldkit::cli
