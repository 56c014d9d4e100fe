#pragma once
// A cutting job: what the device does, in device units, pass by pass. The value between plan_job (which
// decides tools, order and placement) and the encoders (which only spell it in HP-GL or GP-GL).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "foldkit/devices/profile.hpp"
#include "foldkit/sheet/sheet.hpp"

namespace foldkit::devices {

/// A point in device units, coordinates in the order the device takes them (already rounded).
struct DevicePoint {
  std::int64_t a = 0, b = 0;
  friend bool operator==(DevicePoint, DevicePoint) = default;
};

/// One tool-down polyline.
struct Stroke {
  std::vector<DevicePoint> points;
  PathRole role = PathRole::Cut;
  std::size_t source = 0;  ///< index of the sheet path (or text) it came from
};

/// What one pass is for.
enum class PassKind { Draw, Score, Perforate, Cut };

/// Lower-case name: "draw", "score", "perforate", "cut".
const char* pass_kind_name(PassKind k);

/// One run over the sheet with one tool and one setting.
struct Pass {
  PassKind kind = PassKind::Cut;
  ToolKind tool = ToolKind::Blade;
  int holder = 1;
  int offset_code = 0;  ///< blade offset (raw FC value); 0 for pens and scorers
  int speed_step = 1, force_step = 1;
  double speed_mm_s = 0;           ///< speed_step in mm/s, for time estimates
  std::optional<int> blade_depth;  ///< AutoBlade depth (GP-GL TF d,1); unset for other tools
  std::vector<Stroke> strokes;
};

/// Registration-mark search parameters, device units relative to the device origin.
struct RegMarkSearch {
  std::string command = "TB123";
  int mark_type = 2;
  std::int64_t origin_a = 0, origin_b = 0;  ///< top-left mark as printed, in device order
  std::int64_t start_a = 0, start_b = 0;    ///< where the search starts: a little before the mark
  std::int64_t extent_a = 0, extent_b = 0;  ///< distance to the far marks along each device axis
  std::int64_t arm_length = 0, stroke = 0;  ///< printed mark geometry in device units (TB51, TB53)
};

/// Figures about a job, for the user and for the report.
struct JobStats {
  double cut_length_mm = 0;     ///< tool-down length of all passes (each repetition counted)
  double travel_before_mm = 0;  ///< pen-up travel had the paths been taken in sheet order
  double travel_after_mm = 0;   ///< pen-up travel in the planned order
  double estimated_s = 0;       ///< tool-down + travel + tool up/down time
  std::size_t strokes = 0;
};

/// A planned job, ready to encode.
struct Job {
  std::string device_id, device_name;
  Protocol protocol = Protocol::Gpgl;
  double units_per_mm = 20;
  std::string firmware;                ///< expected model string
  std::optional<int> mat_code;         ///< GP-GL TG value; unset = no TG (no known code)
  DevicePoint window_min, window_max;  ///< the cut window (device units from the machine's origin)
  std::string hpgl_force_command = "FS";
  GpglFamily gpgl_family = GpglFamily::Cameo3;
  int gpgl_acceleration = 2;  ///< Graphtec `*a,f` acceleration
  bool select_holder = true;  ///< the device has several holders: passes start with J (GP-GL)
  std::optional<RegMarkSearch> regmarks;
  std::vector<Pass> passes;
  JobStats stats;
  std::vector<std::string> notes;  ///< choices the planner made that the user should hear about
};

/// The bytes of an encoded stream (encoders return them in a std::string) as a Transport takes them.
inline std::span<const std::byte> stream_bytes(const std::string& stream) {
  return std::as_bytes(std::span<const char>(stream.data(), stream.size()));
}

}  // namespace foldkit::devices
