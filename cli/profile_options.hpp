#pragma once
// The profile options `cut` and `profiles` share: --profile FILE (repeatable) on top of the built-in
// profiles found relative to the executable and the user's own (devices/install_paths.hpp).
#include <filesystem>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "foldkit/devices/profile.hpp"

namespace foldkit::cli {

/// Adds --profile FILE (repeatable) to `cmd`, bound to `files`.
void add_profile_options(CLI::App& cmd, std::vector<std::string>& files);

/// The profile folders this process reads, in order: the installed (or build tree's) built-in ones, then
/// the user's.
std::vector<std::filesystem::path> cli_profile_dirs();

/// The profiles of cli_profile_dirs plus `files`. Throws InputError naming the file and key of a bad
/// profile, and Error naming the folders looked in when there is no profile at all.
devices::ProfileSet load_cli_profiles(const std::vector<std::string>& files);

/// The device profile `id` of `profiles`, as --device names it. Throws InputError "--device ID: no such
/// device profile (known: …)".
const devices::DeviceProfile& device_option(const devices::ProfileSet& profiles, const std::string& id);

/// The media profile `id` of `profiles`, as --media names it. Throws InputError "--media ID: …".
const devices::MediaProfile& media_option(const devices::ProfileSet& profiles, const std::string& id);

}  // namespace foldkit::cli
