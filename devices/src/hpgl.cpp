#include "foldkit/devices/hpgl.hpp"

#include <algorithm>

namespace foldkit::devices {
namespace {

void point(std::string& out, DevicePoint p) {
  out += std::to_string(p.a);
  out += ',';
  out += std::to_string(p.b);
}

}  // namespace

std::string encode_hpgl(const Job& job) {
  std::string out = "IN;PA;";
  for (const Pass& pass : job.passes) {
    out += "SP";
    out += std::to_string(pass.holder);
    out += ";VS";
    out += std::to_string(pass.speed_step);
    out += ';';
    if (!job.hpgl_force_command.empty()) {
      out += job.hpgl_force_command;
      out += std::to_string(pass.force_step);
      out += ';';
    }
    for (const Stroke& s : pass.strokes) {
      if (s.points.empty()) continue;
      out += "PU";
      point(out, s.points.front());
      out += ";PD";
      // A lone point still lowers the tool: repeat it so PD has coordinates (a bare PD; draws nothing).
      const std::size_t n = std::max<std::size_t>(s.points.size(), 2);
      for (std::size_t i = 1; i < n; ++i) {
        if (i > 1) out += ',';
        point(out, s.points[std::min(i, s.points.size() - 1)]);
      }
      out += ";\n";  // newline padding: some cutters on lp drop commands without it (inkcut#367)
    }
  }
  out += "PU;SP0;IN;";
  return out;
}

std::string hpgl_abort_tail() {
  return "PU;SP0;IN;";
}

}  // namespace foldkit::devices
