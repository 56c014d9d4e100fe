#pragma once
// `foldkit profiles`: the device and media profiles --device and --media can name.
#include <optional>
#include <string>
#include <vector>

namespace foldkit::cli {

/// What `foldkit profiles` was asked; the parser fills it, run_profiles does the work.
struct ProfilesArgs {
  std::vector<std::string> files;
  bool json = false;
};

/// Loads the profiles (built-in, user, --profile files) and prints them on stdout (JSON with --json). Throws
/// InputError.
void run_profiles(const ProfilesArgs& args);

}  // namespace foldkit::cli
