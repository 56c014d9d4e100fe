#pragma once
// The profile options `cut` and `profiles` share: --profile FILE (repeatable) on top of the built-in
// profiles found beside the build or the executable.
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "foldkit/devices/profile.hpp"

namespace foldkit::cli {

/// Adds --profile FILE (repeatable) to `cmd`, bound to `files`.
void add_profile_options(CLI::App& cmd, std::vector<std::string>& files);

/// The built-in profiles plus `files`. Throws InputError naming the file and key of a bad profile.
devices::ProfileSet load_cli_profiles(const std::vector<std::string>& files);

}  // namespace foldkit::cli
