#include "profile_options.hpp"

#include "foldkit/error.hpp"
#include "installed_data.hpp"

namespace foldkit::cli {

void add_profile_options(CLI::App& cmd, std::vector<std::string>& files) {
  cmd.add_option(
         "--profile", files,
         "A device or media profile file of your own (TOML, like profiles/devices/*.toml); repeatable")
      ->check(CLI::ExistingFile);
}

std::vector<std::filesystem::path> cli_profile_dirs() {
  return devices::profile_dirs(this_install());
}

devices::ProfileSet load_cli_profiles(const std::vector<std::string>& files) {
  const std::vector<std::filesystem::path> extra(files.begin(), files.end());
  devices::ProfileSet set = devices::load_profiles(cli_profile_dirs(), extra);
  if (set.devices.empty() && set.media.empty()) {
    std::string looked;
    for (const auto& dir : devices::profile_search_dirs(this_install()))
      looked += (looked.empty() ? "" : ", ") + dir.string();
    throw Error("no device or media profiles found (looked in " + (looked.empty() ? "no folder" : looked) +
                    "); the installation is incomplete",
                ExitCode::Failure);
  }
  return set;
}

const devices::DeviceProfile& device_option(const devices::ProfileSet& profiles, const std::string& id) {
  try {
    return profiles.device(id);
  } catch (const InputError& e) {
    throw InputError("--device " + id, e.problem());
  }
}

const devices::MediaProfile& media_option(const devices::ProfileSet& profiles, const std::string& id) {
  try {
    return profiles.medium(id);
  } catch (const InputError& e) {
    throw InputError("--media " + id, e.problem());
  }
}

}  // namespace foldkit::cli
