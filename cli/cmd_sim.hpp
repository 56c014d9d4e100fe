#pragma once
// `foldkit sim`: replay a cutter job on the simulated device.
#include <optional>
#include <string>
#include <vector>

namespace foldkit::cli {

/// What `foldkit sim` was asked; the parser fills it, run_sim does the work.
struct SimArgs {
  std::string file, device, mat, paper = "a4", preview;
  std::vector<std::string> profiles, sim_faults;
  bool json = false;
};

/// Replays the job on the simulated machine, writes the preview and prints what it cut (JSON with --json).
/// Throws Error (usage), InputError or DeviceError (with how far it got).
void run_sim(const SimArgs& args);

}  // namespace foldkit::cli
