#include "installed_data.hpp"

#include <cstdlib>
#include <system_error>

#include "user_config.hpp"

namespace foldkit::cli {

devices::InstallPaths this_install() {
  devices::InstallPaths paths;
  std::error_code ec;
  paths.executable = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) paths.executable.clear();
  paths.user_config_dir = user_config_dir_if_known().value_or(std::filesystem::path());
  paths.data_dirs = devices::xdg_data_dirs(std::getenv("XDG_DATA_DIRS"));
  return paths;
}

devices::StrokeFont load_label_font() {
  return devices::load_stroke_font(devices::find_stroke_font(this_install()));
}

}  // namespace foldkit::cli
