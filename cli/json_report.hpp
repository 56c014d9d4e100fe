#pragma once
// What every `--json` report shares (docs/json.md): one version key, raised when a key changes meaning
// or goes away, so that scripts can refuse a report they do not understand.
#include <nlohmann/json.hpp>

namespace foldkit::cli {

/// The version of the --json scheme this build writes.
inline constexpr int kJsonSchemaVersion = 1;

/// `report` with the version key added: what a command prints for --json.
inline nlohmann::json versioned(nlohmann::json report) {
  report["schema_version"] = kJsonSchemaVersion;
  return report;
}

}  // namespace foldkit::cli
