#pragma once
// A cutting plotter in software: a Transport that parses what it receives as strictly as the profile's
// device would be expected to, keeps tool, pen and position state, answers status and registration-mark
// queries, can be told to fail, and renders what it cut, scored and drew. Used by --dry-run and by the
// round-trip tests (sheet -> job -> bytes -> strokes back).
#include <array>
#include <cstddef>
#include <deque>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "foldkit/devices/command_parser.hpp"
#include "foldkit/devices/device_model.hpp"
#include "foldkit/devices/printed_marks.hpp"
#include "foldkit/devices/profile.hpp"
#include "foldkit/devices/transport.hpp"

namespace foldkit::devices {

/// Failures the simulated device can be told to show.
struct SimFaults {
  bool not_ready = false;                       ///< reports paused (status 3) forever
  bool no_media = false;                        ///< reports no media (status 2); refuses geometry
  std::optional<std::size_t> disconnect_after;  ///< unplugged once this many bytes arrived
  std::optional<std::size_t> stall_after;       ///< accepts no more bytes (write timeout), busy
  bool marks_not_found = false;                 ///< registration-mark search fails
};

struct SimOptions {
  std::string mat;  ///< mat id loaded (empty = the machine's first)
  SimFaults faults;
  /// The machine to simulate; unset = the built-in model of the profile's USB id (else the profile).
  std::optional<MachineModel> model;
  std::optional<Vec2> sheet_mm;  ///< the sheet loaded (on the mat's corner, or at a roll cutter's origin)
  /// The marks printed on that sheet: the search finds them only where they really are.
  std::optional<PrintedMarks> printed_marks;
  bool require_initialize = true;   ///< GP-GL: ESC 04 must come before set-up commands
  std::map<int, ToolKind> mounted;  ///< tool per holder for rendering; default from the profile
};

/// One tool-down polyline the device executed, in the device coordinates it received.
struct SimStroke {
  int holder = 1;
  int force = 0, speed = 0;
  std::vector<Vec2> points;
};

/// What the simulated device's rendering shows, in page millimetres (sheet orientation): the mat (when it is
/// a sheet-sized one, not a roll), the loaded sheet, the machine's origin, where the mark search put (0,0),
/// and each stroke with its colour and width.
struct SimScene {
  struct Line {
    std::vector<Vec2> points;
    std::array<double, 3> rgb{0, 0, 0};  ///< cuts black, blade scores blue, scoring tool green, pen red
    double width_mm = 0.2;
  };
  Box2 box;  ///< everything drawn
  std::optional<Box2> mat, sheet;
  Vec2 machine_origin;
  std::optional<Vec2> search_origin;
  std::vector<Line> lines;
};

/// A Transport that executes HP-GL or GP-GL on a simulated machine: its facts (mats and TG codes, axes,
/// holders, ranges, commands, replies) come from its own MachineModel, not from the planner's profile.
class SimulatedDevice final : public Transport {
 public:
  /// Simulates options.model, else the built-in model for `profile`'s USB id, else `profile` itself.
  explicit SimulatedDevice(const DeviceProfile& profile, SimOptions options = {});

  /// Parses and executes; throws DeviceError naming the byte offset of the first bad command, or the
  /// injected fault. After an error every call throws.
  void write(std::span<const std::byte> bytes) override;
  DeviceState status() override;
  /// Writes `command` and returns the reply it produced; throws DeviceError (timeout) when it gives none.
  bool reads_replies() const override { return true; }
  std::optional<std::vector<std::byte>> request(std::span<const std::byte> command,
                                                std::chrono::milliseconds timeout) override;
  /// Ends the stream: throws DeviceError when it stopped inside a command or left the tool down.
  void close() override;
  std::string describe() const override;

  /// Strokes executed so far, in order.
  const std::vector<SimStroke>& strokes() const { return strokes_; }
  /// Replies not yet read (ETX- or CR-terminated).
  std::size_t pending_replies() const { return replies_.size(); }
  /// Bytes accepted.
  std::size_t bytes_received() const { return received_; }
  /// Tool-down and tool-up path lengths in mm.
  double down_length_mm() const;
  double travel_mm() const { return travel_units_ / profile_.units_per_mm; }
  /// Where the registration-mark search put the logical origin (device units), if it ran.
  std::optional<Vec2> mark_origin() const { return mark_origin_; }
  /// The machine simulated (model_.from_profile when there was no built-in model).
  const MachineModel& model() const { return model_; }
  /// Bounds of the executed tool-down strokes on the sheet, in mm (empty when nothing was cut).
  Box2 cut_bounds_mm() const;
  /// Why the last mark search failed ("" when it did not).
  const std::string& marks_problem() const { return marks_problem_; }
  /// The first error, if the device stopped on one.
  const std::optional<std::string>& fault() const { return error_; }

  /// Renders the executed strokes to `path` (.png or .svg, by extension) in sheet orientation and
  /// millimetres over the mat (grey), the sheet (white) with its printed marks, and the machine's origin
  /// (a red cross): cuts black, blade scores blue, scoring tool green, pen red. After a fault it shows
  /// the strokes done so far. Atomic write.
  void render(const std::filesystem::path& path, double png_dpi = 150) const;
  /// What render() draws, in page millimetres.
  SimScene scene() const;

 private:
  void execute(const ParsedCommand& c);
  void execute_gpgl(const ParsedCommand& c);
  // The GP-GL commands by kind; each returns false for a command that is not of its kind.
  bool gpgl_session(const ParsedCommand& c);  // ESC 05, FG, ESC 04: answered before initialisation
  bool gpgl_query(const ParsedCommand& c);
  void gpgl_tb(const ParsedCommand& c);
  bool gpgl_media(const ParsedCommand& c);
  bool gpgl_tool(const ParsedCommand& c);
  bool gpgl_motion(const ParsedCommand& c);
  int gpgl_int(const ParsedCommand& c, double v, const char* what);
  int gpgl_holder(const ParsedCommand& c, std::size_t i);  // parameter i, else the selected holder
  void check_steps(const ParsedCommand& c, int value, const StepRange& range, const char* what);
  void execute_hpgl(const ParsedCommand& c);
  void move_to(Vec2 p, bool down, std::size_t offset);
  void pen_up();
  void reply(const std::string& text);
  void search_marks(Vec2 start, Vec2 extent);
  [[noreturn]] void fail(std::size_t offset, const std::string& problem);
  void check_alive() const;

  MachineModel model_;
  DeviceProfile& profile_ = model_.facts;
  SimOptions options_;
  Vec2 area_mm_;
  Vec2 machine_min_, machine_max_;  // device units: what the machine reaches
  Vec2 area_min_, area_max_;        // device units: where cutting is allowed (the sheet on a roll cutter)
  Vec2 window_min_, window_max_;
  GpglParser gpgl_;
  HpglParser hpgl_;
  std::size_t received_ = 0;
  bool initialized_ = false, closed_ = false, down_ = false, relative_ = false;
  bool marks_failed_ = false;
  std::string marks_problem_;
  double mark_arm_ = -1, mark_stroke_ = -1;  // TB51, TB53 as received
  std::optional<std::string> error_;
  int holder_ = 0;
  std::map<int, int> speed_, force_;
  Vec2 pos_;
  double travel_units_ = 0;
  std::optional<Vec2> mark_origin_;
  std::vector<SimStroke> strokes_;
  std::deque<std::string> replies_;
};

}  // namespace foldkit::devices
