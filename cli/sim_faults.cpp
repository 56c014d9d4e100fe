#include "sim_faults.hpp"

#include <charconv>
#include <optional>

#include "foldkit/error.hpp"

namespace foldkit::cli {
namespace {

constexpr const char* kFaultList = "not-ready, no-media, marks-not-found, disconnect=BYTES, stall=BYTES";

Error bad_fault(const std::string& spec, const std::string& why) {
  return Error("--sim-fault " + spec.substr(0, 60) + ": " + why + " (faults: " + kFaultList + ")",
               ExitCode::Usage);
}

// A byte count: digits only (no sign, which std::stoul would wrap around), within std::size_t.
std::optional<std::size_t> byte_count(const std::string& text) {
  std::size_t bytes = 0;
  const char* end = text.data() + text.size();
  const auto [at, ec] = std::from_chars(text.data(), end, bytes);
  if (text.empty() || ec != std::errc() || at != end) return std::nullopt;
  return bytes;
}

}  // namespace

devices::SimFaults parse_faults(const std::vector<std::string>& specs) {
  devices::SimFaults f;
  for (const std::string& spec : specs) {
    const auto eq = spec.find('=');
    const std::string name = spec.substr(0, eq);
    const bool takes_bytes = name == "disconnect" || name == "stall";
    const bool known = takes_bytes || name == "not-ready" || name == "no-media" || name == "marks-not-found";
    if (!known) throw bad_fault(spec, "unknown fault");
    if (takes_bytes && eq == std::string::npos)
      throw bad_fault(spec, "give the byte count, e.g. " + name + "=500");
    if (!takes_bytes && eq != std::string::npos) throw bad_fault(spec, "takes no value");
    std::optional<std::size_t> bytes;
    if (takes_bytes) {
      bytes = byte_count(spec.substr(eq + 1));
      if (!bytes) throw bad_fault(spec, "expected a byte count (0 or more) after '='");
    }
    if (name == "not-ready") f.not_ready = true;
    if (name == "no-media") f.no_media = true;
    if (name == "marks-not-found") f.marks_not_found = true;
    if (name == "disconnect") f.disconnect_after = bytes;
    if (name == "stall") f.stall_after = bytes;
  }
  return f;
}

}  // namespace foldkit::cli
