#include "bench_layout.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <optional>
#include <regex>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench_before.hpp"
#include "choose_parts.hpp"
#include "foldkit/error.hpp"
#include "foldkit/layout/layout.hpp"
#include "foldkit/layout/pack.hpp"
#include "foldkit/layout/paper.hpp"
#include "foldkit/unfold/mesh_io.hpp"
#include "foldkit/unfold/unfold.hpp"
#include "foldkit/unfold/unfolding.hpp"
#include "json_report.hpp"
#include "layout_options.hpp"
#include "median.hpp"
#include "pipeline.hpp"
#include "print_cuts.hpp"
#include "sheet_fill.hpp"

namespace foldkit::cli {
namespace {
namespace fs = std::filesystem;
using nlohmann::json;

struct Row {
  std::string mesh;
  int faces = 0;
  double size_mm = 0;
  std::string error;
  long sheets = 0, bound = 0;
  long shape_bound = 0;   ///< the flat faces' shape bound (layout::shape_sheet_bound)
  long spaced_bound = 0;  ///< the pieces' outlines kept a gap apart (layout::spaced_sheet_bound)
  long larger_bound() const { return std::max({bound, shape_bound, spaced_bound}); }
  int parts = 0, seams = 0, no_tab = 0;
  double coverage = 0, seconds = 0;
  double used_sheets = 0;  ///< area of parts and tabs over one printable area
  double cpu_seconds = 0;  ///< process CPU time: the machine may be shared, the wall clock then lies
  /// What unfold::check_unfolding finds wrong with the parts (congruence, overlap, partners): none.
  std::vector<std::string> part_problems;
  const BeforeRun* before = nullptr;  ///< the same run measured before a change, if given
};

std::vector<fs::path> mesh_files(const fs::path& corpus) {
  static const std::regex ext(R"(\.(obj|off|stl|ply)$)", std::regex::icase);
  std::vector<fs::path> files;
  for (const fs::path& dir : {corpus / "lowpoly", corpus})
    if (fs::is_directory(dir))
      for (const auto& entry : fs::directory_iterator(dir))
        if (entry.is_regular_file() && std::regex_search(entry.path().string(), ext))
          files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

// What `make` does with one unfolding at one size: the parts chosen and laid out (choose_and_note_parts).
Row run_one(UnfoldRun run, const layout::LayoutOptions& asked) {
  // make's default colour options: a coloured model keeps the gap its bleed needs.
  const layout::LayoutOptions o = with_bleed_gap(asked, run.loaded.mesh, layout::FillOptions{});
  Row row;
  const auto start = std::chrono::steady_clock::now();
  const std::clock_t cpu_start = std::clock();
  auto stop = [&] {
    row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    row.cpu_seconds = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  };
  try {
    const ChooseOptions choose =
        bleed_room(choose_options_of(LayoutCliOptions{}), run.loaded.mesh, layout::FillOptions{});
    std::optional<layout::LayoutResult> laid_out = choose_and_note_parts(run, o, choose);
    const unfold::Unfolding& chosen = run.result.unfolding;
    const layout::LayoutResult r = laid_out ? std::move(*laid_out) : layout::layout_sheets(chosen, o);
    stop();
    row.part_problems = unfold::check_unfolding(run.loaded.mesh, chosen);
    const Box2 area = layout::printable_area(o);
    const double used = r.overall.piece_area_mm2 + r.overall.tab_area_mm2;
    row.sheets = static_cast<long>(r.sheets.size());
    row.bound = area_sheet_bound(o, used);
    row.shape_bound = flat_face_sheet_bound(chosen, o);
    row.spaced_bound = layout::spaced_sheet_bound(r, o);
    row.parts = chosen.piece_count;
    row.seams = chosen.seam_count();
    row.no_tab = r.overall.dropped_tabs;
    row.coverage = r.overall.coverage;
    row.used_sheets = used / (area.width() * area.height());
  } catch (const Error& e) {
    row.error = e.what();
    stop();
  }
  return row;
}

void print_row(const Row& row) {
  if (!row.error.empty()) {
    std::printf("%-28s %5d %5.0f | error: %s\n", row.mesh.c_str(), row.faces, row.size_mm, row.error.c_str());
  } else {
    std::printf("%-28s %5d %5.0f | %6ld %5ld %5ld %6ld %5d %7.0f%% %3d/%-3d %7.2f %7.2f", row.mesh.c_str(),
                row.faces, row.size_mm, row.sheets, row.bound, row.shape_bound, row.spaced_bound, row.parts,
                100 * row.coverage, row.no_tab, row.seams, row.seconds, row.cpu_seconds);
    if (const BeforeRun* b = row.before)
      std::printf(" | %6ld %5ld %5ld %7.0f%% %3ld/%-3ld %7.2f", b->sheets, b->area_bound, b->parts,
                  100 * b->coverage, b->seams_without_tab, b->seams, b->wall_s);
    std::printf("\n");
  }
  if (!row.part_problems.empty())
    std::printf("  parts fail the unfolding checks: %s\n", row.part_problems.front().c_str());
  std::fflush(stdout);
}

// One mesh file: unfolded once, laid out at every size (rows printed as they finish unless JSON). Nothing
// for a file that does not load or lies outside the face bounds.
void bench_file(const LayoutBenchArgs& a, const fs::path& file, Vec2 paper, const BeforeRuns* before,
                std::vector<Row>& rows) {
  unfold::LoadedMesh loaded;
  try {
    loaded = unfold::load_mesh(file);
  } catch (const Error&) {
    return;  // not a usable mesh: the loader has its own tests
  }
  if (loaded.mesh.num_faces() < a.min_faces || loaded.mesh.num_faces() > a.max_faces) return;
  const std::string name =
      (file.parent_path().filename() == "lowpoly" ? "lowpoly/" : "") + file.filename().string();
  for (double size : a.sizes_mm) {
    layout::LayoutOptions o;
    o.paper_mm = paper;
    o.size_mm = size;
    if (a.nest2d) o.pack.engine = layout::PackEngine::Nest2d;
    // Unfolded per size, as `make` unfolds: the cuts depend on the print scale (print_cuts.hpp).
    unfold::UnfoldOptions uo;
    uo.time_limit_s = a.time_limit_s;
    uo.cuts = cuts_for_print(loaded.mesh, o, uo.cuts);
    // The unfolding is timed apart (`bench`), the choice of parts with its layouts here, as make runs it.
    UnfoldRun run{loaded, unfold::unfold_mesh(loaded.mesh, uo), uo};
    Row row = run_one(std::move(run), o);
    row.mesh = name;
    row.faces = loaded.mesh.num_faces();
    row.size_mm = size;
    if (before) row.before = before->find(name, size);
    if (!a.json_out) print_row(row);
    rows.push_back(std::move(row));
  }
}

// The layout targets on the totals (issue 11): sheets at most this many times the sum of the area
// bounds, and this median coverage.
constexpr double kSheetRatioTarget = 1.15;
constexpr double kMedianCoverageTarget = 0.55;

// The figures the layout targets are judged by, over the rows without an error.
struct Totals {
  long sheets = 0, bound = 0, mid_seams = 0, mid_no_tab = 0;
  long larger_bound = 0;    ///< sum of the largest of the three bounds per run
  long over = 0;            ///< runs more than one sheet over the area bound
  long over_reachable = 0;  ///< runs more than one sheet over the largest bound
  long unreachable = 0;     ///< runs whose shape or spaced bound exceeds the area bound
  long invalid = 0;         ///< runs whose parts fail unfold::check_unfolding
  double seconds = 0, cpu_seconds = 0;
  std::vector<double> coverage;
  std::vector<FilledRun> filled;  ///< the runs as the fill yardstick sees them (sheet_fill.hpp)
  double ratio() const { return bound > 0 ? double(sheets) / double(bound) : NAN; }
  /// seams without a tab over the runs of 350-1,000 faces at 150 mm
  double share() const { return mid_seams > 0 ? double(mid_no_tab) / double(mid_seams) : NAN; }
};

Totals totals(const std::vector<Row>& rows) {
  Totals t;
  for (const Row& r : rows) {
    if (!r.error.empty()) continue;
    t.sheets += r.sheets;
    t.bound += r.bound;
    const long larger = r.larger_bound();
    t.larger_bound += larger;
    t.over += r.sheets > r.bound + 1;
    t.over_reachable += r.sheets > larger + 1;
    t.unreachable += larger > r.bound;
    t.invalid += !r.part_problems.empty();
    t.seconds += r.seconds;
    t.cpu_seconds += r.cpu_seconds;
    t.coverage.push_back(r.coverage);
    t.filled.push_back({r.used_sheets, r.bound});
    if (r.size_mm == 150 && r.faces >= 350 && r.faces <= 1000) {
      t.mid_seams += r.seams;
      t.mid_no_tab += r.no_tab;
    }
  }
  return t;
}

// The fill a run's parts and tabs would need on one sheet fewer; infinite on one sheet.
double one_sheet_fewer_fill(const Row& r) {
  return r.sheets > 1 ? r.used_sheets / static_cast<double>(r.sheets - 1) : INFINITY;
}

// The runs above all their bounds whose sheet fewer needs less than `fill`, the fill the whole set
// reaches: where the packing did worse than it does on the set, the first places to look.
std::vector<const Row*> below_par(const std::vector<Row>& rows, double fill) {
  std::vector<const Row*> out;
  for (const Row& r : rows)
    if (r.error.empty() && r.sheets > r.larger_bound() && one_sheet_fewer_fill(r) < fill) out.push_back(&r);
  std::sort(out.begin(), out.end(),
            [](const Row* a, const Row* b) { return one_sheet_fewer_fill(*a) < one_sheet_fewer_fill(*b); });
  return out;
}

// The fill of every sheet the totals correspond to, and the fills the two targets ask for.
struct Fills {
  double now = NAN, ratio_target = NAN, coverage_target = NAN;
};

Fills fills(const Totals& t) {
  if (t.filled.empty()) return {};
  const auto ratio_sheets = static_cast<long>(std::floor(kSheetRatioTarget * static_cast<double>(t.bound)));
  return {fill_for_sheets(t.filled, t.sheets), fill_for_sheets(t.filled, ratio_sheets),
          fill_for_median_coverage(t.filled, kMedianCoverageTarget)};
}

// The runs measured both times: as measured now, and as the report before recorded them (its bounds of
// shapes and gaps unknown, so taken as the area bound).
struct SharedRuns {
  std::vector<Row> now, before;
};

SharedRuns shared_runs(const std::vector<Row>& rows) {
  SharedRuns shared;
  for (const Row& r : rows) {
    if (!r.error.empty() || r.before == nullptr) continue;
    shared.now.push_back(r);
    Row b;
    b.mesh = r.mesh;
    b.faces = r.faces;
    b.size_mm = r.size_mm;
    b.sheets = r.before->sheets;
    b.bound = r.before->area_bound;
    b.parts = static_cast<int>(r.before->parts);
    b.seams = static_cast<int>(r.before->seams);
    b.no_tab = static_cast<int>(r.before->seams_without_tab);
    b.coverage = r.before->coverage;
    b.seconds = r.before->wall_s;
    shared.before.push_back(std::move(b));
  }
  return shared;
}

long total_parts(const std::vector<Row>& rows) {
  long parts = 0;
  for (const Row& r : rows)
    parts += r.parts;
  return parts;
}

// The totals both measurements are compared by, over the runs they share.
json compared_json(const std::vector<Row>& rows) {
  const Totals t = totals(rows);
  return {{"run_count", rows.size()},
          {"sheet_count", t.sheets},
          {"area_bound_sheet_count", t.bound},
          {"sheets_over_bound_ratio", t.ratio()},
          {"runs_more_than_one_over_count", t.over},
          {"part_count", total_parts(rows)},
          {"median_coverage", median(t.coverage)},
          {"seams_without_tab_fraction", t.share()},
          {"wall_s", t.seconds}};
}

std::string compared_text(const std::vector<Row>& rows) {
  const Totals t = totals(rows);
  char no_tab[96] = "(no run of 350-1,000 faces at 150 mm)";
  if (t.mid_seams > 0)
    std::snprintf(no_tab, sizeof no_tab, "%ld/%ld (%.1f%%)", t.mid_no_tab, t.mid_seams, 100 * t.share());
  char line[320];
  std::snprintf(line, sizeof line,
                "%ld sheets, area bound %ld (x%.2f), %ld runs more than one sheet over, %ld parts, median "
                "coverage %.1f%%, seams without a tab %s, layout %.1f s wall",
                t.sheets, t.bound, t.ratio(), t.over, total_parts(rows), 100 * median(t.coverage), no_tab,
                t.seconds);
  return line;
}

void print_compared(const std::vector<Row>& rows, const BeforeRuns& before) {
  const SharedRuns shared = shared_runs(rows);
  std::printf("before (%s), on the %zu runs measured both times:\n", before.file.c_str(), shared.now.size());
  if (shared.now.empty()) return;
  std::printf("  before: %s\n  now:    %s\n", compared_text(shared.before).c_str(),
              compared_text(shared.now).c_str());
}

json bench_json(const std::vector<Row>& rows, const Totals& t) {
  json out{{"rows", json::array()}};
  for (const Row& r : rows) {
    json j{{"mesh", r.mesh},
           {"face_count", r.faces},
           {"size_mm", r.size_mm},
           {"wall_s", r.seconds},
           {"cpu_s", r.cpu_seconds}};
    if (!r.error.empty()) {
      j["error"] = r.error;
    } else {
      j.update({{"sheet_count", r.sheets},
                {"area_bound_sheet_count", r.bound},
                {"shape_bound_sheet_count", r.shape_bound},
                {"spaced_bound_sheet_count", r.spaced_bound},
                {"part_count", r.parts},
                {"coverage", r.coverage},
                {"used_area_ratio", r.used_sheets},
                {"seam_count", r.seams},
                {"seams_without_tab_count", r.no_tab},
                {"part_problems", r.part_problems}});
      if (const BeforeRun* b = r.before)
        j["before"] = {{"sheet_count", b->sheets}, {"area_bound_sheet_count", b->area_bound},
                       {"part_count", b->parts},   {"coverage", b->coverage},
                       {"seam_count", b->seams},   {"seams_without_tab_count", b->seams_without_tab},
                       {"wall_s", b->wall_s}};
    }
    out["rows"].push_back(j);
  }
  const Fills f = fills(t);
  json par = json::array();
  for (const Row* r : below_par(rows, f.now))
    par.push_back({{"mesh", r->mesh},
                   {"size_mm", r->size_mm},
                   {"one_sheet_fewer_fill_fraction", one_sheet_fewer_fill(*r)}});
  out["totals"] = {{"sheet_count", t.sheets},
                   {"area_bound_sheet_count", t.bound},
                   {"sheets_over_bound_ratio", t.ratio()},
                   {"runs_more_than_one_over_count", t.over},
                   {"larger_bound_sheet_count", t.larger_bound},
                   {"runs_area_bound_unreachable_count", t.unreachable},
                   {"runs_more_than_one_over_larger_bound_count", t.over_reachable},
                   // parts failing the unfolding's invariants (congruence, overlap, partners)
                   {"runs_with_invalid_parts_count", t.invalid},
                   {"median_coverage", median(t.coverage)},
                   // every sheet filled to this share of its printable area gives the sheets counted
                   {"equivalent_fill_fraction", f.now},
                   {"sheet_ratio_target_fill_fraction", f.ratio_target},
                   {"median_coverage_target_fill_fraction", f.coverage_target},
                   // runs above their bounds whose sheet fewer needs less than the equivalent fill
                   {"below_par_runs", par},
                   // over the runs of 350-1,000 faces at 150 mm
                   {"seams_without_tab_fraction", t.share()},
                   {"wall_s", t.seconds},
                   {"cpu_s", t.cpu_seconds}};
  return out;
}

void print_totals(const std::vector<Row>& rows, const Totals& t) {
  char no_tab[96] = "no mesh of 350-1,000 faces at 150 mm";
  if (t.mid_seams > 0)
    std::snprintf(no_tab, sizeof no_tab, "%ld/%ld (%.1f%%) on 350-1,000 faces at 150 mm", t.mid_no_tab,
                  t.mid_seams, 100 * t.share());
  std::printf(
      "totals: %ld sheets, area bound %ld (x%.2f), %ld runs more than one sheet over; %ld runs where shapes "
      "or gaps leave the area bound out of reach, larger bound %ld (x%.2f), %ld runs more than one sheet "
      "over it; "
      "median coverage %.0f%%, seams without a tab %s, layout %.1f s (CPU %.1f s)\n",
      t.sheets, t.bound, t.ratio(), t.over, t.unreachable, t.larger_bound,
      t.larger_bound > 0 ? double(t.sheets) / double(t.larger_bound) : NAN, t.over_reachable,
      100 * median(t.coverage), no_tab, t.seconds, t.cpu_seconds);
  std::printf("parts checked (congruent, overlap-free, partners matched): %zu runs, %ld failing\n",
              t.coverage.size(), t.invalid);
  const Fills f = fills(t);
  if (!std::isnan(f.now))
    std::printf(
        "fill: these sheets are every sheet filled to %.1f%% of its printable area; x%.2f of the area bound "
        "needs %.1f%%, median coverage %.0f%% needs %.1f%%\n",
        100 * f.now, kSheetRatioTarget, 100 * f.ratio_target, 100 * kMedianCoverageTarget,
        100 * f.coverage_target);
  const std::vector<const Row*> par = below_par(rows, f.now);
  if (par.empty()) return;
  std::printf("below par (a sheet fewer needs less than %.1f%%):", 100 * f.now);
  for (std::size_t k = 0; k < par.size(); ++k)
    std::printf("%s %s at %.0f mm %.1f%%", k ? ";" : "", par[k]->mesh.c_str(), par[k]->size_mm,
                100 * one_sheet_fewer_fill(*par[k]));
  std::printf("\n");
}

}  // namespace

void run_layout_bench(const LayoutBenchArgs& a) {
  const fs::path corpus = a.corpus;
  if (!fs::is_directory(corpus)) throw InputError(corpus.string(), "no such folder of meshes");
  const auto paper = layout::parse_paper(a.paper);
  if (!paper) throw Error("--paper: unknown paper '" + a.paper + "'", ExitCode::Usage);
  // Read first: a report that is not one must not cost a whole benchmark.
  std::optional<BeforeRuns> before;
  if (!a.before.empty()) before = read_before_runs(a.before);
  if (!a.json_out) {
    std::printf(
        "foldkit bench --layout: %s, %d-%d faces, %s, search unfolding (seed 1)\n%-28s %5s %5s | %6s %5s %5s "
        "%6s %5s %8s %7s %7s %7s",
        corpus.string().c_str(), a.min_faces, a.max_faces, a.paper.c_str(), "mesh", "faces", "size", "sheets",
        "area", "shape", "spaced", "parts", "coverage", "no tab", "s", "cpu s");
    if (before)
      std::printf(" | %6s %5s %5s %8s %7s %7s", "before", "area", "parts", "coverage", "no tab", "s");
    std::printf("\n");
  }
  std::vector<Row> rows;
  for (const fs::path& file : mesh_files(corpus))
    if (a.filter.empty() || file.filename().string().find(a.filter) != std::string::npos)
      bench_file(a, file, *paper, before ? &*before : nullptr, rows);
  const Totals t = totals(rows);
  if (a.json_out) {
    json out = bench_json(rows, t);
    if (before) {
      const SharedRuns shared = shared_runs(rows);
      out["before"] = {{"file", before->file},
                       {"totals", compared_json(shared.before)},
                       {"now_totals", compared_json(shared.now)}};
    }
    std::cout << versioned(out).dump(2) << "\n";
  } else {
    print_totals(rows, t);
    if (before) print_compared(rows, *before);
  }
}

}  // namespace foldkit::cli
