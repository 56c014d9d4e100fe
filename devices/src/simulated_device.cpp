#include "foldkit/devices/simulated_device.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <sstream>

#include <cairo-svg.h>
#include <cairo.h>

#include "foldkit/devices/atomic_file.hpp"
#include "foldkit/devices/plan.hpp"
#include "foldkit/error.hpp"

namespace foldkit::devices {
namespace {

// Coordinates a hair outside the window still count as inside: GP-GL accepts decimals and rounding
// in a sender must not be an error.
constexpr double kTolerance = 1e-6;

std::string fmt(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

std::string fmt(Vec2 p) {
  std::ostringstream s;
  s << '(' << p.x << ", " << p.y << ')';
  return s.str();
}

// GP-GL replies right-align numbers in 5 columns: "    0,    0".
std::string padded(long v) {
  std::ostringstream s;
  s.width(5);
  s << v;
  return s.str();
}

bool inside(Vec2 p, Vec2 lo, Vec2 hi) {
  return p.x >= lo.x - kTolerance && p.x <= hi.x + kTolerance && p.y >= lo.y - kTolerance &&
         p.y <= hi.y + kTolerance;
}

cairo_status_t write_to_stream(void* closure, const unsigned char* data, unsigned int length) {
  auto* out = static_cast<std::ostream*>(closure);
  out->write(reinterpret_cast<const char*>(data), length);
  return out->good() ? CAIRO_STATUS_SUCCESS : CAIRO_STATUS_WRITE_ERROR;
}

}  // namespace

SimulatedDevice::SimulatedDevice(const DeviceProfile& profile, SimOptions options)
    : model_(options.model ? *options.model : machine_model(profile)), options_(std::move(options)) {
  // A machine without mats ignores the planner's mat names (a carrier sheet is not a TG mat).
  area_mm_ = profile_.mats.empty() ? Vec2{profile_.area_width_mm, profile_.area_max_length_mm}
                                   : cutting_area_mm(profile_, options_.mat);
  auto box = [&](Vec2 size_mm, Vec2& lo, Vec2& hi) {
    const double m = profile_.margin_mm;
    const Vec2 c1 = page_to_device(profile_, {m, m}, size_mm);
    const Vec2 c2 = page_to_device(profile_, {size_mm.x - m, size_mm.y - m}, size_mm);
    lo = {std::round(std::fmin(c1.x, c2.x)), std::round(std::fmin(c1.y, c2.y))};
    hi = {std::round(std::fmax(c1.x, c2.x)), std::round(std::fmax(c1.y, c2.y))};
  };
  box(area_mm_, machine_min_, machine_max_);
  if (options_.sheet_mm && profile_.axes.origin_at_media) {
    // A roll cutter's origin is the sheet's corner: off the sheet is off the media.
    area_mm_ = {std::fmin(area_mm_.x, options_.sheet_mm->x), std::fmin(area_mm_.y, options_.sheet_mm->y)};
  }
  box(area_mm_, area_min_, area_max_);
  window_min_ = machine_min_;
  window_max_ = machine_max_;
  if (profile_.holders == 1) holder_ = 1;  // one holder: nothing to select (no J)
  // Graphtec's own list has no ESC 04: such a machine takes commands from power-on.
  if (profile_.protocol == Protocol::Gpgl && profile_.gpgl_family == GpglFamily::Graphtec)
    initialized_ = true;
  if (options_.mounted.empty()) {
    for (int h = 1; h <= profile_.holders; ++h) {
      // What a user would most likely have mounted: the blade in its holder, else a pen, else a scorer.
      for (ToolKind k : {ToolKind::Blade, ToolKind::Pen, ToolKind::Scorer}) {
        const Tool* t = nullptr;
        for (const Tool& tool : profile_.tools) {
          if (tool.kind == k && tool.holder == h && !t) t = &tool;
        }
        if (t && !options_.mounted.count(h)) options_.mounted[h] = k;
      }
    }
  }
}

std::string SimulatedDevice::describe() const {
  return "simulated " + profile_.name;
}

void SimulatedDevice::check_alive() const {
  if (error_) throw DeviceError("simulated " + profile_.name + " stopped earlier: " + *error_);
}

void SimulatedDevice::fail(std::size_t offset, const std::string& problem) {
  const std::string dialect = profile_.protocol == Protocol::Gpgl ? "GP-GL" : "HP-GL";
  error_ = dialect + " byte " + std::to_string(offset) + ": " + problem;
  throw DeviceError(*error_);
}

void SimulatedDevice::write(std::span<const std::byte> bytes) {
  check_alive();
  if (closed_) throw DeviceError("simulated " + profile_.name + ": write after close");
  std::size_t accept = bytes.size();
  std::optional<std::string> fault;
  if (options_.faults.stall_after && received_ + accept > *options_.faults.stall_after) {
    accept = *options_.faults.stall_after - std::min(received_, *options_.faults.stall_after);
    fault = "write timed out: the device accepted no data after " +
            std::to_string(*options_.faults.stall_after) + " bytes (stalled)";
  }
  if (options_.faults.disconnect_after && received_ + accept > *options_.faults.disconnect_after) {
    accept = *options_.faults.disconnect_after - std::min(received_, *options_.faults.disconnect_after);
    fault = "device disconnected after " + std::to_string(*options_.faults.disconnect_after) +
            " bytes (unplugged?)";
  }
  const auto part = bytes.first(accept);
  std::vector<ParsedCommand> commands;
  try {
    commands = profile_.protocol == Protocol::Gpgl ? gpgl_.feed(part) : hpgl_.feed(part);
  } catch (const DeviceError& e) {
    error_ = e.what();
    throw;
  }
  received_ += accept;
  for (const ParsedCommand& c : commands)
    execute(c);
  if (fault) {
    // A stalled device stays attached and busy; an unplugged one is gone.
    if (options_.faults.disconnect_after && received_ >= *options_.faults.disconnect_after) error_ = *fault;
    throw DeviceError(*fault);
  }
}

DeviceState SimulatedDevice::status() {
  check_alive();
  if (options_.faults.no_media) return DeviceState::NoMedia;
  if (options_.faults.not_ready) return DeviceState::Paused;
  if (options_.faults.stall_after && received_ >= *options_.faults.stall_after) return DeviceState::Busy;
  return DeviceState::Ready;
}

std::optional<std::vector<std::byte>> SimulatedDevice::request(std::span<const std::byte> command,
                                                               std::chrono::milliseconds timeout) {
  replies_.clear();  // stale replies belong to earlier commands
  write(command);
  if (replies_.empty()) {
    throw DeviceError("simulated " + profile_.name + ": no reply within " + std::to_string(timeout.count()) +
                      " ms");
  }
  const std::string r = replies_.front();
  replies_.pop_front();
  std::vector<std::byte> out(r.size());
  std::transform(r.begin(), r.end(), out.begin(), [](char c) { return static_cast<std::byte>(c); });
  return out;
}

void SimulatedDevice::close() {
  if (closed_ || error_) return;
  closed_ = true;
  try {
    if (profile_.protocol == Protocol::Gpgl)
      gpgl_.finish();
    else
      hpgl_.finish();
  } catch (const DeviceError& e) {
    error_ = e.what();
    throw;
  }
  if (down_) {
    fail(received_, profile_.protocol == Protocol::Gpgl
                        ? "job ends with the tool down (no M after the last D: the device would hold back "
                          "the last segment)"
                        : "job ends with the pen down (no PU)");
  }
}

// The sensor scans from the search start: it finds a mark that lies no further than this beyond it,
// and none that lies before it. The reference starts 10 mm before the mark.
constexpr double kSearchReachMm = 20;
constexpr double kSearchLeadMm = 10;

void SimulatedDevice::search_marks(Vec2 start, Vec2 extent) {
  const double k = profile_.units_per_mm;
  auto units = [&](double mm) { return fmt(mm) + " mm"; };
  Vec2 mark = start + Vec2{kSearchLeadMm * k, kSearchLeadMm * k};
  marks_problem_.clear();
  if (const auto& pm = options_.printed_marks) {
    mark = page_to_device(profile_, pm->origin_mm, area_mm_);
    const Vec2 ext = page_to_device(profile_, pm->origin_mm + pm->extent_mm, area_mm_) - mark;
    const Vec2 reach = start + Vec2{kSearchReachMm * k, kSearchReachMm * k};
    if (std::fabs(pm->square_mm - profile_.regmarks.square_mm) > 0.05)
      marks_problem_ = "the sensor finds " + units(profile_.regmarks.square_mm) +
                       " squares, the printed one is " + units(pm->square_mm);
    else if (std::fabs(mark_arm_ - pm->arm_mm * k) > 1)
      marks_problem_ =
          "TB51 says " + units(mark_arm_ / k) + " arms, the printed ones are " + units(pm->arm_mm);
    else if (std::fabs(mark_stroke_ - pm->stroke_mm * k) > 1)
      marks_problem_ =
          "TB53 says " + units(mark_stroke_ / k) + " lines, the printed ones are " + units(pm->stroke_mm);
    else if (mark.x < start.x - kTolerance || mark.y < start.y - kTolerance || mark.x > reach.x ||
             mark.y > reach.y)
      marks_problem_ = "the search starts at " + fmt(start) + " but the printed mark is at " + fmt(mark);
    else if (std::fabs(std::fabs(ext.x) - extent.x) > k || std::fabs(std::fabs(ext.y) - extent.y) > k)
      marks_problem_ = "the search expects the far marks " + fmt(extent) + " away, printed " +
                       fmt(Vec2{std::fabs(ext.x), std::fabs(ext.y)});
  }
  if (marks_problem_.empty() &&
      (!inside(mark, area_min_, area_max_) || !inside(mark + extent, area_min_, area_max_)))
    marks_problem_ = "the marks lie outside the cutting area";
  if (marks_problem_.empty() && options_.faults.marks_not_found)
    marks_problem_ = "marks not found (injected fault)";
  if (!marks_problem_.empty()) {
    marks_failed_ = true;
    reply("    1");
    return;
  }
  mark_origin_ = mark;
  // Window coordinates are logical from here on: relative to the top-left mark.
  window_min_ = area_min_ - mark;
  window_max_ = area_max_ - mark;
  reply("    0");
}

void SimulatedDevice::reply(const std::string& text) {
  replies_.push_back(text + (profile_.protocol == Protocol::Gpgl ? "\x03" : "\r"));
}

void SimulatedDevice::execute(const ParsedCommand& c) {
  if (!model_.commands.count(c.name))
    fail(c.offset, (c.name.starts_with("ESC") ? "escape " : "command ") + c.name + " is not one the " +
                       profile_.name + " takes");
  if (profile_.protocol == Protocol::Gpgl)
    execute_gpgl(c);
  else
    execute_hpgl(c);
}

void SimulatedDevice::pen_up() {
  down_ = false;
}

void SimulatedDevice::move_to(Vec2 p, bool down, std::size_t offset) {
  const Vec2 origin = mark_origin_.value_or(Vec2{0, 0});
  if (down) {
    if (options_.faults.no_media) fail(offset, "no media loaded: refusing to cut");
    if (marks_failed_) fail(offset, "registration marks were not found: refusing to cut at an unknown place");
    if (!inside(p, window_min_, window_max_))
      fail(offset, "tool-down move to " + fmt(p) + " leaves the cut window " + fmt(window_min_) + ".." +
                       fmt(window_max_));
    if (!inside(p + origin, area_min_, area_max_))
      fail(offset,
           "tool-down move to " + fmt(p + origin) + " leaves the " +
               (options_.sheet_mm && profile_.axes.origin_at_media ? "loaded sheet " : "cutting area ") +
               fmt(area_min_) + ".." + fmt(area_max_) + " (device units from the origin)");
    if (!down_) strokes_.push_back({holder_, force_[holder_], speed_[holder_], {pos_}});
    strokes_.back().points.push_back(p);
    down_ = true;
  } else {
    travel_units_ += norm(p - pos_);
    down_ = false;
  }
  pos_ = p;
}

void SimulatedDevice::execute_gpgl(const ParsedCommand& c) {
  if (gpgl_session(c)) return;
  if (options_.require_initialize && !initialized_) fail(c.offset, c.name + " before ESC 04 (initialise)");
  if (c.name == "TB") return gpgl_tb(c);
  if (gpgl_query(c) || gpgl_media(c) || gpgl_tool(c) || gpgl_motion(c)) return;
  fail(c.offset, "command " + c.name + " is not supported by this device");
}

int SimulatedDevice::gpgl_int(const ParsedCommand& c, double v, const char* what) {
  if (v != std::floor(v)) fail(c.offset, std::string(what) + " must be an integer, got " + fmt(v));
  // Converting a double beyond int's range is undefined behaviour (found by fuzz_device_gpgl).
  if (std::fabs(v) > 1e9) fail(c.offset, std::string(what) + " out of range, got " + fmt(v));
  return static_cast<int>(v);
}

int SimulatedDevice::gpgl_holder(const ParsedCommand& c, std::size_t i) {
  const int h = c.params.size() > i ? gpgl_int(c, c.params[i], "holder") : holder_;
  if (h < 1 || h > profile_.holders)
    fail(c.offset, c.name + ": holder " + std::to_string(h) + " does not exist (device has " +
                       std::to_string(profile_.holders) + ")");
  return h;
}

void SimulatedDevice::check_steps(const ParsedCommand& c, int value, const StepRange& range,
                                  const char* what) {
  if (value < range.min || value > range.max)
    fail(c.offset, std::string(what) + " " + std::to_string(value) + " out of range " +
                       std::to_string(range.min) + ".." + std::to_string(range.max));
}

bool SimulatedDevice::gpgl_session(const ParsedCommand& c) {
  if (c.name == "ESC05") {
    const DeviceState s = status();
    reply(s == DeviceState::NoMedia  ? "2"
          : s == DeviceState::Paused ? "3"
          : s == DeviceState::Busy   ? "1"
                                     : "0");
  } else if (c.name == "FG") {
    std::string fw = profile_.firmware;
    if (fw.size() < 17) fw.resize(17, ' ');
    reply(fw);
  } else if (c.name == "ESC04") {
    initialized_ = true;
  } else {
    return false;
  }
  return true;
}

bool SimulatedDevice::gpgl_query(const ParsedCommand& c) {
  const std::string& n = c.name;
  if (n == "ESC15")
    reply("0,0");
  else if (n == "FA" || n == "TC" || n == "[")
    reply("    0,    0");
  else if (n == "U")
    reply(padded(std::lround(area_max_.x)) + "," + padded(std::lround(area_max_.y)));
  else
    return false;
  return true;
}

void SimulatedDevice::gpgl_tb(const ParsedCommand& c) {
  const auto& p = c.params;
  const int sub = gpgl_int(c, p[0], "TB code");
  if (sub == 71) {
    reply("    0,    0");
  } else if (sub == 50) {
    if (p.size() != 2 || p[1] != 0)
      fail(c.offset, "TB50 must be TB50,0 (portrait); landscape is not supported");
  } else if (sub == 51 || sub == 53) {
    (sub == 51 ? mark_arm_ : mark_stroke_) = p.size() > 1 ? p[1] : -1;
  } else if (sub == 123 || sub == 124) {
    if (!profile_.regmarks.supported) fail(c.offset, "this device has no registration-mark sensor");
    if (p.size() != 5) fail(c.offset, "TB" + std::to_string(sub) + " takes height, width, top, left");
    search_marks(Vec2{p[3], p[4]}, Vec2{p[1], p[2]});
  } else if (sub != 99 && sub != 51 && sub != 52 && sub != 53 && sub != 54 && sub != 55) {
    fail(c.offset, "unknown TB" + std::to_string(sub));
  }
}

// The mat, the cut window and settings that change nothing the simulation tracks.
bool SimulatedDevice::gpgl_media(const ParsedCommand& c) {
  const auto& p = c.params;
  const std::string& n = c.name;
  if (n == "TG") {
    const int code = gpgl_int(c, p[0], "mat code");
    const Mat* loaded = options_.mat.empty() ? (profile_.mats.empty() ? nullptr : &profile_.mats.front())
                                             : profile_.mat(options_.mat);
    if (loaded && loaded->code != code)
      fail(c.offset, "job expects mat TG" + std::to_string(code) + " but mat " + loaded->id + " (" +
                         (loaded->code ? "TG" + std::to_string(*loaded->code) : "no TG code") +
                         ") is loaded on the " + profile_.name);
  } else if (n == "FN") {
    if (p[0] != 0 && p[0] != 1) fail(c.offset, "FN takes 0 or 1");
  } else if (n == "\\" || n == "Z") {
    const Vec2 corner{p[0], p[1]};
    const Vec2 origin = mark_origin_.value_or(Vec2{0, 0});
    if (!inside(corner + origin, machine_min_, machine_max_))
      fail(c.offset, n + " window corner " + fmt(corner) + " lies outside the cutting area " +
                         fmt(machine_min_) + ".." + fmt(machine_max_));
    (n == "Z" ? window_max_ : window_min_) = corner;
  } else if (n == "FE" || n == "FY" || n == "FF" || n == "L" || n == "FO" || n == "FW" || n == "H") {
    // Accepted settings that change nothing the simulation tracks (lift, overcut, feed, home).
    if (n == "H") move_to({0, 0}, false, c.offset);
  } else if (n == "SO") {
    if (p[0] != 0) fail(c.offset, "SO takes 0");
  } else {
    return false;
  }
  return true;
}

// Holder, speed, force, blade offset, AutoBlade depth and acceleration.
bool SimulatedDevice::gpgl_tool(const ParsedCommand& c) {
  const auto& p = c.params;
  const std::string& n = c.name;
  if (n == "J") {
    const int h = gpgl_int(c, p[0], "holder");
    if (h < 0 || h > profile_.holders)
      fail(c.offset, "J" + std::to_string(h) + ": holder does not exist (device has " +
                         std::to_string(profile_.holders) + ")");
    holder_ = h;
  } else if (n == "!") {
    const int s = gpgl_int(c, p[0], "speed");
    check_steps(c, s, profile_.speed_steps, "speed");
    speed_[gpgl_holder(c, 1)] = s;
  } else if (n == "FX") {
    const int f = gpgl_int(c, p[0], "force");
    check_steps(c, f, profile_.force_steps, "force");
    force_[gpgl_holder(c, 1)] = f;
  } else if (n == "FC") {
    if (p[0] < 0 || p[0] > model_.max_blade_offset)
      fail(c.offset,
           "FC cutter offset " + fmt(p[0]) + " out of range 0.." + std::to_string(model_.max_blade_offset));
    if (p.size() == 3) gpgl_holder(c, 2);
  } else if (n == "TF") {
    if (!model_.autoblade_holder_1) fail(c.offset, "TF: the " + profile_.name + " has no AutoBlade");
    if (p[1] != 1) fail(c.offset, "TF sets the AutoBlade depth in holder 1 only, got holder " + fmt(p[1]));
    if (p[0] < 0 || p[0] > 10 || p[0] != std::floor(p[0]))
      fail(c.offset, "TF depth " + fmt(p[0]) + " out of range 0..10");
  } else if (n == "TJ") {
    if (p[0] < 0 || p[0] > 3 || p[0] != std::floor(p[0]))
      fail(c.offset, "TJ acceleration " + fmt(p[0]) + " out of range 0..3");
  } else if (n == "*") {
    // Graphtec: * a,f[,n] acceleration and force.
    const int a = gpgl_int(c, p[0], "acceleration"), f = gpgl_int(c, p[1], "force");
    if (a < 1 || a > 3) fail(c.offset, "* acceleration " + std::to_string(a) + " out of range 1..3");
    check_steps(c, f, profile_.force_steps, "force");
    force_[gpgl_holder(c, 2)] = f;
  } else {
    return false;
  }
  return true;
}

bool SimulatedDevice::gpgl_motion(const ParsedCommand& c) {
  const auto& p = c.params;
  if (c.name == "M") {
    move_to({p[0], p[1]}, false, c.offset);
  } else if (c.name == "D") {
    if (holder_ < 1) fail(c.offset, "D with no tool holder selected (J)");
    if (!speed_.count(holder_) || !force_.count(holder_))
      fail(c.offset,
           "D before speed and force of holder " + std::to_string(holder_) + " were set (! and FX)");
    for (std::size_t i = 0; i + 1 < p.size(); i += 2)
      move_to({p[i], p[i + 1]}, true, c.offset);
  } else {
    return false;
  }
  return true;
}

void SimulatedDevice::execute_hpgl(const ParsedCommand& c) {
  const auto& p = c.params;
  const std::string& n = c.name;
  if (n == "IN") {
    initialized_ = true;
    relative_ = false;
    pen_up();
    return;
  }
  if (n == "OI") {
    reply(profile_.firmware);
    return;
  }
  if (n == "OS") {
    reply(std::to_string(8 + (status() == DeviceState::Ready ? 16 : 0) + (down_ ? 1 : 0)));
    return;
  }
  if (options_.require_initialize && !initialized_) fail(c.offset, n + " before IN; (initialise)");
  auto coords = [&](bool down) {
    for (std::size_t i = 0; i + 1 < p.size(); i += 2) {
      const Vec2 q{p[i], p[i + 1]};
      move_to(relative_ ? pos_ + q : q, down, c.offset);
    }
  };
  auto int_in = [&](double v, int lo, int hi, const char* what) {
    if (v != std::floor(v) || v < lo || v > hi)
      fail(c.offset, std::string(what) + " " + fmt(v) + " out of range " + std::to_string(lo) + ".." +
                         std::to_string(hi));
    return static_cast<int>(v);
  };
  if (n == "OH") {
    reply(fmt(area_min_.x) + "," + fmt(area_min_.y) + "," + fmt(area_max_.x) + "," + fmt(area_max_.y));
  } else if (n == "PA" || n == "PR") {
    relative_ = n == "PR";
    coords(down_);
  } else if (n == "SP") {
    holder_ = p.empty() ? 0 : int_in(p[0], 0, profile_.holders, "pen");
    if (holder_ == 0) pen_up();
  } else if (n == "VS") {
    const int s = int_in(p[0], profile_.speed_steps.min, profile_.speed_steps.max, "velocity");
    speed_[p.size() > 1 ? int_in(p[1], 1, profile_.holders, "pen") : holder_] = s;
  } else if (n == "FS" || n == "!FS") {
    const int f = int_in(p[0], profile_.force_steps.min, profile_.force_steps.max, "force");
    force_[p.size() > 1 ? int_in(p[1], 1, profile_.holders, "pen") : holder_] = f;
  } else if (n == "PU") {
    if (p.empty())
      pen_up();
    else
      coords(false);
  } else if (n == "PD") {
    if (holder_ < 1) fail(c.offset, "PD with no pen selected (SP)");
    if (p.empty()) {
      if (options_.faults.no_media) fail(c.offset, "no media loaded: refusing to cut");
      if (!down_) strokes_.push_back({holder_, force_[holder_], speed_[holder_], {pos_}});
      down_ = true;
    } else {
      coords(true);
    }
  } else if (n == "LT" || n == "!ST") {
    // Line types change how a pen plotter dashes; a cutter ignores them.
  } else {
    fail(c.offset, "command " + n + " is not supported by this device");
  }
}

double SimulatedDevice::down_length_mm() const {
  double len = 0;
  for (const SimStroke& s : strokes_) {
    for (std::size_t i = 1; i < s.points.size(); ++i)
      len += norm(s.points[i] - s.points[i - 1]);
  }
  return len / profile_.units_per_mm;
}

Box2 SimulatedDevice::cut_bounds_mm() const {
  const Vec2 origin = mark_origin_.value_or(Vec2{0, 0});
  Box2 box;
  for (const SimStroke& s : strokes_) {
    for (Vec2 q : s.points)
      box.add(device_to_page(profile_, q + origin, area_mm_));
  }
  return box;
}

namespace {

// Cuts black, blade scores (a lighter pass than the holder's heaviest) blue, the scoring tool green, pen red.
SimScene::Line styled_line(const SimStroke& s, ToolKind kind, int heaviest) {
  SimScene::Line line;
  if (kind == ToolKind::Pen)
    line.rgb = {0.8, 0.1, 0.1};
  else if (kind == ToolKind::Scorer)
    line.rgb = {0.1, 0.55, 0.2};
  else if (s.force < heaviest)
    line.rgb = {0.1, 0.3, 0.8};
  line.width_mm = kind == ToolKind::Blade && s.force >= heaviest ? 0.25 : 0.2;
  return line;
}

void paint_mat_and_sheet(cairo_t* cr, const std::optional<Box2>& mat, const std::optional<Box2>& sheet) {
  auto rect = [&](const Box2& b) { cairo_rectangle(cr, b.min.x, b.min.y, b.width(), b.height()); };
  cairo_set_source_rgb(cr, 0.93, 0.93, 0.93);  // outside the sheet
  cairo_paint(cr);
  if (mat) {
    cairo_set_source_rgb(cr, 0.72, 0.80, 0.88);  // a light blue mat
    rect(*mat);
    cairo_fill(cr);
  }
  if (sheet) {
    cairo_set_source_rgb(cr, 1, 1, 1);
    rect(*sheet);
    cairo_fill_preserve(cr);
    cairo_set_source_rgb(cr, 0.55, 0.55, 0.55);
    cairo_set_line_width(cr, 0.3);
    cairo_stroke(cr);
  }
}

// As printed: the square and the two L brackets, in ink grey under the strokes.
void paint_marks(cairo_t* cr, const PrintedMarks& pm) {
  cairo_set_source_rgb(cr, 0.35, 0.35, 0.35);
  cairo_rectangle(cr, pm.origin_mm.x, pm.origin_mm.y, pm.square_mm, pm.square_mm);
  cairo_fill(cr);
  const double h = pm.stroke_mm / 2, a = pm.arm_mm;
  const Vec2 tr{pm.origin_mm.x + pm.extent_mm.x - h, pm.origin_mm.y + h};
  const Vec2 bl{pm.origin_mm.x + h, pm.origin_mm.y + pm.extent_mm.y - h};
  cairo_set_line_width(cr, pm.stroke_mm);
  cairo_move_to(cr, tr.x - a + h, tr.y);
  cairo_line_to(cr, tr.x, tr.y);
  cairo_line_to(cr, tr.x, tr.y + a - h);
  cairo_move_to(cr, bl.x, bl.y - a + h);
  cairo_line_to(cr, bl.x, bl.y);
  cairo_line_to(cr, bl.x + a - h, bl.y);
  cairo_stroke(cr);
}

void paint_cross(cairo_t* cr, Vec2 at, double r, double red, double green, double blue) {
  cairo_set_source_rgb(cr, red, green, blue);
  cairo_set_line_width(cr, 0.4);
  cairo_move_to(cr, at.x - r, at.y);
  cairo_line_to(cr, at.x + r, at.y);
  cairo_move_to(cr, at.x, at.y - r);
  cairo_line_to(cr, at.x, at.y + r);
  cairo_stroke(cr);
}

void paint_line(cairo_t* cr, const std::vector<Vec2>& points, double r, double g, double b, double width_mm) {
  cairo_set_source_rgb(cr, r, g, b);
  cairo_set_line_width(cr, width_mm);
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (i == 0)
      cairo_move_to(cr, points[i].x, points[i].y);
    else
      cairo_line_to(cr, points[i].x, points[i].y);
  }
  cairo_stroke(cr);
}

// A PNG (at `png_dpi`) or SVG of w_mm x h_mm drawn by `paint` in millimetres, written to `out`.
void write_picture(const std::filesystem::path& path, std::ostream& out, bool png, double png_dpi,
                   double w_mm, double h_mm, const std::function<void(cairo_t*)>& paint) {
  const double scale = png ? png_dpi / 25.4 : 72.0 / 25.4;
  cairo_surface_t* surface =
      png ? cairo_image_surface_create(CAIRO_FORMAT_RGB24,
                                       std::max(1, static_cast<int>(std::ceil(w_mm * scale))),
                                       std::max(1, static_cast<int>(std::ceil(h_mm * scale))))
          : cairo_svg_surface_create_for_stream(write_to_stream, &out, w_mm * scale, h_mm * scale);
  cairo_t* cr = cairo_create(surface);
  cairo_scale(cr, scale, scale);
  paint(cr);
  cairo_destroy(cr);
  cairo_surface_flush(surface);
  cairo_status_t st = CAIRO_STATUS_SUCCESS;
  if (png)
    st = cairo_surface_write_to_png_stream(surface, write_to_stream, &out);
  else
    cairo_surface_finish(surface);
  if (st == CAIRO_STATUS_SUCCESS) st = cairo_surface_status(surface);
  cairo_surface_destroy(surface);
  if (st != CAIRO_STATUS_SUCCESS) throw OutputError(path.string(), cairo_status_to_string(st));
}

}  // namespace

SimScene SimulatedDevice::scene() const {
  SimScene sc;
  const Vec2 origin = mark_origin_.value_or(Vec2{0, 0});
  auto page = [&](Vec2 d) { return device_to_page(profile_, d + origin, area_mm_); };
  sc.box.add(Vec2{0, 0});
  for (const SimStroke& s : strokes_) {
    for (Vec2 q : s.points)
      sc.box.add(page(q));
  }
  constexpr double kLargestMatDrawnMm = 1000;
  const Mat* loaded = options_.mat.empty() ? (profile_.mats.empty() ? nullptr : &profile_.mats.front())
                                           : profile_.mat(options_.mat);
  if (loaded && loaded->code && *loaded->code != 0 && loaded->length_mm <= kLargestMatDrawnMm)
    sc.mat = Box2{{0, 0}, {loaded->width_mm, loaded->length_mm}};
  if (options_.sheet_mm) sc.sheet = Box2{{0, 0}, *options_.sheet_mm};
  sc.machine_origin = device_to_page(profile_, {0, 0}, area_mm_);
  for (const auto& b : {sc.mat, sc.sheet}) {
    if (b) {
      sc.box.add(b->min);
      sc.box.add(b->max);
    }
  }
  sc.box.add(sc.machine_origin);
  if (mark_origin_) sc.search_origin = page({0, 0});
  std::map<int, int> blade_max_force;
  for (const SimStroke& s : strokes_)
    blade_max_force[s.holder] = std::max(blade_max_force[s.holder], s.force);
  for (const SimStroke& s : strokes_) {
    const auto it = options_.mounted.find(s.holder);
    const ToolKind kind = it == options_.mounted.end() ? ToolKind::Blade : it->second;
    SimScene::Line line = styled_line(s, kind, blade_max_force[s.holder]);
    for (Vec2 q : s.points)
      line.points.push_back(page(q));
    sc.lines.push_back(std::move(line));
  }
  return sc;
}

void SimulatedDevice::render(const std::filesystem::path& path, double png_dpi) const {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char ch) { return std::tolower(ch); });
  if (ext != ".png" && ext != ".svg")
    throw OutputError(path.string(), "the simulated device renders .png or .svg, not \"" + ext + "\"");
  const SimScene sc = scene();
  constexpr double kBorderMm = 5;
  const double w_mm = sc.box.width() + 2 * kBorderMm, h_mm = sc.box.height() + 2 * kBorderMm;
  write_file_atomically(path, [&](std::ostream& out) {
    write_picture(path, out, ext == ".png", png_dpi, w_mm, h_mm, [&](cairo_t* cr) {
      cairo_translate(cr, kBorderMm - sc.box.min.x, kBorderMm - sc.box.min.y);
      cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
      cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
      paint_mat_and_sheet(cr, sc.mat, sc.sheet);
      if (options_.printed_marks) paint_marks(cr, *options_.printed_marks);
      paint_cross(cr, sc.machine_origin, 4, 0.85, 0.1, 0.1);
      if (sc.search_origin) paint_cross(cr, *sc.search_origin, 3, 0.9, 0.5, 0.0);
      for (const SimScene::Line& l : sc.lines)
        paint_line(cr, l.points, l.rgb[0], l.rgb[1], l.rgb[2], l.width_mm);
    });
  });
}

}  // namespace foldkit::devices
