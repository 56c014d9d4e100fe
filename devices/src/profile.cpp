#include "foldkit/devices/profile.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <system_error>

#include <toml++/toml.h>

#include "foldkit/error.hpp"

namespace foldkit::devices {
namespace fs = std::filesystem;

const char* protocol_name(Protocol p) {
  return p == Protocol::Gpgl ? "gpgl" : "hpgl";
}

const char* tool_kind_name(ToolKind k) {
  switch (k) {
    case ToolKind::Blade:
      return "blade";
    case ToolKind::Pen:
      return "pen";
    case ToolKind::Scorer:
      return "scorer";
  }
  return "?";
}

const std::vector<std::pair<std::string, FoldMethod>>& fold_method_choices() {
  static const std::vector<std::pair<std::string, FoldMethod>> choices = {
      {"scorer", FoldMethod::Scorer},
      {"reduced-force", FoldMethod::ReducedForce},
      {"perforate", FoldMethod::Perforate},
      {"none", FoldMethod::None}};
  return choices;
}

const char* fold_method_name(FoldMethod m) {
  for (const auto& [name, method] : fold_method_choices())
    if (method == m) return name.c_str();
  return "?";
}

namespace {

// Physical limits of any cutting plotter or paper, with room to spare. They keep hostile or mistyped
// profiles from reaching the planner: device coordinates stay far inside 32 bits (1000 units/mm over
// 100 m is 1e8), time estimates stay finite, and a perforation dash cannot be shorter than a blade tip.
constexpr double kMinUnitsPerMm = 1;       // coarser than 1 mm is no cutter
constexpr double kMaxUnitsPerMm = 1000;    // 1 um steps; real devices use 20 (GP-GL) or 40 (HP-GL)
constexpr double kMaxLengthMm = 100'000;   // a 100 m roll
constexpr double kMaxSpeedMmS = 10'000;    // 10 m/s; real cutters reach about 1 m/s
constexpr double kMaxForceGf = 100'000;    // 100 kgf; real cutters reach about 600 gf
constexpr double kMaxThicknessMm = 10;     // thicker than any card a drag knife cuts
constexpr double kMinPerforationMm = 0.1;  // a dash or gap shorter than this is not a dash
constexpr double kMaxPerforationMm = 1000;
// Registration marks: the ranges of the --regmark-* options; Silhouette's own marks are 5, 20, 0.5, 10.
constexpr double kMinRegMarkSquareMm = 1, kMaxRegMarkSquareMm = 50;
constexpr double kMinRegMarkArmMm = 1, kMaxRegMarkArmMm = 100;
constexpr double kMinRegMarkStrokeMm = 0.05, kMaxRegMarkStrokeMm = 5;
constexpr double kMaxRegMarkInsetMm = 100;

// Reads one TOML table, remembering which keys were asked for so that leftovers (typos, keys from
// another version) are reported instead of ignored.
class Reader {
 public:
  Reader(const toml::table& table, std::string file, std::string prefix)
      : table_(table), file_(std::move(file)), prefix_(std::move(prefix)) {}

  [[noreturn]] void fail(const std::string& key, const std::string& problem) const {
    throw InputError(file_, path(key) + ": " + problem);
  }
  std::string path(const std::string& key) const { return prefix_.empty() ? key : prefix_ + "." + key; }
  const std::string& prefix() const { return prefix_; }
  bool has(const std::string& key) const { return table_.contains(key); }

  double number(const std::string& key, std::optional<double> fallback = std::nullopt) {
    used_.insert(key);
    const toml::node* node = table_.get(key);
    if (!node) {
      if (fallback) return *fallback;
      fail(key, "missing");
    }
    if (auto v = node->value_exact<double>()) return check_finite(key, *v);
    if (auto v = node->value_exact<std::int64_t>()) return static_cast<double>(*v);
    fail(key, "expected a number");
  }
  double positive(const std::string& key, std::optional<double> fallback = std::nullopt) {
    const double v = number(key, fallback);
    if (!(v > 0)) fail(key, "must be greater than 0, got " + format(v));
    return v;
  }
  /// A positive number no larger than `hi`: physical limits so absurd values fail here, not as
  /// overflowing device coordinates or hours of planning later (docs/failures.md, "Profiles").
  double positive_up_to(const std::string& key, double hi, std::optional<double> fallback = std::nullopt) {
    const double v = positive(key, fallback);
    if (v > hi) fail(key, "must be at most " + format(hi) + ", got " + format(v));
    return v;
  }
  /// A number in [lo, hi] (lo > 0), for quantities with a lower physical limit too.
  double between(const std::string& key, double lo, double hi,
                 std::optional<double> fallback = std::nullopt) {
    const double v = number(key, fallback);
    if (!(v >= lo && v <= hi))
      fail(key, "must be between " + format(lo) + " and " + format(hi) + ", got " + format(v));
    return v;
  }
  double non_negative(const std::string& key, std::optional<double> fallback = std::nullopt) {
    const double v = number(key, fallback);
    if (v < 0) fail(key, "must not be negative, got " + format(v));
    return v;
  }
  std::int64_t integer(const std::string& key, std::int64_t lo, std::int64_t hi,
                       std::optional<std::int64_t> fallback = std::nullopt) {
    used_.insert(key);
    const toml::node* node = table_.get(key);
    if (!node) {
      if (fallback) return *fallback;
      fail(key, "missing");
    }
    auto v = node->value_exact<std::int64_t>();
    if (!v) fail(key, "expected an integer");
    if (*v < lo || *v > hi)
      fail(key, "must be between " + std::to_string(lo) + " and " + std::to_string(hi) + ", got " +
                    std::to_string(*v));
    return *v;
  }
  bool boolean(const std::string& key, std::optional<bool> fallback = std::nullopt) {
    used_.insert(key);
    const toml::node* node = table_.get(key);
    if (!node) {
      if (fallback) return *fallback;
      fail(key, "missing");
    }
    auto v = node->value_exact<bool>();
    if (!v) fail(key, "expected true or false");
    return *v;
  }
  std::string string(const std::string& key, std::optional<std::string> fallback = std::nullopt) {
    used_.insert(key);
    const toml::node* node = table_.get(key);
    if (!node) {
      if (fallback) return *fallback;
      fail(key, "missing");
    }
    auto v = node->value_exact<std::string>();
    if (!v) fail(key, "expected a string");
    return *v;
  }
  template <typename Enum>
  Enum choice(const std::string& key, const std::vector<std::pair<std::string, Enum>>& options,
              std::optional<Enum> fallback = std::nullopt) {
    if (!has(key) && fallback) {
      used_.insert(key);
      return *fallback;
    }
    const std::string v = string(key);
    for (const auto& [name, value] : options) {
      if (name == v) return value;
    }
    std::string names;
    for (const auto& o : options)
      names += (names.empty() ? "" : ", ") + o.first;
    fail(key, "unknown value \"" + v + "\" (expected one of " + names + ")");
  }
  // A sub-table; missing is an error unless `optional`, then an empty table is read.
  Reader table(const std::string& key, bool optional = false) {
    used_.insert(key);
    const toml::node* node = table_.get(key);
    if (!node) {
      if (!optional) fail(key, "missing table");
      return Reader(empty_table(), file_, path(key));
    }
    const toml::table* t = node->as_table();
    if (!t) fail(key, "expected a table");
    return Reader(*t, file_, path(key));
  }
  // An array of tables ([[key]]).
  std::vector<Reader> tables(const std::string& key, bool optional = false) {
    used_.insert(key);
    std::vector<Reader> out;
    const toml::node* node = table_.get(key);
    if (!node) {
      if (!optional) fail(key, "missing");
      return out;
    }
    const toml::array* arr = node->as_array();
    if (!arr) fail(key, "expected an array of tables ([[" + key + "]])");
    for (std::size_t i = 0; i < arr->size(); ++i) {
      const toml::table* t = (*arr)[i].as_table();
      if (!t) fail(key, "element " + std::to_string(i + 1) + " is not a table");
      out.emplace_back(*t, file_, path(key) + "[" + std::to_string(i + 1) + "]");
    }
    return out;
  }
  // Throws for the first key nobody asked for.
  void finish() const {
    for (const auto& [key, node] : table_) {
      const std::string k(key.str());
      if (!used_.count(k)) fail(k, "unknown key");
    }
  }

 private:
  static const toml::table& empty_table() {
    static const toml::table empty;
    return empty;
  }
  double check_finite(const std::string& key, double v) const {
    if (!std::isfinite(v)) fail(key, "must be a finite number");
    return v;
  }
  static std::string format(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
  }

  const toml::table& table_;
  std::string file_, prefix_;
  std::set<std::string> used_;
};

toml::table parse(const fs::path& file) {
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) throw InputError(file.string(), "no such profile file");
  try {
    return toml::parse_file(file.string());
  } catch (const toml::parse_error& e) {
    std::ostringstream where;
    where << "line " << e.source().begin.line << ", column " << e.source().begin.column << ": "
          << e.description();
    throw InputError(file.string(), where.str());
  }
}

// Every table of a device profile may say where its facts come from (`source = "..."`): kept so
// `foldkit profiles` and reviews can check them, and so a guess never passes for a measured fact.
void read_source(Reader& r, DeviceProfile& d) {
  if (!r.has("source")) return;
  std::string src = r.string("source");
  if (src.empty()) r.fail("source", "must not be empty");
  d.sources[r.prefix()] = std::move(src);
}

StepRange read_range(Reader& r) {
  StepRange s;
  s.min = static_cast<int>(r.integer("min", 0, 10000));
  s.max = static_cast<int>(r.integer("max", 0, 10000));
  if (s.max < s.min) r.fail("max", "must not be below min");
  return s;
}

// [usb]: the ids that find the cutter (none: 0).
void read_usb(Reader& root, DeviceProfile& d) {
  Reader usb = root.table("usb", true);
  d.usb_vendor = static_cast<std::uint16_t>(usb.integer("vendor", 0, 0xffff, 0));
  d.usb_product = static_cast<std::uint16_t>(usb.integer("product", 0, 0xffff, 0));
  read_source(usb, d);
  usb.finish();
}

// [axes]: how the device's coordinates lie on the sheet.
void read_axes(Reader& root, DeviceProfile& d) {
  Reader axes = root.table("axes");
  d.axes.feed_first = axes.choice<bool>("first", {{"feed", true}, {"carriage", false}});
  d.axes.carriage_reversed = axes.choice<bool>("carriage_from", {{"left", false}, {"right", true}});
  d.axes.feed_reversed = axes.choice<bool>("feed_from", {{"top", false}, {"bottom", true}});
  d.axes.origin_at_media = axes.choice<bool>("origin", {{"area", false}, {"media", true}}, false);
  read_source(axes, d);
  axes.finish();
}

// [area]: what the machine reaches.
void read_area(Reader& root, DeviceProfile& d) {
  Reader area = root.table("area");
  d.area_width_mm = area.positive_up_to("width_mm", kMaxLengthMm);
  d.area_max_length_mm = area.positive_up_to("max_length_mm", kMaxLengthMm);
  d.margin_mm = area.non_negative("margin_mm", 0.0);
  read_source(area, d);
  area.finish();
}

// [[mats]]: each no wider than the area, no id twice.
void read_mats(Reader& root, DeviceProfile& d) {
  for (Reader& m : root.tables("mats", true)) {
    Mat mat;
    mat.id = m.string("id");
    if (m.has("code")) mat.code = static_cast<int>(m.integer("code", 0, 99));
    mat.width_mm = m.positive_up_to("width_mm", kMaxLengthMm);
    mat.length_mm = m.positive_up_to("length_mm", kMaxLengthMm);
    if (mat.width_mm > d.area_width_mm + 1e-9)
      m.fail("width_mm", "wider than the cutting area (" + std::to_string(d.area_width_mm) + " mm)");
    if (d.mat(mat.id)) m.fail("id", "mat \"" + mat.id + "\" given twice");
    read_source(m, d);
    m.finish();
    d.mats.push_back(mat);
  }
}

// [holders] and [[tools]]: a blade at least, an AutoBlade only in holder 1.
void read_tools(Reader& root, DeviceProfile& d) {
  Reader holders = root.table("holders");
  d.holders = static_cast<int>(holders.integer("count", 1, 9));
  read_source(holders, d);
  holders.finish();
  for (Reader& t : root.tables("tools")) {
    Tool tool;
    tool.id = t.string("id");
    tool.kind = t.choice<ToolKind>(
        "kind", {{"blade", ToolKind::Blade}, {"pen", ToolKind::Pen}, {"scorer", ToolKind::Scorer}});
    tool.holder = static_cast<int>(t.integer("holder", 1, d.holders));
    tool.offset_code = static_cast<int>(t.integer("offset_code", 0, 100, 0));
    tool.autoblade = t.boolean("autoblade", false);
    if (tool.autoblade && (tool.kind != ToolKind::Blade || tool.holder != 1))
      t.fail("autoblade", "only a blade in holder 1 can be an AutoBlade (TF d,1)");
    read_source(t, d);
    t.finish();
    d.tools.push_back(tool);
  }
  if (!d.tool(ToolKind::Blade)) root.fail("tools", "no tool of kind \"blade\"");
}

// [speed] and [force]: the device steps and what one step is.
void read_steps(Reader& root, DeviceProfile& d) {
  Reader speed = root.table("speed");
  d.speed_steps = read_range(speed);
  d.mm_s_per_speed_step = speed.positive_up_to("mm_s_per_step", kMaxSpeedMmS);
  read_source(speed, d);
  speed.finish();
  Reader force = root.table("force");
  d.force_steps = read_range(force);
  d.gf_per_force_step = force.positive_up_to("gf_per_step", kMaxForceGf);
  read_source(force, d);
  force.finish();
}

// [regmarks]: the sensor and the marks it finds.
void read_regmarks(Reader& root, DeviceProfile& d) {
  Reader reg = root.table("regmarks", true);
  d.regmarks.supported = reg.boolean("supported", false);
  d.regmarks.search = reg.choice<std::string>("search", {{"TB123", "TB123"}, {"TB124", "TB124"}}, "TB123");
  d.regmarks.mark_type = static_cast<int>(reg.integer("mark_type", 0, 9, 2));
  // The marks' geometry is printed by the layout (cut takes it from here), and TB51/TB53 are read
  // back from what was printed: bounded like the --regmark-* options, so 1e300 fails here, not as an
  // overflowing device coordinate.
  d.regmarks.square_mm = reg.between("square_mm", kMinRegMarkSquareMm, kMaxRegMarkSquareMm, 5.0);
  d.regmarks.arm_length_mm = reg.between("arm_length_mm", kMinRegMarkArmMm, kMaxRegMarkArmMm, 20.0);
  d.regmarks.stroke_mm = reg.between("stroke_mm", kMinRegMarkStrokeMm, kMaxRegMarkStrokeMm, 0.5);
  d.regmarks.inset_mm = reg.between("inset_mm", 0.0, kMaxRegMarkInsetMm, 10.0);
  read_source(reg, d);
  reg.finish();
}

// [hpgl] or [gpgl]: only the table of the device's protocol.
void read_dialects(Reader& root, DeviceProfile& d) {
  Reader hpgl = root.table("hpgl", true);
  d.hpgl_force_command =
      hpgl.choice<std::string>("force_command", {{"FS", "FS"}, {"!FS", "!FS"}, {"none", ""}}, "FS");
  read_source(hpgl, d);
  hpgl.finish();
  if (d.protocol == Protocol::Gpgl && root.has("hpgl")) root.fail("hpgl", "only for protocol \"hpgl\"");
  Reader gpgl = root.table("gpgl", true);
  d.gpgl_family = gpgl.choice<GpglFamily>(
      "family",
      {{"cameo3", GpglFamily::Cameo3}, {"cameo4", GpglFamily::Cameo4}, {"graphtec", GpglFamily::Graphtec}},
      GpglFamily::Cameo3);
  d.gpgl_acceleration = static_cast<int>(gpgl.integer("acceleration", 1, 3, 2));
  read_source(gpgl, d);
  gpgl.finish();
  if (d.protocol == Protocol::Hpgl && root.has("gpgl")) root.fail("gpgl", "only for protocol \"gpgl\"");
}

DeviceProfile read_device(Reader& root, const fs::path& file) {
  DeviceProfile d;
  d.file = file;
  d.id = file.stem().string();
  d.name = root.string("name");
  d.protocol = root.choice<Protocol>("protocol", {{"gpgl", Protocol::Gpgl}, {"hpgl", Protocol::Hpgl}});
  d.firmware = root.string("firmware", d.name);
  d.units_per_mm = root.between("units_per_mm", kMinUnitsPerMm, kMaxUnitsPerMm);
  d.fold_method = root.choice<FoldMethod>("fold_method", fold_method_choices(), FoldMethod::ReducedForce);
  d.travel_speed_mm_s = root.positive_up_to("travel_speed_mm_s", kMaxSpeedMmS, 200.0);
  d.tool_change_s = root.non_negative("tool_change_s", 0.2);
  read_usb(root, d);
  read_axes(root, d);
  read_area(root, d);
  read_mats(root, d);
  read_tools(root, d);
  read_steps(root, d);
  read_regmarks(root, d);
  read_dialects(root, d);
  read_source(root, d);
  if (d.fold_method == FoldMethod::Scorer && !d.tool(ToolKind::Scorer))
    root.fail("fold_method", "\"scorer\" but no tool of kind \"scorer\"");
  return d;
}

ToolSettings read_settings(Reader r) {
  ToolSettings s;
  s.force_gf = r.positive_up_to("force_gf", kMaxForceGf);
  s.speed_mm_s = r.positive_up_to("speed_mm_s", kMaxSpeedMmS);
  s.passes = static_cast<int>(r.integer("passes", 1, 10, 1));
  if (r.has("blade_depth")) s.blade_depth = static_cast<int>(r.integer("blade_depth", 0, 10));
  r.finish();
  return s;
}

MediaProfile read_media(Reader& root, const fs::path& file) {
  MediaProfile m;
  m.file = file;
  m.id = file.stem().string();
  m.name = root.string("name");
  m.thickness_mm = root.positive_up_to("thickness_mm", kMaxThicknessMm);
  if (root.has("fold_method")) m.fold_method = root.choice<FoldMethod>("fold_method", fold_method_choices());
  m.cut = read_settings(root.table("cut"));
  m.score = read_settings(root.table("score"));
  m.draw = read_settings(root.table("draw"));
  Reader perf = root.table("perforation", true);
  m.perforation_cut_mm = perf.between("cut_mm", kMinPerforationMm, kMaxPerforationMm, 1.0);
  m.perforation_gap_mm = perf.between("gap_mm", kMinPerforationMm, kMaxPerforationMm, 1.0);
  perf.finish();
  return m;
}

std::string read_kind(Reader& root) {
  return root.choice<std::string>("kind", {{"device", "device"}, {"media", "media"}});
}

std::vector<fs::path> toml_files(const fs::path& dir) {
  std::vector<fs::path> out;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return out;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.is_regular_file() && entry.path().extension() == ".toml") out.push_back(entry.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

template <typename T>
void put(std::vector<T>& list, T item) {
  auto it = std::find_if(list.begin(), list.end(), [&](const T& x) { return x.id == item.id; });
  if (it != list.end())
    *it = std::move(item);
  else
    list.push_back(std::move(item));
}

template <typename T>
std::string known_ids(const std::vector<T>& list) {
  std::string out;
  for (const T& x : list)
    out += (out.empty() ? "" : ", ") + x.id;
  return out.empty() ? "none" : out;
}

}  // namespace

const Mat* DeviceProfile::mat(const std::string& mat_id) const {
  for (const Mat& m : mats) {
    if (m.id == mat_id) return &m;
  }
  return nullptr;
}

const Tool* DeviceProfile::tool(ToolKind kind) const {
  for (const Tool& t : tools) {
    if (t.kind == kind) return &t;
  }
  return nullptr;
}

DeviceProfile load_device_profile(const fs::path& file) {
  const toml::table table = parse(file);
  Reader root(table, file.string(), "");
  if (read_kind(root) != "device") root.fail("kind", "this is a media profile, not a device profile");
  DeviceProfile d = read_device(root, file);
  root.finish();
  return d;
}

MediaProfile load_media_profile(const fs::path& file) {
  const toml::table table = parse(file);
  Reader root(table, file.string(), "");
  if (read_kind(root) != "media") root.fail("kind", "this is a device profile, not a media profile");
  MediaProfile m = read_media(root, file);
  root.finish();
  return m;
}

const DeviceProfile& ProfileSet::device(const std::string& id) const {
  for (const DeviceProfile& d : devices) {
    if (d.id == id) return d;
  }
  throw InputError("device " + id, "no such device profile (known: " + known_ids(devices) + ")");
}

const MediaProfile& ProfileSet::medium(const std::string& id) const {
  for (const MediaProfile& m : media) {
    if (m.id == id) return m;
  }
  throw InputError("media " + id, "no such media profile (known: " + known_ids(media) + ")");
}

ProfileSet load_profiles(const fs::path& dir, const std::vector<fs::path>& extra_files) {
  return load_profiles(dir.empty() ? std::vector<fs::path>{} : std::vector<fs::path>{dir}, extra_files);
}

ProfileSet load_profiles(const std::vector<fs::path>& dirs, const std::vector<fs::path>& extra_files) {
  ProfileSet set;
  for (const fs::path& dir : dirs) {
    for (const fs::path& f : toml_files(dir / "devices"))
      put(set.devices, load_device_profile(f));
    for (const fs::path& f : toml_files(dir / "media"))
      put(set.media, load_media_profile(f));
  }
  for (const fs::path& f : extra_files) {
    const toml::table table = parse(f);
    Reader root(table, f.string(), "");
    if (read_kind(root) == "device") {
      DeviceProfile d = read_device(root, f);
      root.finish();
      put(set.devices, std::move(d));
    } else {
      MediaProfile m = read_media(root, f);
      root.finish();
      put(set.media, std::move(m));
    }
  }
  auto by_id = [](const auto& a, const auto& b) { return a.id < b.id; };
  std::sort(set.devices.begin(), set.devices.end(), by_id);
  std::sort(set.media.begin(), set.media.end(), by_id);
  return set;
}

Vec2 page_to_device(const DeviceProfile& device, Vec2 p_mm, Vec2 area_mm) {
  const double carriage = device.axes.carriage_reversed ? area_mm.x - p_mm.x : p_mm.x;
  const double feed = device.axes.feed_reversed ? area_mm.y - p_mm.y : p_mm.y;
  const double k = device.units_per_mm;
  return device.axes.feed_first ? Vec2{feed * k, carriage * k} : Vec2{carriage * k, feed * k};
}

Vec2 device_to_page(const DeviceProfile& device, Vec2 d, Vec2 area_mm) {
  const double k = device.units_per_mm;
  const double feed = (device.axes.feed_first ? d.x : d.y) / k;
  const double carriage = (device.axes.feed_first ? d.y : d.x) / k;
  return {device.axes.carriage_reversed ? area_mm.x - carriage : carriage,
          device.axes.feed_reversed ? area_mm.y - feed : feed};
}

int speed_step(const DeviceProfile& device, double speed_mm_s) {
  const long step = std::lround(speed_mm_s / device.mm_s_per_speed_step);
  return static_cast<int>(std::clamp<long>(step, device.speed_steps.min, device.speed_steps.max));
}

int force_step(const DeviceProfile& device, double force_gf) {
  const long step = std::lround(force_gf / device.gf_per_force_step);
  return static_cast<int>(std::clamp<long>(step, device.force_steps.min, device.force_steps.max));
}

}  // namespace foldkit::devices
