#include "foldkit/devices/gpgl.hpp"

#include <algorithm>

namespace foldkit::devices {
namespace {

// Long strokes are split over several D commands so no command outgrows a device's line buffer; the
// first point of each continuation repeats the last of the previous one implicitly (D continues).
constexpr std::size_t kPointsPerDraw = 64;

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

void append_pt(std::string& out, DevicePoint p) {
  out += num(p.a);
  out += ',';
  out += num(p.b);
}

std::string pt(DevicePoint p) {
  std::string s;
  append_pt(s, p);
  return s;
}

}  // namespace

std::string encode_gpgl(const Job& job) {
  std::string out;
  out += kEsc;
  out += '\x05';  // status: the sender reads "0" (ready) before anything else
  cmd(out, "FG");
  out += kEsc;
  out += '\x04';  // initialise
  cmd(out, "TB71");
  cmd(out, "FA");
  cmd(out, "TG", num(job.mat_code));
  cmd(out, "FN0");
  cmd(out, "TB50,0");
  if (job.regmarks) {
    const RegMarkSearch& r = *job.regmarks;
    cmd(out, "TB99");
    cmd(out, "TB52,", num(r.mark_type));
    cmd(out, "TB51,", num(r.arm_length));
    cmd(out, "TB53,", num(r.stroke));
    cmd(out, "TB55,1");
    cmd(out, r.command, ",", num(r.extent_a), ",", num(r.extent_b), ",", num(r.origin_a), ",",
        num(r.origin_b));
  }
  // The window is in logical coordinates, which a mark search moves to the top-left mark: set it after.
  cmd(out, "\\", pt(job.window_min));
  cmd(out, "Z", pt(job.window_max));
  for (const Pass& pass : job.passes) {
    const std::string h = num(pass.holder);
    cmd(out, "J", h);
    cmd(out, "!", num(pass.speed_step), ",", h);
    cmd(out, "FX", num(pass.force_step), ",", h);
    cmd(out, "FE0,", h);
    cmd(out, "FC0,1,", h);
    if (pass.offset_code > 0) cmd(out, "FC", num(pass.offset_code), ",1,", h);
    for (const Stroke& s : pass.strokes) {
      if (s.points.empty()) continue;
      cmd(out, "M", pt(s.points.front()));
      const std::size_t n = std::max<std::size_t>(s.points.size(), 2);
      for (std::size_t i = 1; i < n; i += kPointsPerDraw) {
        std::string d = "D";
        for (std::size_t k = i; k < std::min(n, i + kPointsPerDraw); ++k) {
          if (k > i) d += ',';
          append_pt(d, s.points[std::min(k, s.points.size() - 1)]);
        }
        cmd(out, d);
      }
    }
  }
  out += gpgl_abort_tail();
  return out;
}

std::string gpgl_abort_tail() {
  std::string out;
  // The device holds the last segment back (blade look-ahead) until another command arrives: the
  // moves here flush it and lift the tool.
  cmd(out, "L0");
  cmd(out, "\\0,0");
  cmd(out, "M0,0");
  cmd(out, "J0");
  cmd(out, "FN0");
  cmd(out, "TB50,0");
  return out;
}

}  // namespace foldkit::devices
