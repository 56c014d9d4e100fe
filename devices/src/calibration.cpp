#include "foldkit/devices/calibration.hpp"

#include <charconv>
#include <cmath>
#include <sstream>
#include <system_error>

#include <toml++/toml.h>

#include "foldkit/devices/atomic_file.hpp"
#include "foldkit/error.hpp"

namespace foldkit::devices {
namespace {

constexpr const char* kKind = "calibration";

std::string format_mm(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

void check_offset(const std::string& file, const char* key, double v) {
  if (!std::isfinite(v)) throw InputError(file, std::string(key) + ": not a number");
  if (std::abs(v) > kMaxPrintCutOffsetMm)
    throw InputError(file, std::string(key) + ": " + format_mm(v) + " mm is more than the " +
                               format_mm(kMaxPrintCutOffsetMm) +
                               " mm a print-and-cut error can be; measure again on a freshly loaded sheet");
}

double number(const toml::table& t, const std::string& file, const char* key) {
  const toml::node* n = t.get(key);
  if (!n) throw InputError(file, std::string(key) + ": missing");
  const std::optional<double> v = n->value<double>();
  if (!v || !(n->is_floating_point() || n->is_integer()))
    throw InputError(file, std::string(key) + ": expected a number of millimetres");
  check_offset(file, key, *v);
  return *v;
}

// The shortest text that reads back as the same double ("0.8", not 0.80000000000000004), always with a
// decimal point so that TOML reads a float.
std::string shortest(double v) {
  char buffer[64];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
  std::string s(buffer, ec == std::errc() ? end : buffer);
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return s;
}

}  // namespace

std::filesystem::path calibration_file(const std::filesystem::path& config_dir,
                                       const std::string& device_id) {
  return config_dir / "calibration" / (device_id + ".toml");
}

std::optional<PrintCutCalibration> load_calibration(const std::filesystem::path& file,
                                                    const std::string& device_id) {
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) return std::nullopt;
  const std::string name = file.string();
  toml::table t;
  try {
    t = toml::parse_file(name);
  } catch (const toml::parse_error& e) {
    throw InputError(name,
                     "line " + std::to_string(e.source().begin.line) + ": " + std::string(e.description()));
  }
  for (const auto& [key, node] : t) {
    const std::string k(key.str());
    if (k != "kind" && k != "device" && k != "offset_x_mm" && k != "offset_y_mm")
      throw InputError(name, k + ": unknown key (kind, device, offset_x_mm, offset_y_mm)");
  }
  if (t["kind"].value<std::string>() != std::optional<std::string>(kKind))
    throw InputError(name, "kind: expected \"calibration\"");
  const std::optional<std::string> device = t["device"].value<std::string>();
  if (!device) throw InputError(name, "device: missing");
  if (*device != device_id)
    throw InputError(name, "device: \"" + *device + "\", but the file is for \"" + device_id + "\"");
  PrintCutCalibration c;
  c.device_id = *device;
  c.offset_mm = {number(t, name, "offset_x_mm"), number(t, name, "offset_y_mm")};
  return c;
}

void save_calibration(const std::filesystem::path& file, const PrintCutCalibration& calibration) {
  check_offset(file.string(), "offset_x_mm", calibration.offset_mm.x);
  check_offset(file.string(), "offset_y_mm", calibration.offset_mm.y);
  std::error_code ec;
  std::filesystem::create_directories(file.parent_path(), ec);
  if (ec) throw OutputError(file.parent_path().string(), "cannot create the folder: " + ec.message());
  write_file_atomically(file, [&](std::ostream& out) {
    out << "# foldkit print-and-cut calibration, written by `foldkit calibrate --offset`: every cut of a\n"
           "# job with registration marks on this device moves by this much (x right, y down, mm).\n"
        << "kind = \"" << kKind << "\"\n"
        << "device = " << toml::value<std::string>(calibration.device_id) << "\n"
        << "offset_x_mm = " << shortest(calibration.offset_mm.x) << "\n"
        << "offset_y_mm = " << shortest(calibration.offset_mm.y) << "\n";
  });
}

}  // namespace foldkit::devices
