#include "user_config.hpp"

#include <cstdlib>
#include <optional>

#include "foldkit/devices/calibration.hpp"
#include "foldkit/error.hpp"

namespace foldkit::cli {

std::optional<std::filesystem::path> user_config_dir_if_known() {
  // Relative values are to be ignored (XDG Base Directory Specification).
  if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg && std::filesystem::path(xdg).is_absolute())
    return std::filesystem::path(xdg) / "foldkit";
  if (const char* home = std::getenv("HOME"); home && std::filesystem::path(home).is_absolute())
    return std::filesystem::path(home) / ".config" / "foldkit";
  return std::nullopt;
}

std::filesystem::path user_config_dir() {
  if (auto dir = user_config_dir_if_known()) return *dir;
  throw Error("cannot find your configuration folder: set XDG_CONFIG_HOME or HOME to an absolute path",
              ExitCode::Failure);
}

Vec2 stored_print_cut_offset_mm(const std::string& device_id) {
  // Without a configuration folder nothing can have been stored.
  const auto dir = user_config_dir_if_known();
  if (!dir) return {0, 0};
  const auto c = devices::load_calibration(devices::calibration_file(*dir, device_id), device_id);
  return c ? c->offset_mm : Vec2{0, 0};
}

}  // namespace foldkit::cli
