#include "foldkit/devices/hpgl.hpp"

namespace foldkit::devices {
namespace {

void point(std::string& out, DevicePoint p) {
  out += std::to_string(p.a);
  out += ',';
  out += std::to_string(p.b);
}

void command(std::string& out, const char* name, DevicePoint p) {
  out += name;
  point(out, p);
  out += ';';
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
      command(out, "PU", s.points.front());
      // One point per PD, as every reference writer sends; a lone point still lowers the tool.
      if (s.points.size() == 1) command(out, "PD", s.points.front());
      for (std::size_t i = 1; i < s.points.size(); ++i)
        command(out, "PD", s.points[i]);
      out += '\n';  // newline padding: some cutters on lp drop commands without it (inkcut#367)
    }
  }
  out += hpgl_abort_tail();
  return out;
}

std::string hpgl_abort_tail() {
  return "PU;SP0;IN;";
}

}  // namespace foldkit::devices
