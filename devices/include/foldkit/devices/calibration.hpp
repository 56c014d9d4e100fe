#pragma once
// The stored print-and-cut calibration of a device: how far the cuts must move to land on the print
// after a registration-mark search (what `foldkit calibrate --offset` measured). One small TOML file
// per device in the user's configuration folder, which the caller names; the library reads no
// environment.
#include <filesystem>
#include <optional>
#include <string>

#include "foldkit/geom/vec.hpp"

namespace foldkit::devices {

/// Largest correction accepted, per axis: the worst shifts reported after a mark search are 10-15 mm
/// (plotter-protocols.md §4.5); more than this is a mismeasurement or a misloaded sheet.
inline constexpr double kMaxPrintCutOffsetMm = 25;

/// A device's print-and-cut correction, sheet mm (x right, y down): added to every cut.
struct PrintCutCalibration {
  std::string device_id;
  Vec2 offset_mm{0, 0};
};

/// The file that holds `device_id`'s calibration under `config_dir` (config_dir/calibration/ID.toml).
std::filesystem::path calibration_file(const std::filesystem::path& config_dir, const std::string& device_id);

/// Reads the calibration in `file`; nullopt when there is no such file. Throws InputError naming the
/// file and the key for a malformed file, another device's file, or an offset beyond the limit.
std::optional<PrintCutCalibration> load_calibration(const std::filesystem::path& file,
                                                    const std::string& device_id);

/// Writes `calibration` to `file` atomically, creating its folders. Throws OutputError naming the file,
/// InputError for a non-finite offset or one beyond the limit.
void save_calibration(const std::filesystem::path& file, const PrintCutCalibration& calibration);

}  // namespace foldkit::devices
