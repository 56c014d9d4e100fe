#include "profile_options.hpp"

#include <filesystem>
#include <system_error>

namespace foldkit::cli {

void add_profile_options(CLI::App& cmd, std::vector<std::string>& files) {
  cmd.add_option(
         "--profile", files,
         "A device or media profile file of your own (TOML, like profiles/devices/*.toml); repeatable")
      ->check(CLI::ExistingFile);
}

devices::ProfileSet load_cli_profiles(const std::vector<std::string>& files) {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  std::vector<std::filesystem::path> extra(files.begin(), files.end());
  return devices::load_profiles(devices::builtin_profiles_dir(ec ? std::filesystem::path() : exe), extra);
}

}  // namespace foldkit::cli
