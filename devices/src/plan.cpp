#include "foldkit/devices/plan.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "foldkit/devices/path_order.hpp"
#include "foldkit/devices/printed_marks.hpp"
#include "foldkit/error.hpp"

namespace foldkit::devices {

const char* pass_kind_name(PassKind k) {
  switch (k) {
    case PassKind::Draw:
      return "draw";
    case PassKind::Score:
      return "score";
    case PassKind::Perforate:
      return "perforate";
    case PassKind::Cut:
      return "cut";
  }
  return "?";
}

Vec2 cutting_area_mm(const DeviceProfile& device, const std::string& mat_id) {
  if (device.mats.empty()) {
    if (!mat_id.empty() && mat_id != "none")
      throw DeviceError(device.name + " has no mat \"" + mat_id + "\" (it takes media without a mat)");
    return {device.area_width_mm, device.area_max_length_mm};
  }
  const Mat* mat = mat_id.empty() ? &device.mats.front() : device.mat(mat_id);
  if (!mat) {
    std::string known;
    for (const Mat& m : device.mats)
      known += (known.empty() ? "" : ", ") + m.id;
    throw DeviceError(device.name + " has no mat \"" + mat_id + "\" (known: " + known + ")");
  }
  return {std::fmin(mat->width_mm, device.area_width_mm),
          std::fmin(mat->length_mm, device.area_max_length_mm)};
}

double stroke_length_mm(const Stroke& stroke, double units_per_mm) {
  double len = 0;
  for (std::size_t i = 1; i < stroke.points.size(); ++i) {
    const double da = static_cast<double>(stroke.points[i].a - stroke.points[i - 1].a);
    const double db = static_cast<double>(stroke.points[i].b - stroke.points[i - 1].b);
    len += std::hypot(da, db);
  }
  return len / units_per_mm;
}

namespace {

// A polyline to be done by one pass, in placed page millimetres, with where it came from.
struct Item {
  std::vector<Vec2> points_mm;
  bool closed = false;
  PathRole role = PathRole::Cut;
  std::size_t source = 0;
  int piece = -1;
  std::string what;  // "cut path 12 (piece 3)", "text \"A1\"": for error messages
};

std::string fmt_mm(double v) {
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(2);
  s << v;
  return s.str();
}

// Everything needed to go from placed page mm to device units and to check the result.
struct Placement {
  const DeviceProfile* device = nullptr;
  std::string mat_label;
  Vec2 area_mm;
  Vec2 frame_mm;  // what reversed axes run from: the area, or the sheet (origin at the media)
  std::optional<Vec2> mark_origin_mm;    // cutting relative to registration marks: the top-left mark
  DevicePoint machine_min, machine_max;  // the window from the machine's origin (what \ and Z say)
  DevicePoint window_min, window_max;    // the same in the coordinates strokes are sent in

  Vec2 to_machine(Vec2 placed_mm) const { return page_to_device(*device, placed_mm, frame_mm); }
  DevicePoint to_device(Vec2 placed_mm) const {
    // Relative to the marks once they are found: the device's logical origin moves to the top-left mark.
    const Vec2 d =
        mark_origin_mm ? to_machine(placed_mm) - to_machine(*mark_origin_mm) : to_machine(placed_mm);
    return {std::llround(d.x), std::llround(d.y)};
  }
  bool inside(DevicePoint p) const {
    return p.a >= window_min.a && p.a <= window_max.a && p.b >= window_min.b && p.b <= window_max.b;
  }
  void check(const Item& item, std::size_t index_in_pass, const char* pass) const {
    for (Vec2 p : item.points_mm) {
      if (!std::isfinite(p.x) || !std::isfinite(p.y))
        throw DeviceError(item.what + " has a point that is not a number");
      if (inside(to_device(p))) continue;
      const double m = device->margin_mm;
      throw DeviceError("stroke " + std::to_string(index_in_pass + 1) + " of the " + pass + " pass (" +
                        item.what + ") leaves the cutting area of " + device->name + mat_label + " at (" +
                        fmt_mm(p.x) + ", " + fmt_mm(p.y) + ") mm; allowed " + fmt_mm(m) + ".." +
                        fmt_mm(area_mm.x - m) + " x " + fmt_mm(m) + ".." + fmt_mm(area_mm.y - m) + " mm");
    }
  }
};

Placement make_placement(const DeviceProfile& device, const PlanOptions& options, Vec2 sheet_mm,
                         std::optional<Vec2> mark_origin_mm) {
  Placement pl;
  pl.device = &device;
  pl.area_mm = cutting_area_mm(device, options.mat);
  pl.frame_mm = device.axes.origin_at_media ? sheet_mm : pl.area_mm;
  const std::string mat = options.mat.empty() && !device.mats.empty() ? device.mats.front().id : options.mat;
  pl.mat_label = mat.empty() ? "" : " with mat " + mat;
  pl.mark_origin_mm = mark_origin_mm;
  // The device reaches margin..size-margin along each of its axes from its origin, wherever the sheet is.
  const double m = device.margin_mm, k = device.units_per_mm;
  const Vec2 carriage{m * k, (pl.area_mm.x - m) * k}, feed{m * k, (pl.area_mm.y - m) * k};
  const Vec2 first = device.axes.feed_first ? feed : carriage,
             second = device.axes.feed_first ? carriage : feed;
  pl.machine_min = {std::llround(first.x), std::llround(second.x)};
  pl.machine_max = {std::llround(first.y), std::llround(second.y)};
  const DevicePoint o = pl.to_device({0, 0}),
                    z = {std::llround(pl.to_machine({0, 0}).x), std::llround(pl.to_machine({0, 0}).y)};
  // Logical = machine - mark origin (in device units): the window moves with the origin.
  const DevicePoint shift{z.a - o.a, z.b - o.b};
  pl.window_min = {pl.machine_min.a - shift.a, pl.machine_min.b - shift.b};
  pl.window_max = {pl.machine_max.a - shift.a, pl.machine_max.b - shift.b};
  return pl;
}

// Splits an open or closed polyline into dashes: `on_mm` cut, `off_mm` left standing, starting with a
// half gap so that both ends of a fold line stay uncut (the fold holds the pieces together there).
std::vector<std::vector<Vec2>> dashes(const std::vector<Vec2>& line, bool closed, double on_mm,
                                      double off_mm) {
  std::vector<Vec2> pts = line;
  if (closed && !pts.empty()) pts.push_back(pts.front());
  std::vector<std::vector<Vec2>> out;
  double total = 0;
  for (std::size_t i = 1; i < pts.size(); ++i)
    total += norm(pts[i] - pts[i - 1]);
  if (total <= 0) return out;
  // Dashes are spread evenly along the line rather than cut off at its end.
  const double period = on_mm + off_mm;
  const int count = std::max(1, static_cast<int>(std::floor((total + off_mm) / period + 1e-9)));
  const double slack = total - (count * period - off_mm);
  double start = slack / 2;
  std::size_t seg = 1;
  double seg_start = 0;
  auto point_at = [&](double s) {
    while (seg + 1 < pts.size() && seg_start + norm(pts[seg] - pts[seg - 1]) < s) {
      seg_start += norm(pts[seg] - pts[seg - 1]);
      ++seg;
    }
    const double len = norm(pts[seg] - pts[seg - 1]);
    const double t = len > 0 ? std::clamp((s - seg_start) / len, 0.0, 1.0) : 0.0;
    return pts[seg - 1] + (pts[seg] - pts[seg - 1]) * t;
  };
  for (int k = 0; k < count; ++k) {
    const double s0 = start + k * period, s1 = std::fmin(s0 + on_mm, total);
    std::vector<Vec2> dash{point_at(s0)};
    // Corners inside the dash are kept so a dash follows a bent fold line.
    double acc = seg_start;
    for (std::size_t i = seg; i < pts.size() && acc + norm(pts[i] - pts[i - 1]) < s1; ++i) {
      acc += norm(pts[i] - pts[i - 1]);
      if (acc > s0) dash.push_back(pts[i]);
    }
    dash.push_back(point_at(s1));
    out.push_back(std::move(dash));
  }
  return out;
}

// The Silhouette sensor looks for the square of its own size; a mark it cannot find would leave the
// blade cutting at an unknown place, so such a sheet is refused before any byte exists.
void check_searchable(const DeviceProfile& device, const PrintedMarks& m) {
  constexpr double kSquareToleranceMm = 0.05;
  const double want = device.regmarks.square_mm;
  if (std::fabs(m.square_mm - want) > kSquareToleranceMm)
    throw DeviceError(device.name + " finds only " + fmt_mm(want) +
                      " mm registration squares; the sheet's is " + fmt_mm(m.square_mm) +
                      " mm (lay it out with " + fmt_mm(want) + " mm squares)");
  if (!(m.arm_mm > m.square_mm) || !(m.stroke_mm > 0))
    throw DeviceError("the sheet's registration brackets (arm " + fmt_mm(m.arm_mm) + " mm, line " +
                      fmt_mm(m.stroke_mm) +
                      " mm) cannot be searched: the arms must be longer than the square");
}

// TB123/TB124 from the printed marks: the extent and the arm and line width as printed, the search
// starting this far before the mark (as the reference does) so a print shifted up or left is found.
constexpr double kSearchLeadMm = 10;

RegMarkSearch mark_search(const DeviceProfile& device, const Placement& pl, const PrintedMarks& m,
                          Vec2 origin_mm) {
  RegMarkSearch s;
  s.command = device.regmarks.search;
  s.mark_type = device.regmarks.mark_type;
  const Vec2 o = pl.to_machine(origin_mm);
  s.origin_a = std::llround(o.x);
  s.origin_b = std::llround(o.y);
  const double lead = kSearchLeadMm * device.units_per_mm;
  s.start_a = std::max<std::int64_t>(0, std::llround(o.x - lead));
  s.start_b = std::max<std::int64_t>(0, std::llround(o.y - lead));
  const Vec2 ext = pl.to_machine(origin_mm + m.extent_mm) - o;
  s.extent_a = std::llround(std::abs(ext.x));
  s.extent_b = std::llround(std::abs(ext.y));
  s.arm_length = std::llround(m.arm_mm * device.units_per_mm);
  s.stroke = std::llround(m.stroke_mm * device.units_per_mm);
  return s;
}

struct PassPlan {
  PassKind kind;
  ToolKind tool;
  const Tool* tool_def;
  ToolSettings settings;
  std::vector<Item> items;
};

// The job's device facts, before any pass.
Job job_for(const DeviceProfile& device, const PlanOptions& options) {
  Job job;
  job.device_id = device.id;
  job.device_name = device.name;
  job.protocol = device.protocol;
  job.units_per_mm = device.units_per_mm;
  job.firmware = device.firmware;
  job.hpgl_force_command = device.hpgl_force_command;
  job.gpgl_family = device.gpgl_family;
  job.gpgl_acceleration = device.gpgl_acceleration;
  job.select_holder = device.holders > 1;
  if (const Mat* mat = options.mat.empty() ? (device.mats.empty() ? nullptr : &device.mats.front())
                                           : device.mat(options.mat))
    job.mat_code = mat->code;
  return job;
}

// The sheet's registration marks, checked against what the device can search; nullopt without --regmarks.
std::optional<PrintedMarks> searchable_marks(const Sheet& sheet, const DeviceProfile& device,
                                             const PlanOptions& options) {
  if (!options.regmarks) return std::nullopt;
  if (!device.regmarks.supported || device.protocol != Protocol::Gpgl)
    throw DeviceError(device.name + " cannot search registration marks (print-and-cut)");
  std::optional<PrintedMarks> marks = printed_marks(sheet);
  if (!marks) throw DeviceError("the sheet has no registration marks (lay it out with marks and print it)");
  check_searchable(device, *marks);
  return marks;
}

std::string describe(const Path& p, std::size_t i) {
  std::string s = std::string(role_name(p.role)) + " path " + std::to_string(i + 1);
  if (p.piece >= 0) s += " (piece " + std::to_string(p.piece) + ")";
  return s;
}

std::vector<Vec2> shifted(const std::vector<Vec2>& pts, Vec2 shift) {
  std::vector<Vec2> out;
  out.reserve(pts.size());
  for (Vec2 p : pts)
    out.push_back(p + shift);
  return out;
}

// The pen pass: label paths, then seam numbers and part letters in the stroke font (a part cut from blank
// card is found by its letter too).
PassPlan draw_pass(const Sheet& sheet, const Tool& pen, const MediaProfile& media, const PlanOptions& options,
                   Vec2 shift) {
  PassPlan draw{PassKind::Draw, ToolKind::Pen, &pen, media.draw, {}};
  for (std::size_t i = 0; i < sheet.paths.size(); ++i) {
    const Path& p = sheet.paths[i];
    if (p.role == PathRole::Label && !p.points_mm.empty())
      draw.items.push_back({shifted(p.points_mm, shift), p.closed, p.role, i, p.piece, describe(p, i)});
  }
  if (!sheet.texts.empty() && !options.font) throw DeviceError("cannot draw labels: no stroke font loaded");
  for (std::size_t i = 0; i < sheet.texts.size(); ++i) {
    const Text& t = sheet.texts[i];
    if (t.role != PathRole::Label && t.role != PathRole::Piece) continue;
    const std::string what = t.role == PathRole::Piece ? "part letter \"" : "text \"";
    for (auto& stroke : text_strokes(*options.font, t)) {
      if (stroke.size() >= 2)
        draw.items.push_back({shifted(stroke, shift), false, t.role, i, t.piece, what + t.text + "\""});
    }
  }
  return draw;
}

// The option's fold method, else the device's scorer, else the media's or device's; a scorer the device
// lacks (or whose holder the pen takes) falls back to the media's other method, said in `notes`.
FoldMethod fold_method(const DeviceProfile& device, const MediaProfile& media, const PlanOptions& options,
                       int pen_holder, std::vector<std::string>& notes) {
  const Tool* scorer = device.tool(ToolKind::Scorer);
  FoldMethod method;
  if (options.fold_method) {
    method = *options.fold_method;
  } else if (device.fold_method == FoldMethod::Scorer && scorer) {
    method = FoldMethod::Scorer;
  } else {
    method = media.fold_method.value_or(device.fold_method);
  }
  if (method == FoldMethod::Scorer && (!scorer || scorer->holder == pen_holder)) {
    const FoldMethod fallback = media.fold_method.value_or(FoldMethod::ReducedForce);
    method = fallback == FoldMethod::Scorer ? FoldMethod::ReducedForce : fallback;
    notes.push_back(std::string(scorer ? "the pen takes the scoring tool's holder" : "no scoring tool") +
                    ": folds are marked by " + fold_method_name(method));
  }
  return method;
}

// The fold pass for `method` (not None): scored, kiss-cut with the blade, or perforated.
PassPlan score_pass(const Sheet& sheet, const DeviceProfile& device, const MediaProfile& media,
                    FoldMethod method, const Tool& blade, Vec2 shift) {
  PassPlan score{PassKind::Score, ToolKind::Blade, &blade, media.score, {}};
  if (method == FoldMethod::Scorer) {
    score.tool = ToolKind::Scorer;
    score.tool_def = device.tool(ToolKind::Scorer);
  } else if (method == FoldMethod::Perforate) {
    score.kind = PassKind::Perforate;
    score.settings = media.cut;
    score.settings.passes = 1;
  }
  for (std::size_t i = 0; i < sheet.paths.size(); ++i) {
    const Path& p = sheet.paths[i];
    if ((p.role != PathRole::Mountain && p.role != PathRole::Valley) || p.points_mm.size() < 2) continue;
    if (method == FoldMethod::Perforate) {
      for (auto& dash :
           dashes(shifted(p.points_mm, shift), p.closed, media.perforation_cut_mm, media.perforation_gap_mm))
        score.items.push_back({std::move(dash), false, p.role, i, p.piece, describe(p, i)});
    } else {
      score.items.push_back({shifted(p.points_mm, shift), p.closed, p.role, i, p.piece, describe(p, i)});
    }
  }
  return score;
}

PassPlan cut_pass(const Sheet& sheet, const Tool& blade, const MediaProfile& media, Vec2 shift) {
  PassPlan cut{PassKind::Cut, ToolKind::Blade, &blade, media.cut, {}};
  for (std::size_t i = 0; i < sheet.paths.size(); ++i) {
    const Path& p = sheet.paths[i];
    if (p.role == PathRole::Cut && p.points_mm.size() >= 2)
      cut.items.push_back({shifted(p.points_mm, shift), p.closed, p.role, i, p.piece, describe(p, i)});
  }
  return cut;
}

// The passes in the order they run: labels first (drawing on paper that is still whole keeps the ink where
// the print put it), then folds, outlines last (once a piece is cut free it may shift, and nothing may be
// done on it after that). Empty passes are left out.
std::vector<PassPlan> pass_plans(const Sheet& sheet, const DeviceProfile& device, const MediaProfile& media,
                                 const PlanOptions& options, Vec2 shift, std::vector<std::string>& notes) {
  std::vector<PassPlan> plans;
  const Tool* blade = device.tool(ToolKind::Blade);
  if (!blade) throw DeviceError(device.name + " has no blade");
  int pen_holder = 0;
  if (options.draw_labels) {
    const Tool* pen = device.tool(ToolKind::Pen);
    if (!pen) throw DeviceError(device.name + " has no pen holder: cannot draw labels");
    pen_holder = pen->holder;
    PassPlan draw = draw_pass(sheet, *pen, media, options, shift);
    if (!draw.items.empty()) plans.push_back(std::move(draw));
  }
  if (options.score_folds) {
    const FoldMethod method = fold_method(device, media, options, pen_holder, notes);
    if (method != FoldMethod::None) {
      PassPlan score = score_pass(sheet, device, media, method, *blade, shift);
      if (!score.items.empty()) plans.push_back(std::move(score));
    }
  }
  PassPlan cut = cut_pass(sheet, *blade, media, shift);
  if (!cut.items.empty()) plans.push_back(std::move(cut));
  return plans;
}

// The pass's paths in cutting order from `start_mm` (or in sheet order with options.order off).
PathOrder order_pass(const PassPlan& plan, Vec2 start_mm, const PlanOptions& options) {
  std::vector<ToolPath> tool_paths;
  tool_paths.reserve(plan.items.size());
  for (const Item& it : plan.items)
    tool_paths.push_back({it.points_mm, it.closed});
  PathOrderOptions po;
  po.start_mm = start_mm;
  po.overcut_mm = plan.kind == PassKind::Cut ? options.overcut_mm : 0;
  po.inside_first = true;
  if (options.order) return order_paths(tool_paths, po);
  PathOrder order;
  for (std::size_t i = 0; i < tool_paths.size(); ++i) {
    OrderedPath o;
    o.source = i;
    o.closed = tool_paths[i].closed;
    o.points_mm =
        o.closed ? closed_trajectory(tool_paths[i].points_mm, 0, po.overcut_mm) : tool_paths[i].points_mm;
    order.paths.push_back(std::move(o));
  }
  order.travel_before_mm = order.travel_after_mm = pen_up_travel_mm(order.paths, po.start_mm);
  return order;
}

// The ordered paths as device strokes with the pass's tool, holder and steps.
Pass device_pass(const PassPlan& plan, const PathOrder& order, const DeviceProfile& device,
                 const MediaProfile& media, const Placement& pl) {
  Pass pass;
  pass.kind = plan.kind;
  pass.tool = plan.tool;
  pass.holder = plan.tool_def->holder;
  pass.offset_code = plan.tool == ToolKind::Blade ? plan.tool_def->offset_code : 0;
  pass.speed_step = speed_step(device, plan.settings.speed_mm_s);
  pass.force_step = force_step(device, plan.settings.force_gf);
  pass.speed_mm_s = pass.speed_step * device.mm_s_per_speed_step;
  // The AutoBlade's depth is physical: every pass with it (a kiss-cut score too) gets the cut's depth.
  if (plan.tool == ToolKind::Blade && plan.tool_def->autoblade) pass.blade_depth = media.cut.blade_depth;
  for (const OrderedPath& o : order.paths) {
    if (o.points_mm.size() < 2) continue;
    Stroke s;
    s.role = plan.items[o.source].role;
    s.source = plan.items[o.source].source;
    for (Vec2 p : o.points_mm) {
      const DevicePoint d = pl.to_device(p);
      if (!pl.inside(d))  // overcut follows the path, so this only trips on a planner bug
        throw DeviceError("overcut of " + plan.items[o.source].what + " leaves the cutting area");
      if (s.points.empty() || !(s.points.back() == d)) s.points.push_back(d);
    }
    if (s.points.size() < 2) s.points.push_back(s.points.back());  // a dot still lowers the tool
    pass.strokes.push_back(std::move(s));
  }
  return pass;
}

// Where the tool is after the ordered paths (unchanged when they are all empty).
Vec2 end_of(const PathOrder& order, Vec2 at_mm) {
  for (auto it = order.paths.rbegin(); it != order.paths.rend(); ++it)
    if (!it->points_mm.empty()) return it->points_mm.back();
  return at_mm;
}

// Adds the pass to the job, once per repeat the settings ask for, with its length, travel and time.
void add_pass(Job& job, const Pass& pass, const PathOrder& order, const ToolSettings& settings,
              const DeviceProfile& device) {
  double length = 0;
  for (const Stroke& s : pass.strokes)
    length += stroke_length_mm(s, device.units_per_mm);
  JobStats& st = job.stats;
  const int repeats = std::max(1, settings.passes);
  for (int r = 0; r < repeats; ++r) {
    st.cut_length_mm += length;
    st.travel_before_mm += order.travel_before_mm;
    st.travel_after_mm += order.travel_after_mm;
    st.strokes += pass.strokes.size();
    st.estimated_s += length / std::max(pass.speed_mm_s, 1e-9) +
                      static_cast<double>(pass.strokes.size()) * device.tool_change_s;
    job.passes.push_back(pass);
  }
}

}  // namespace

Job plan_job(const Sheet& sheet, const DeviceProfile& device, const MediaProfile& media,
             const PlanOptions& options) {
  Job job = job_for(device, options);
  const std::optional<PrintedMarks> marks = searchable_marks(sheet, device, options);
  const Vec2 mark_origin = marks ? marks->origin_mm + options.offset_mm : Vec2{0, 0};
  const Placement pl =
      make_placement(device, options, sheet.size_mm, marks ? std::optional<Vec2>(mark_origin) : std::nullopt);
  job.window_min = pl.machine_min;
  job.window_max = pl.machine_max;
  if (marks) job.regmarks = mark_search(device, pl, *marks, mark_origin);

  const Vec2 shift = options.offset_mm + (options.regmarks ? options.print_cut_offset_mm : Vec2{0, 0});
  const std::vector<PassPlan> plans = pass_plans(sheet, device, media, options, shift, job.notes);
  // Every stroke is checked before any ordering or encoding, in sheet order, so the message names the
  // first offending path of the sheet.
  for (const PassPlan& plan : plans) {
    for (std::size_t k = 0; k < plan.items.size(); ++k)
      pl.check(plan.items[k], k, pass_kind_name(plan.kind));
  }
  Vec2 at_mm = options.regmarks ? mark_origin : device_to_page(device, {0, 0}, pl.frame_mm);
  for (const PassPlan& plan : plans) {
    const PathOrder order = order_pass(plan, at_mm, options);
    add_pass(job, device_pass(plan, order, device, media, pl), order, plan.settings, device);
    at_mm = end_of(order, at_mm);
  }
  job.stats.estimated_s += job.stats.travel_after_mm / device.travel_speed_mm_s;
  return job;
}

}  // namespace foldkit::devices
