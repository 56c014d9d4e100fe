#include "foldkit/devices/gpgl.hpp"

namespace foldkit::devices {
namespace {

// Silhouette Studio's corner settings for a blade, FF s,e in 0.1 mm (docs/plotter-protocols.md 2.3,
// the Cameo 3 recording): sharpen corners 0.1 mm at start and end. Pens and scorers get FF0,0.
constexpr int kSharpenStart = 1, kSharpenEnd = 1;
// Studio always sends the blade offset first as 0 (then the real one); the second argument is 1 SU.
constexpr int kOffsetMinor = 1;
// Cameo 4 line: Studio sets acceleration 0 before the first force and 3 after the second (2.3).
constexpr int kCameo4AccelFirst = 0, kCameo4AccelSecond = 3;
// Graphtec `! l`: l = 101..160 means l - 100 cm/s; the speed step of a Graphtec profile is in cm/s.
constexpr int kGraphtecSpeedBase = 100;
// Searching registration marks moves the head; the reference starts 10 mm before the printed mark.

// Appends the pieces and the terminator; building in place also sidesteps GCC 12's false -Wrestrict on
// chained string concatenation.
template <typename... Parts>
void cmd(std::string& out, const Parts&... parts) {
  (out += ... += parts);
  out += kEtx;
}

std::string num(std::int64_t v) {
  return std::to_string(v);
}

std::string pt(DevicePoint p) {
  return num(p.a) + "," + num(p.b);
}

void esc(std::string& out, char code) {
  out += kEsc;
  out += code;
}

// Status, model and initialise, then the calibration queries the reference reads on each family.
void handshake(std::string& out, const Job& job) {
  if (job.gpgl_family == GpglFamily::Graphtec) return;  // the CE list has no ESC 05, FG, TB71 or FA
  esc(out, '\x05');                                     // the sender reads "0" (ready) before anything else
  cmd(out, "FG");
  esc(out, '\x04');
  cmd(out, "TB71");
  cmd(out, "FA");
  if (job.gpgl_family == GpglFamily::Cameo3) cmd(out, "TC");
}

void setup(std::string& out, const Job& job) {
  if (job.gpgl_family != GpglFamily::Graphtec) {
    if (job.mat_code) cmd(out, "TG", num(*job.mat_code));
    cmd(out, "FN0");
    cmd(out, "TB50,0");
  }
  cmd(out, "\\", pt(job.window_min));
  cmd(out, "Z", pt(job.window_max));
}

// [IS] Graphtec.plot sends portrait orientation again right before the mark sequence, though the
// set-up already did: the search reads its coordinates in the orientation set last.
void regmark_search(std::string& out, const RegMarkSearch& r) {
  cmd(out, "TB50,0");
  cmd(out, "TB99");
  cmd(out, "TB52,", num(r.mark_type));
  cmd(out, "TB51,", num(r.arm_length));
  cmd(out, "TB53,", num(r.stroke));
  cmd(out, "TB55,1");
  cmd(out, r.command, ",", num(r.extent_a), ",", num(r.extent_b), ",", num(r.start_a), ",", num(r.start_b));
}

void corners(std::string& out, const Pass& pass, const std::string& h) {
  if (pass.tool == ToolKind::Blade) {
    cmd(out, "FF", num(kSharpenStart), ",0,", h);
    cmd(out, "FF", num(kSharpenStart), ",", num(kSharpenEnd), ",", h);
  } else {
    cmd(out, "FF0,0,", h);
  }
}

void depth(std::string& out, const Pass& pass) {
  if (pass.blade_depth) cmd(out, "TF", num(*pass.blade_depth), ",1");
}

// The Cameo 3 recording: ! FX FE FF FF FC0 FC18 TF for a blade; ! FX FC0 FE FF0,0 for a pen.
void tool_cameo3(std::string& out, const Pass& pass, const std::string& h) {
  cmd(out, "!", num(pass.speed_step), ",", h);
  cmd(out, "FX", num(pass.force_step), ",", h);
  if (pass.tool != ToolKind::Blade) {
    cmd(out, "FC0,", num(kOffsetMinor), ",", h);
    cmd(out, "FE0,", h);
    corners(out, pass, h);
    return;
  }
  cmd(out, "FE0,", h);
  corners(out, pass, h);
  cmd(out, "FC0,", num(kOffsetMinor), ",", h);
  if (pass.offset_code > 0) cmd(out, "FC", num(pass.offset_code), ",", num(kOffsetMinor), ",", h);
  depth(out, pass);
}

// Studio on a Cameo 4 Pro: FX TJ0 ! FC0 FE FF FF FX TJ3 FC18 (force and acceleration twice).
void tool_cameo4(std::string& out, const Pass& pass, const std::string& h) {
  cmd(out, "FX", num(pass.force_step), ",", h);
  cmd(out, "TJ", num(kCameo4AccelFirst));
  cmd(out, "!", num(pass.speed_step), ",", h);
  cmd(out, "FC0,", num(kOffsetMinor), ",", h);
  cmd(out, "FE0,", h);
  corners(out, pass, h);
  cmd(out, "FX", num(pass.force_step), ",", h);
  cmd(out, "TJ", num(kCameo4AccelSecond));
  cmd(out, "FC", num(pass.tool == ToolKind::Blade ? pass.offset_code : 0), ",", num(kOffsetMinor), ",", h);
  depth(out, pass);
}

// Graphtec's list: `! l` speed and `* a,f` acceleration and force; the blade offset is the panel's.
void tool_graphtec(std::string& out, const Job& job, const Pass& pass) {
  cmd(out, "!", num(kGraphtecSpeedBase + pass.speed_step));
  cmd(out, "*", num(job.gpgl_acceleration), ",", num(pass.force_step));
}

void tool(std::string& out, const Job& job, const Pass& pass) {
  const std::string h = num(pass.holder);
  if (job.select_holder) cmd(out, "J", h);
  switch (job.gpgl_family) {
    case GpglFamily::Cameo3:
      tool_cameo3(out, pass, h);
      break;
    case GpglFamily::Cameo4:
      tool_cameo4(out, pass, h);
      break;
    case GpglFamily::Graphtec:
      tool_graphtec(out, job, pass);
      break;
  }
}

// One point per D, as the reference sends: no command outgrows any device's line buffer.
void strokes(std::string& out, const Pass& pass) {
  for (const Stroke& s : pass.strokes) {
    if (s.points.empty()) continue;
    cmd(out, "M", pt(s.points.front()));
    // A lone point still lowers the tool: draw to itself.
    if (s.points.size() == 1) cmd(out, "D", pt(s.points.front()));
    for (std::size_t i = 1; i < s.points.size(); ++i)
      cmd(out, "D", pt(s.points[i]));
  }
}

}  // namespace

std::string encode_gpgl(const Job& job) {
  std::string out;
  handshake(out, job);
  setup(out, job);
  // The reference sets the window in machine coordinates, then searches; afterwards (0,0) is the mark.
  if (job.regmarks) regmark_search(out, *job.regmarks);
  for (const Pass& pass : job.passes) {
    tool(out, job, pass);
    strokes(out, pass);
  }
  out += gpgl_abort_tail(job);
  return out;
}

std::string gpgl_abort_tail(const Job& job) {
  std::string out;
  // The device holds the last segment back (blade look-ahead) until another command arrives: the
  // moves here flush it and lift the tool.
  if (job.gpgl_family == GpglFamily::Graphtec) {
    cmd(out, "H");
    return out;
  }
  cmd(out, "L0");
  cmd(out, "\\0,0");
  cmd(out, "M0,0");
  if (job.select_holder) cmd(out, "J0");
  cmd(out, "FN0");
  cmd(out, "TB50,0");
  return out;
}

std::string gpgl_abort_tail() {
  return gpgl_abort_tail(Job{});
}

}  // namespace foldkit::devices
