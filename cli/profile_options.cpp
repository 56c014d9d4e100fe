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

}  // namespace foldkit::cli
