#pragma once
// Device and media profiles: what a cutting plotter can do and how a paper wants to be cut, scored and
// drawn. Read from human-edited TOML files (profiles/devices/*.toml, profiles/media/*.toml) into typed
// structs. Unknown keys are errors, so a typo never silently falls back to a default.
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "foldkit/geom/vec.hpp"

namespace foldkit::devices {

/// The command language a device speaks.
enum class Protocol { Gpgl, Hpgl };

/// What sits in a tool holder.
enum class ToolKind { Blade, Pen, Scorer };

/// How fold lines are marked so the paper folds crisply.
enum class FoldMethod {
  Scorer,        ///< a scoring tool (usually in a second holder)
  ReducedForce,  ///< the blade with the media's (low) score force: a kiss cut
  Perforate,     ///< a dashed cut through the paper
  None,          ///< fold lines are left to the printout
};

/// Lower-case names used in profiles and messages: "gpgl", "blade", "reduced-force", …
const char* protocol_name(Protocol p);
const char* tool_kind_name(ToolKind k);
const char* fold_method_name(FoldMethod m);
/// Every fold method by its name, in the order help text lists them: the one table profiles, --fold-method
/// and fold_method_name read.
const std::vector<std::pair<std::string, FoldMethod>>& fold_method_choices();

/// An inclusive range of a device setting in device steps.
struct StepRange {
  int min = 1, max = 1;
};

/// A cutting mat (or "none" for media fed without a mat).
struct Mat {
  std::string id;           ///< e.g. "12x12"
  std::optional<int> code;  ///< GP-GL TG argument; unset = no TG is sent (no known code; HP-GL)
  double width_mm = 0;      ///< across the carriage
  double length_mm = 0;     ///< along the media feed
};

/// A tool a holder can take.
struct Tool {
  std::string id;  ///< e.g. "autoblade", "sketch-pen"
  ToolKind kind = ToolKind::Blade;
  int holder = 1;          ///< holder number (GP-GL J, HP-GL SP)
  int offset_code = 0;     ///< blade offset as the device's raw FC value (0 for pens and scorers)
  bool autoblade = false;  ///< a Silhouette AutoBlade: its depth is set with TF d,1 (holder 1 only)
};

/// Where the device's origin is and which page axis its first coordinate follows. The page is the sheet
/// as rendered: x to the right (across the carriage), y down (the direction the media feeds in).
struct AxisSetup {
  bool feed_first = true;          ///< first device coordinate runs along the media feed (page y)
  bool carriage_reversed = false;  ///< device carriage coordinate grows from the page's right edge
  bool feed_reversed = false;      ///< device feed coordinate grows from the page's bottom (HP-GL y-up)
  /// Where the device's origin is: at a corner of its cutting area (Silhouette mats), or at the loaded
  /// media's corner (roll cutters set it where the sheet sits, so reversed axes run from the sheet's
  /// own edges, not from the far end of the carriage).
  bool origin_at_media = false;
};

/// Which GP-GL dialect and set-up sequence a device takes (docs/plotter-protocols.md 2.3, 2.6).
enum class GpglFamily {
  Cameo3,    ///< Silhouette Cameo 3 set-up: J, !, FX, FE, FF, FC (+TC query)
  Cameo4,    ///< Cameo 4 line (Cameo 4/5, Portrait 3/4): FX and TJ twice, FC twice
  Graphtec,  ///< Graphtec's own GP-GL list (CE series): !, * (force), no Silhouette queries
};

/// Registration-mark support for print-and-cut.
struct RegMarkSetup {
  bool supported = false;
  std::string search = "TB123";  ///< GP-GL search command: TB123 (three marks) or TB124 (four)
  int mark_type = 2;             ///< TB52 argument (2 = Cameo/Portrait square and L brackets)
  double square_mm = 5;          ///< side of the filled top-left square
  double arm_length_mm = 20;     ///< length of the L brackets
  double stroke_mm = 0.5;        ///< line width of the marks
  double inset_mm = 10;          ///< usual distance of the marks from the sheet edges
};

/// One cutting plotter model.
struct DeviceProfile {
  std::string id;  ///< file stem: what --device takes
  std::string name;
  std::filesystem::path file;  ///< where the profile was read from
  Protocol protocol = Protocol::Gpgl;
  std::string firmware;  ///< model string the device answers to FG / OI (for the simulated device)
  std::uint16_t usb_vendor = 0, usb_product = 0;  ///< 0 when the device has no USB id
  double units_per_mm = 20;
  AxisSetup axes;
  double area_width_mm = 0;       ///< widest cut across the carriage
  double area_max_length_mm = 0;  ///< longest cut along the feed without a mat
  double margin_mm = 0;           ///< unreachable strip at every edge of the cutting area
  std::vector<Mat> mats;          ///< first = default
  int holders = 1;                ///< number of tool holders
  std::vector<Tool> tools;
  StepRange speed_steps, force_steps;
  double mm_s_per_speed_step = 10;  ///< speed step -> mm/s (for the media's speeds and time estimates)
  double gf_per_force_step = 7;     ///< force step -> gram-force (for the media's forces)
  double travel_speed_mm_s = 200;   ///< pen-up moves, for time estimates
  double tool_change_s = 0.2;       ///< lifting and lowering the tool once, for time estimates
  FoldMethod fold_method = FoldMethod::Scorer;  ///< the device's preferred way to mark folds
  RegMarkSetup regmarks;
  /// HP-GL only: the force command ("FS", Roland "!FS", or "" when the device takes force from its panel).
  std::string hpgl_force_command = "FS";
  GpglFamily gpgl_family = GpglFamily::Cameo3;  ///< GP-GL only
  int gpgl_acceleration = 0;                    ///< Graphtec `*a,f`: a (1-3); unused by Silhouettes
  /// Where each fact came from: the `source` key of the file ("") and of its tables ("axes", "mats[2]").
  std::map<std::string, std::string> sources;

  /// The mat with `id`; nullptr when the device has none of that name.
  const Mat* mat(const std::string& id) const;
  /// The first tool of `kind`, or nullptr.
  const Tool* tool(ToolKind kind) const;
};

/// Force, speed and repetitions for one kind of stroke on one paper.
struct ToolSettings {
  double force_gf = 0;
  double speed_mm_s = 0;
  int passes = 1;
  std::optional<int> blade_depth;  ///< AutoBlade depth 0-10 (TF), cut settings only
};

/// One paper or card.
struct MediaProfile {
  std::string id, name;
  std::filesystem::path file;
  double thickness_mm = 0.1;
  ToolSettings cut, score, draw;
  /// How folds are marked on this paper when no scoring tool is used (thick card: perforate); unset =
  /// the device's preference.
  std::optional<FoldMethod> fold_method;
  double perforation_cut_mm = 1.0;  ///< dash length of a perforated fold
  double perforation_gap_mm = 1.0;  ///< gap between dashes
};

/// Parses one device profile. Throws InputError "<file>: <key>: <problem>" for unreadable TOML,
/// unknown or missing keys, wrong types and out-of-range values.
DeviceProfile load_device_profile(const std::filesystem::path& file);
/// Parses one media profile; errors as load_device_profile.
MediaProfile load_media_profile(const std::filesystem::path& file);

/// Every device and media profile that can be chosen by id.
struct ProfileSet {
  std::vector<DeviceProfile> devices;  ///< sorted by id
  std::vector<MediaProfile> media;     ///< sorted by id

  /// The device with `id`; throws InputError listing the known ids when there is none.
  const DeviceProfile& device(const std::string& id) const;
  /// The media with `id`; throws InputError listing the known ids when there is none.
  const MediaProfile& medium(const std::string& id) const;
};

/// Loads `dir`/devices/*.toml and `dir`/media/*.toml, then each of `extra_files` (a device or media
/// profile, told apart by its `kind` key); a later profile with the same id replaces an earlier one.
/// Where the built-in profiles are is install_paths.hpp's business (profile_dirs).
ProfileSet load_profiles(const std::filesystem::path& dir,
                         const std::vector<std::filesystem::path>& extra_files = {});
/// As above for several folders, read in order (built-in first, then the user's own).
ProfileSet load_profiles(const std::vector<std::filesystem::path>& dirs,
                         const std::vector<std::filesystem::path>& extra_files = {});

/// Device coordinates (device units, in the order the device takes them) of page point `p_mm`, where
/// `area_mm` is what reversed axes run from: the active cutting area (width across the carriage, length
/// along the feed), or the sheet when the origin is at the media (axes.origin_at_media). Not rounded.
Vec2 page_to_device(const DeviceProfile& device, Vec2 p_mm, Vec2 area_mm);
/// Inverse of page_to_device.
Vec2 device_to_page(const DeviceProfile& device, Vec2 d, Vec2 area_mm);

/// Device steps for a media setting, clamped to the device's range.
int speed_step(const DeviceProfile& device, double speed_mm_s);
int force_step(const DeviceProfile& device, double force_gf);

}  // namespace foldkit::devices
