#pragma once
// --sim-fault NAME[=BYTES] for the commands that drive the simulated device (cut --dry-run, sim).
#include <string>
#include <vector>

#include "foldkit/devices/simulated_device.hpp"

namespace foldkit::cli {

/// Parses the --sim-fault values; throws a usage Error naming the bad one.
devices::SimFaults parse_faults(const std::vector<std::string>& specs);

}  // namespace foldkit::cli
