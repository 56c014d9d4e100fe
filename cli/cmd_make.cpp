// `foldkit make MESH -o model.pdf|svg|png`: load -> unfold -> lay out -> render, the main job.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <tuple>

#include <nlohmann/json.hpp>

#include "choices.hpp"
#include "cmd_make.hpp"
#include "colour_options.hpp"
#include "commands.hpp"
#include "foldkit/devices/atomic_file.hpp"
#include "foldkit/devices/bundle.hpp"
#include "foldkit/devices/dxf.hpp"
#include "foldkit/devices/render.hpp"
#include "foldkit/error.hpp"
#include "foldkit/layout/guide.hpp"
#include "installed_data.hpp"
#include "json_report.hpp"
#include "layout_options.hpp"
#include "limits.hpp"
#include "output_paths.hpp"
#include "pipeline.hpp"

namespace foldkit::cli {
namespace {

// Dash patterns (mm on, off, …) by name.
const std::map<std::string, std::vector<double>>& fold_styles() {
  static const std::map<std::string, std::vector<double>> styles = {
      {"dash-dot", {2.5, 0.8, 0.4, 0.8}}, {"dashed", {2.0, 1.0}}, {"dotted", {0.4, 0.8}}, {"solid", {}}};
  return styles;
}

nlohmann::json stats_json(const layout::SheetStats& s) {
  return {{"coverage", s.coverage},
          {"piece_count", s.pieces},
          {"tab_count", s.tabs},
          {"dropped_tab_count", s.dropped_tabs},
          {"split_tab_count", s.split_tabs},
          {"label_count", s.labels},
          {"labels_with_leader_count", s.leaders},
          {"min_label_mm", s.min_label_mm},
          {"piece_area_mm2", s.piece_area_mm2},
          {"tab_area_mm2", s.tab_area_mm2}};
}

// What make writes: --format's choices and the extensions -o is known by.
const std::vector<std::string> kOutputFormats = {"pdf", "svg", "png", "dxf"};

// The format named by --format, else by the output's extension ("-": PDF). Throws a usage error.
std::string output_format(const std::string& output, const std::string& format) {
  if (!format.empty()) return format;
  if (output == "-") return "pdf";
  std::string ext = std::filesystem::path(output).extension().string();
  for (char& c : ext)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  std::string known;  // ".pdf, .svg, .png or .dxf"
  for (std::size_t i = 0; i < kOutputFormats.size(); ++i) {
    if (ext == "." + kOutputFormats[i]) return kOutputFormats[i];
    known += (i == 0 ? "" : i + 1 == kOutputFormats.size() ? " or " : ", ") + ("." + kOutputFormats[i]);
  }
  throw Error("-o " + output + ": output must end in " + known + " (or give --format)", ExitCode::Usage);
}

// Sheets an earlier, longer run left under the same name would be taken for part of this one.
std::string remove_stale_files(const std::string& output, std::size_t sheet_count) {
  if (devices::resolve_output(output).kind != devices::OutputKind::File) return "";
  const auto removed = devices::remove_stale_sheet_files(output, sheet_count);
  if (removed.empty()) return "";
  std::string note = "removed " + std::to_string(removed.size()) +
                     " sheet file(s) of an earlier run: " + removed.front().string();
  if (removed.size() > 1) note += " ... " + removed.back().string();
  return note;
}

// DXF goes through its own writer (stroke-font labels, layers); everything else through Cairo.
// `font` is the label font, loaded before the pipeline ran (required for DXF).
std::vector<std::filesystem::path> write_sheets(const std::vector<Sheet>& sheets, const std::string& output,
                                                const devices::RenderOptions& render,
                                                const devices::StrokeFont* font) {
  if (render.format != "dxf") return devices::render_sheets(sheets, output, render);
  return devices::write_dxf_sheets(sheets, output, {font});
}

// The bundle's prints are for printing: 300 dpi, whatever --dpi says for previews.
constexpr double kBundleDpi = 300;

// The bundle's file stem: the mesh's name with only characters every cutting program and file system
// takes in a name.
std::string bundle_name(const std::string& mesh) {
  std::string name = std::filesystem::path(mesh).stem().string();
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') c = '_';
  return name.empty() ? "model" : name;
}

std::vector<std::filesystem::path> write_bundle(const std::vector<Sheet>& sheets, const Sheet* guide,
                                                const std::string& mesh, const std::string& dir,
                                                const devices::RenderOptions& render, double size_mm,
                                                const devices::StrokeFont* font) {
  devices::BundleOptions options;
  options.name = bundle_name(mesh);
  options.render = render;
  options.render.png_dpi = kBundleDpi;
  options.font = font;
  options.guide = guide;
  char scale[64];
  std::snprintf(scale, sizeof scale, "%.0f mm", size_mm);
  std::vector<std::string> notes = {"model: " + mesh + " at " + scale};
  // What only foldkit's own commands add, which the library's README text does not name.
  const bool marks = std::any_of(sheets.begin(), sheets.end(), [](const Sheet& s) {
    return std::any_of(s.paths.begin(), s.paths.end(),
                       [](const Path& p) { return p.role == PathRole::RegMark; });
  });
  notes.push_back(
      marks ? "registration marks: the sheets carry Silhouette marks; print each PDF at 100 % and cut it "
              "with `foldkit cut MESH --regmarks --device ID` and the same layout options (it applies "
              "the offset `foldkit calibrate` stored)"
            : "registration marks: none of foldkit's (make the bundle with --regmarks to cut a print "
              "with `foldkit cut --regmarks`)");
  const auto files = devices::bundle_files(sheets, options);
  if (std::any_of(files.begin(), files.end(),
                  [](const devices::BundleFile& f) { return f.too_large_for_print_then_cut; }))
    notes.push_back(
        "Print Then Cut: some parts are larger than its area (marked below); a smaller --size fits them");
  return devices::write_bundle(sheets, dir, options, notes);
}

// The parts in letter order: each part's letter, sheet (1-based) and faces, as 0-based indices of the
// input file's faces (a polygon is in one part: flat faces are never cut).
nlohmann::json parts_json(const unfold::Mesh& mesh, const unfold::Unfolding& u,
                          const layout::LayoutResult& r) {
  std::vector<std::vector<int>> faces = u.piece_faces();
  for (std::vector<int>& list : faces) {
    for (int& f : list)
      f = mesh.polygon_of(f);
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  std::vector<int> by_letter(faces.size());
  for (std::size_t p = 0; p < by_letter.size(); ++p)
    by_letter[p] = static_cast<int>(p);
  std::sort(by_letter.begin(), by_letter.end(), [&](int a, int b) {
    const std::string& la = r.piece_letters[a];
    const std::string& lb = r.piece_letters[b];
    return la.size() != lb.size() ? la.size() < lb.size() : la < lb;
  });
  nlohmann::json parts = nlohmann::json::array();
  for (int p : by_letter)
    parts.push_back({{"id", r.piece_letters[p]}, {"sheet", r.placements[p].sheet + 1}, {"faces", faces[p]}});
  return parts;
}

// The labels without a clear spot, where a maker looks for them: by sheet, then part letter.
nlohmann::json crowded_labels_json(const layout::LayoutResult& r) {
  std::vector<const layout::LayoutResult::CrowdedLabel*> labels;
  for (const auto& l : r.crowded_labels)
    labels.push_back(&l);
  const auto sheet = [&](const auto* l) { return r.placements[l->piece].sheet; };
  const auto letter = [&](const auto* l) { return r.piece_letters[l->piece]; };
  std::stable_sort(labels.begin(), labels.end(), [&](const auto* a, const auto* b) {
    const std::string la = letter(a), lb = letter(b);
    return std::make_tuple(sheet(a), la.size(), la) < std::make_tuple(sheet(b), lb.size(), lb);
  });
  nlohmann::json list = nlohmann::json::array();
  for (const auto* l : labels)
    list.push_back(
        {{"text", l->text}, {"seam_name", l->seam_name}, {"part", letter(l)}, {"sheet", sheet(l) + 1}});
  return list;
}

// One line when the faces are too small for clear labels, with the remedy computed for this model.
std::string label_remedy(const layout::LayoutResult& r, int faces) {
  if (!(r.label_room_factor > 1)) return "";
  const double f = r.label_room_factor;
  char line[256];
  std::snprintf(line, sizeof line,
                "%d of %d edge numbers find no spot clear of lines and labels at %.0f mm (faces too small): "
                "use --size %.0fmm, or --max-faces %d at this size (--json lists them)",
                r.labels_without_room, r.overall.labels, r.size_mm, std::ceil(r.size_mm * f / 10) * 10,
                std::max(4, static_cast<int>(faces / (f * f))));
  return line;
}

// What the parser cannot check alone; the output format. Throws a usage error.
std::string check_make_args(const MakeArgs& args) {
  if (args.output.empty() && args.bundle.empty())
    throw Error("make needs -o FILE or --bundle DIR (or both)", ExitCode::Usage);
  const std::string format = args.output.empty() ? "" : output_format(args.output, args.format);
  if (args.output == "-" && args.json)
    throw Error("--json and the output would both go to standard output (-): choose one", ExitCode::Usage);
  return format;
}

devices::RenderOptions render_options(const MakeArgs& args, const std::string& format,
                                      const layout::LayoutResult& r) {
  devices::RenderOptions render;
  render.format = format;
  render.png_dpi = args.dpi;
  render.mountain.dash_mm = fold_styles().at(args.mountain);
  render.valley.dash_mm = fold_styles().at(args.valley);
  const bool coloured =
      std::any_of(r.sheets.begin(), r.sheets.end(), [](const Sheet& s) { return !s.fills.empty(); });
  apply_colour_render_options(args.colour, coloured, render);
  return render;
}

// What the sheets were written to: every file, and how many of them are sheets (not the guide).
struct Written {
  std::vector<std::filesystem::path> files;
  std::size_t sheet_files = 0;
  int guide_pages = 0;
};

// The sheets to -o, with the guide as the PDF's last page or as NAME-guide.svg/.png beside them.
Written write_output(const MakeArgs& args, const std::vector<Sheet>& sheets,
                     const std::optional<Sheet>& guide, bool guide_beside_output,
                     const devices::RenderOptions& render, const devices::StrokeFont* font) {
  Written w;
  if (!guide || !guide_beside_output) {
    w.files = write_sheets(sheets, args.output, render, font);
    w.sheet_files = w.files.size();
    return w;
  }
  w.guide_pages = 1;
  if (render.format == "pdf") {
    // The guide is the last page, so that page k is sheet k as the labels' "p3" say.
    std::vector<Sheet> pages = sheets;
    pages.push_back(*guide);
    w.files = write_sheets(pages, args.output, render, font);
    w.sheet_files = w.files.size();
    return w;
  }
  std::filesystem::path guide_path = args.output;
  guide_path.replace_filename(guide_path.stem().string() + "-guide" + guide_path.extension().string());
  // One commit for sheets and guide: a run stopped while drawing the guide leaves no new sheets
  // beside an old guide.
  w.files = devices::render_sheets(sheets, args.output, render, {&*guide, guide_path});
  w.sheet_files = w.files.size() - 1;
  return w;
}

std::vector<std::string> make_notes(const PipelineRun& run, const std::string& stale) {
  const layout::LayoutResult& r = run.layout;
  std::vector<std::string> notes = run.unfolded.loaded.notes;
  notes.insert(notes.end(), run.unfolded.result.notes.begin(), run.unfolded.result.notes.end());
  notes.insert(notes.end(), r.notes.begin(), r.notes.end());
  if (const std::string remedy = label_remedy(r, run.unfolded.result.unfolding.num_faces()); !remedy.empty())
    notes.push_back(remedy);
  if (!stale.empty()) notes.push_back(stale);
  return notes;
}

nlohmann::json make_json(const MakeArgs& args, const PipelineRun& run,
                         const layout::LayoutOptions& layout_options, const Written& w,
                         const std::vector<std::string>& notes) {
  const layout::LayoutResult& r = run.layout;
  const unfold::Unfolding& u = run.unfolded.result.unfolding;
  nlohmann::json sheets = nlohmann::json::array();
  for (const layout::SheetStats& s : r.sheet_stats)
    sheets.push_back(stats_json(s));
  nlohmann::json outputs = nlohmann::json::array();
  for (const auto& f : w.files)
    outputs.push_back(f.string());
  nlohmann::json assembly = nlohmann::json::array();
  for (const layout::AssemblyStep& step : r.assembly)
    assembly.push_back({{"step", step.step},
                        {"seam", step.number},
                        {"seam_name", step.name},
                        {"fold_angle_rad", step.fold_angle_rad}});
  nlohmann::json j{{"file", args.mesh},
                   {"face_count", u.num_faces()},
                   {"piece_count", u.piece_count},
                   {"seam_count", u.seam_count()},
                   {"method", run.unfolded.result.method},
                   {"size_mm", r.size_mm},
                   {"scale_mm_per_unit", r.scale_mm_per_unit},
                   {"paper_mm", {layout_options.paper_mm.x, layout_options.paper_mm.y}},
                   {"spacing_mm", r.spacing_mm},
                   {"sheet_count", r.sheets.size()},
                   {"sheets", sheets},
                   {"overall", stats_json(r.overall)},
                   {"unfold_s", run.unfolded.result.seconds},
                   {"layout_s", run.layout_seconds},
                   {"outputs", outputs},
                   {"notes", notes},
                   {"parts", parts_json(run.unfolded.loaded.mesh, u, r)},
                   {"labels_crossing_lines_count", r.label_audit.crossing_lines},
                   {"guide_page_count", w.guide_pages},
                   {"labels_touching_count", r.label_audit.touching},
                   {"labels_turned_count", r.label_audit.turned},
                   {"letters_crossing_lines_count", r.label_audit.letters_crossing_lines},
                   {"labels_without_room_count", r.labels_without_room},
                   {"crowded_labels", crowded_labels_json(r)},
                   {"dropped_tab_seams", r.dropped_tab_seams}};
  if (!r.assembly.empty()) j["assembly_steps"] = assembly;
  return j;
}

// The notes on stderr and one summary line: on stdout, or on stderr when the sheets are on stdout.
void print_make_summary(const MakeArgs& args, const PipelineRun& run, const Written& w,
                        const std::vector<std::string>& notes) {
  const layout::LayoutResult& r = run.layout;
  const unfold::Unfolding& u = run.unfolded.result.unfolding;
  for (const auto& n : notes)
    std::cerr << "note: " << n << "\n";
  // With only --bundle, its README.txt (which lists the rest) stands for the files written.
  const std::string shown =
      args.output.empty() ? (std::filesystem::path(args.bundle) / "README.txt").string() : args.output;
  // With -o - the sheets are on standard output: the summary must not be mixed into them.
  std::fprintf(
      args.output == "-" ? stderr : stdout,
      "%s: %d faces -> %d piece%s (%s) -> %zu sheet%s at %.0f mm, coverage %.0f%%, %d tabs (%d dropped) -> "
      "%s%s\n",
      args.mesh.c_str(), u.num_faces(), u.piece_count, u.piece_count == 1 ? "" : "s",
      run.unfolded.result.method.c_str(), r.sheets.size(), r.sheets.size() == 1 ? "" : "s", r.size_mm,
      100 * r.overall.coverage, r.overall.tabs, r.overall.dropped_tabs, shown.c_str(),
      w.files.size() > 1 ? (" (+" + std::to_string(w.files.size() - 1) + " more)").c_str() : "");
}

}  // namespace

void run_make(MakeArgs args) {
  const std::string format = check_make_args(args);
  const std::vector<std::filesystem::path> inputs{args.mesh, args.unfold.cut_file, args.unfold.keep_file};
  refuse_output_over_inputs("-o", args.output, inputs);
  finish_unfold_options(args.unfold);
  layout::LayoutOptions layout_options = to_layout_options(args.layout);
  layout_options.model_name = std::filesystem::path(args.mesh).stem().string();
  if (format == "png") check_png_raster(layout_options.paper_mm, args.dpi);  // before minutes of work
  if (!args.bundle.empty())
    devices::check_bundle_sheet_size(layout_options.paper_mm, kBundleDpi, args.bundle);
  // DXF labels are pen strokes: a missing font is found out before the pipeline, not after it.
  std::optional<devices::StrokeFont> font;
  if (format == "dxf" || !args.bundle.empty()) font = load_label_font();
  const devices::StrokeFont* label_font = font ? &*font : nullptr;
  ProgressLine line(!args.quiet);
  const PipelineRun run = load_unfold_layout(args.mesh, args.unfold, layout_options, line,
                                             to_fill_options(args.colour), choose_options_of(args.layout));
  const layout::LayoutResult& r = run.layout;
  if (format != "pdf") {
    for (std::size_t i = 1; i < r.sheets.size(); ++i)
      refuse_output_over_inputs("-o", sheet_output_path(args.output, i), inputs);
  }
  const devices::RenderOptions render = render_options(args, format, r);
  line.update("rendering " + std::to_string(r.sheets.size()) + " sheets");
  const bool pdf = format == "pdf", picture = format == "svg" || format == "png";
  // A guide beside SVG/PNG sheets is one more file, which standard output cannot hold.
  const bool guide_beside_output = !args.output.empty() && (pdf || (picture && args.output != "-"));
  std::optional<Sheet> guide;
  if (!args.no_guide && (guide_beside_output || !args.bundle.empty())) {
    line.update("drawing the assembly guide");
    layout::GuideOptions guide_options;
    guide_options.paper_mm = layout_options.paper_mm;
    guide_options.margin_mm = layout_options.margin_mm;
    guide_options.model_name = layout_options.model_name;
    guide_options.up = args.guide_up == "y"   ? layout::UpAxis::Y
                       : args.guide_up == "z" ? layout::UpAxis::Z
                                              : layout::UpAxis::Auto;
    guide = layout::guide_sheet(run.unfolded.loaded.mesh, run.unfolded.result.unfolding, r, guide_options);
  }
  Written w;
  if (!args.output.empty()) w = write_output(args, r.sheets, guide, guide_beside_output, render, label_font);
  if (!args.bundle.empty()) {
    line.update("writing the bundle");
    const auto bundled = write_bundle(r.sheets, guide ? &*guide : nullptr, args.mesh, args.bundle, render,
                                      r.size_mm, label_font);
    w.files.insert(w.files.end(), bundled.begin(), bundled.end());
  }
  line.clear();
  const std::string stale =
      format == "pdf" || format.empty() ? "" : remove_stale_files(args.output, w.sheet_files);
  const std::vector<std::string> notes = make_notes(run, stale);
  if (args.json)
    std::cout << versioned(make_json(args, run, layout_options, w, notes)).dump(2) << "\n";
  else
    print_make_summary(args, run, w, notes);
}

void setup_make(CLI::App& app) {
  auto args = std::make_shared<MakeArgs>();
  CLI::App* cmd = app.add_subcommand(
      "make", "Unfold a mesh and lay it out on sheets: PDF, SVG, PNG, DXF or a hand-off bundle");
  cmd->add_option("mesh", args->mesh, "Mesh file (.obj, .off, .stl, .ply, .gltf, .glb)")->required();
  cmd->add_option("-o,--output", args->output,
                  "Output file: .pdf (one page per sheet), .svg, .png or .dxf (one file per sheet); - for "
                  "standard output");
  cmd->add_option("--format", args->format,
                  "Output format when -o has no such extension (default for -: pdf)")
      ->check(CLI::IsMember(kOutputFormats));
  cmd->add_option(
      "--bundle", args->bundle,
      "Also (or instead of -o) write a hand-off folder for Silhouette Studio, Cricut Design Space "
      "and CanvasWorkspace: per sheet PNG (300 dpi), PDF, DXF and SVG, part PNGs, the guide, README.txt");
  cmd->add_option("--dpi", args->dpi, "Resolution of PNG previews")
      ->check(number_in(10, 2400, "dpi"))
      ->capture_default_str();
  const std::vector<std::string> styles = choice_names(fold_styles());
  auto style_names = CLI::IsMember(styles);
  cmd->add_option("--mountain", args->mountain, "Mountain fold style: " + joined(styles))
      ->check(style_names)
      ->capture_default_str();
  cmd->add_option("--valley", args->valley, "Valley fold style: " + joined(styles))
      ->check(style_names)
      ->capture_default_str();
  cmd->add_flag("--json", args->json, "Print a JSON report on stdout");
  cmd->add_flag("-q,--quiet", args->quiet, "No progress line");
  cmd->add_flag("--no-guide", args->no_guide,
                "No assembly guide (a last PDF page, NAME-guide.svg/.png beside SVG and PNG sheets, "
                "NAME-guide.pdf in a bundle)");
  cmd->add_option("--guide-up", args->guide_up,
                  "Which axis is up in the guide's views: y (OBJ and glTF convention), z (CAD, STL, most "
                  "low-poly models) or auto (z where the model stands on a flat base at its lowest z)")
      ->check(CLI::IsMember({"auto", "y", "z"}))
      ->capture_default_str();
  add_layout_options(*cmd, args->layout);
  add_colour_options(*cmd, args->colour);
  add_unfold_options(*cmd, args->unfold);
  cmd->callback([args] { run_make(*args); });
}

}  // namespace foldkit::cli
