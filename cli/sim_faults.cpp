#include "sim_faults.hpp"

#include <optional>

#include "foldkit/error.hpp"

namespace foldkit::cli {

devices::SimFaults parse_faults(const std::vector<std::string>& specs) {
  devices::SimFaults f;
  for (const std::string& spec : specs) {
    const auto eq = spec.find('=');
    const std::string name = spec.substr(0, eq);
    std::optional<std::size_t> bytes;
    if (eq != std::string::npos) {
      try {
        bytes = std::stoul(spec.substr(eq + 1));
      } catch (const std::exception&) {
        throw Error("--sim-fault " + spec + ": expected a byte count after '='", ExitCode::Usage);
      }
    }
    const bool takes_bytes = name == "disconnect" || name == "stall";
    if (takes_bytes != bytes.has_value())
      throw Error("--sim-fault " + spec +
                      (takes_bytes ? ": give the byte count, e.g. " + name + "=500" : ": takes no value"),
                  ExitCode::Usage);
    if (name == "not-ready")
      f.not_ready = true;
    else if (name == "no-media")
      f.no_media = true;
    else if (name == "marks-not-found")
      f.marks_not_found = true;
    else if (name == "disconnect")
      f.disconnect_after = bytes;
    else if (name == "stall")
      f.stall_after = bytes;
    else
      throw Error("--sim-fault " + spec +
                      ": unknown fault (not-ready, no-media, marks-not-found, disconnect=N, stall=N)",
                  ExitCode::Usage);
  }
  return f;
}

}  // namespace foldkit::cli
