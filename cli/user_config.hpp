#pragma once
// The user's foldkit folder ($XDG_CONFIG_HOME/foldkit, else ~/.config/foldkit) and what lives in it that
// more than one command reads: the print-and-cut calibration per device.
#include <filesystem>
#include <optional>
#include <string>

#include "foldkit/geom/vec.hpp"

namespace foldkit::cli {

/// $XDG_CONFIG_HOME/foldkit when that is an absolute path, else $HOME/.config/foldkit (the XDG base
/// directory rule). Throws Error when neither variable gives an absolute path.
std::filesystem::path user_config_dir();
/// As user_config_dir, or nullopt when neither variable gives an absolute path.
std::optional<std::filesystem::path> user_config_dir_if_known();

/// The print-and-cut correction stored for `device_id` by `foldkit calibrate --offset` (0, 0 when none).
/// Throws InputError naming the file when it is malformed.
Vec2 stored_print_cut_offset_mm(const std::string& device_id);

}  // namespace foldkit::cli
