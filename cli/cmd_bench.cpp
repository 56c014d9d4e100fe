// `foldkit bench`: one table of unfolding results over a corpus of meshes (default ../shared/meshes):
// pieces, seconds and peak memory per method, every result checked with check_unfolding, beside the
// seed paper's Table 1 and Blender's paper-model export where the reference CSVs are present.
// Each (mesh, method) runs in a fresh child process (this executable re-run with --one) so that the
// peak memory read from wait4's ru_maxrss is that run's alone.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench_layout.hpp"
#include "choices.hpp"
#include "cmd_bench.hpp"
#include "commands.hpp"
#include "foldkit/error.hpp"
#include "foldkit/unfold/mesh_io.hpp"
#include "foldkit/unfold/unfold.hpp"
#include "foldkit/unfold/unfolding.hpp"
#include "json_report.hpp"
#include "length_option.hpp"
#include "median.hpp"
#include "unfold_options.hpp"

namespace foldkit::cli {
namespace {
namespace fs = std::filesystem;
using nlohmann::json;

std::optional<unfold::Method> parse_method(const std::string& m) {
  for (const auto& [name, method] : unfold_methods())
    if (m == name) return method;
  return std::nullopt;
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string part; std::getline(in, part, sep);)
    if (!part.empty()) out.push_back(part);
  return out;
}

// The child: load, unfold, check; everything the parent needs on one JSON line.
void run_one(const BenchArgs& a) {
  auto method = parse_method(a.method);
  if (!method) throw Error("unknown method '" + a.method + "'", ExitCode::Usage);
  json j{{"mesh", a.one}, {"method", a.method}};
  try {
    const unfold::LoadedMesh loaded = unfold::load_mesh(a.one);
    unfold::UnfoldOptions opt;
    opt.method = *method;
    opt.seed = a.seed;
    opt.time_limit_s = a.time_limit_s;
    opt.threads = a.threads;
    const unfold::UnfoldResult r = unfold::unfold_mesh(loaded.mesh, opt);
    const auto problems = unfold::check_unfolding(loaded.mesh, r.unfolding);
    j["face_count"] = loaded.mesh.num_faces();
    j["piece_count"] = r.unfolding.piece_count;
    j["unfold_s"] = r.seconds;
    j["produced_by"] = r.method;
    j["valid"] = problems.empty();
    if (!problems.empty()) j["problem"] = problems.front();
  } catch (const std::exception& e) {
    j["error"] = e.what();
  }
  std::cout << j.dump() << std::endl;
}

struct ChildResult {
  json row;
  double peak_mb = 0;
};

ChildResult run_child(const BenchArgs& a, const fs::path& mesh, const std::string& method) {
  int fd[2];
  if (pipe(fd) != 0) throw Error("cannot create a pipe for a benchmark run", ExitCode::Failure);
  std::vector<std::string> argv_s{"foldkit",      "bench",
                                  "--one",        mesh.string(),
                                  "--method",     method,
                                  "--time-limit", std::to_string(a.time_limit_s),
                                  "--seed",       std::to_string(a.seed),
                                  "--threads",    std::to_string(a.threads)};
  std::vector<char*> argv;
  for (auto& s : argv_s)
    argv.push_back(s.data());
  argv.push_back(nullptr);
  pid_t pid = fork();
  if (pid < 0) throw Error("cannot start a benchmark run", ExitCode::Failure);
  if (pid == 0) {
    dup2(fd[1], STDOUT_FILENO);
    close(fd[0]);
    close(fd[1]);
    execv("/proc/self/exe", argv.data());
    _exit(127);
  }
  close(fd[1]);
  std::string out;
  char buf[4096];
  for (ssize_t n; (n = read(fd[0], buf, sizeof buf)) > 0;)
    out.append(buf, static_cast<std::size_t>(n));
  close(fd[0]);
  int status = 0;
  rusage ru{};
  wait4(pid, &status, 0, &ru);
  ChildResult r;
  r.peak_mb = static_cast<double>(ru.ru_maxrss) / 1024.0;  // kilobytes on Linux
  try {
    r.row = json::parse(out.substr(0, out.find('\n')));
  } catch (const std::exception&) {
    r.row =
        json{{"error", WIFSIGNALED(status) ? "killed by signal " + std::to_string(WTERMSIG(status))
                                           : "no result (exit " + std::to_string(WEXITSTATUS(status)) + ")"}};
  }
  return r;
}

// Reference figures: CSV with '#' comment lines and a header row.
std::vector<std::map<std::string, std::string>> read_csv(const fs::path& p) {
  std::vector<std::map<std::string, std::string>> rows;
  std::ifstream in(p);
  std::vector<std::string> header;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> cells;
    std::stringstream s(line);
    for (std::string c; std::getline(s, c, ',');)
      cells.push_back(c);
    if (!line.empty() && line.back() == ',') cells.push_back("");
    if (header.empty()) {
      header = cells;
      continue;
    }
    std::map<std::string, std::string> row;
    for (std::size_t i = 0; i < header.size() && i < cells.size(); ++i)
      row[header[i]] = cells[i];
    rows.push_back(std::move(row));
  }
  return rows;
}

// Model name of a corpus file: "bunny_1000.obj" -> "bunny"; "seedbunny_348.obj" -> "bunny".
std::string model_of(const fs::path& p) {
  std::string stem = p.stem().string();
  auto us = stem.rfind('_');
  std::string name = us == std::string::npos ? stem : stem.substr(0, us);
  if (name.rfind("seed", 0) == 0) name = name.substr(4);
  return name;
}

std::string fmt(const char* f, double v) {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

using CsvRows = std::vector<std::map<std::string, std::string>>;

// The corpus's meshes within the face bounds and --filter, with their face counts, fewest faces first
// (loaded here once; the runs load them again in their own process).
std::vector<std::pair<fs::path, int>> bench_meshes(const BenchArgs& a, const fs::path& corpus) {
  std::vector<std::pair<fs::path, int>> meshes;
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(corpus)) {
    static const std::regex ext(R"(\.(obj|off|stl|ply)$)", std::regex::icase);
    if (entry.is_regular_file() && std::regex_search(entry.path().string(), ext))
      files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  for (const auto& f : files) {
    if (!a.filter.empty() && f.filename().string().find(a.filter) == std::string::npos) continue;
    try {
      int faces = unfold::load_mesh(f).mesh.num_faces();
      if (faces <= a.max_faces && faces >= a.min_faces) meshes.push_back({f, faces});
    } catch (const Error&) {
      // Not a usable mesh: the bench measures unfolding, the loader has its own tests.
    }
  }
  std::stable_sort(meshes.begin(), meshes.end(), [](auto& x, auto& y) { return x.second < y.second; });
  return meshes;
}

std::string table_head(const std::vector<std::string>& methods) {
  std::ostringstream head;
  char b[256];
  std::snprintf(b, sizeof b, "%-24s %6s", "mesh", "faces");
  head << b;
  for (const auto& m : methods) {
    std::snprintf(b, sizeof b, " | %-6s %4s %8s %6s", m.c_str(), "pcs", "s", "MB");
    head << b;
  }
  head << " | check | blender pcs     s | seed Table 1 (65/70/75%)";
  return head.str();
}

// Blender's figures for `path` into row["blender"]; the table cell ("" when it has none).
std::string blender_cell(const fs::path& path, const CsvRows& blender_rows, json& row) {
  const std::string rel = "meshes/" + path.filename().string();
  std::string blender = "";
  char b[256];
  for (const auto& br : blender_rows) {
    auto it = br.find("mesh");
    if (it == br.end() || it->second != rel) continue;
    if (br.at("pieces").empty()) {
      // The add-on refused the mesh; say so rather than leave a blank.
      row["blender"] = {{"error", br.count("error") ? br.at("error") : "refused"}};
      std::snprintf(b, sizeof b, "%17s", "refused");
    } else {
      row["blender"] = {{"piece_count", std::stoi(br.at("pieces"))},
                        {"unfold_s", std::stod(br.at("seconds"))}};
      std::snprintf(b, sizeof b, "%11s %5s", br.at("pieces").c_str(), br.at("seconds").c_str());
    }
    blender = b;
  }
  return blender;
}

// The seed paper's Table 1 figures for a model of about `faces` faces into row["seed_table1"]; the cells.
std::string seed_cells(const fs::path& path, int faces, const CsvRows& seed_rows, json& row) {
  std::ostringstream line;
  for (const auto& sr : seed_rows) {
    int sf = std::stoi(sr.at("faces"));
    if (sr.at("model") != model_of(path) || std::abs(sf - faces) > 0.1 * sf) continue;
    row["seed_table1"] = {
        {"model", sr.at("model")},
        {"face_count", sf},
        {"piece_counts", {std::stoi(sr.at("n65")), std::stoi(sr.at("n70")), std::stoi(sr.at("n75"))}},
        {"unfold_s", {std::stod(sr.at("t65")), std::stod(sr.at("t70")), std::stod(sr.at("t75"))}},
        {"mst_piece_count", std::stoi(sr.at("mst_n"))}};
    line << " | " << sr.at("model") << " " << sf << ": " << sr.at("n65") << "/" << sr.at("n70") << "/"
         << sr.at("n75") << " pcs in " << sr.at("t65") << "/" << sr.at("t70") << "/" << sr.at("t75") << " s";
  }
  return line.str();
}

// One mesh: every method in its own child process, then the reference figures. Fills `row`, returns the
// table line.
std::string bench_mesh(const BenchArgs& a, const fs::path& path, int faces,
                       const std::vector<std::string>& methods, const CsvRows& seed_rows,
                       const CsvRows& blender_rows, json& row) {
  row = json{{"mesh", path.filename().string()}, {"face_count", faces}};
  bool all_valid = true;
  std::ostringstream line;
  char b[256];
  std::snprintf(b, sizeof b, "%-24s %6d", path.filename().string().c_str(), faces);
  line << b;
  for (const auto& m : methods) {
    ChildResult c = run_child(a, path, m);
    json r = c.row;
    r["peak_mb"] = c.peak_mb;
    bool ok = !r.contains("error") && r.value("valid", false);
    all_valid &= ok;
    row["results"][m] = r;
    if (r.contains("error")) {
      std::snprintf(b, sizeof b, " | %-6s %4s %8s %6.0f", m.c_str(), "err", "-", c.peak_mb);
    } else {
      std::snprintf(b, sizeof b, " | %-6s %4d %8.3f %6.1f", m.c_str(), r.value("piece_count", -1),
                    r.value("unfold_s", 0.0), c.peak_mb);
    }
    line << b;
  }
  row["valid"] = all_valid;
  line << " | " << (all_valid ? " ok  " : "FAIL ");
  const std::string blender = blender_cell(path, blender_rows, row);
  line << " | " << (blender.empty() ? std::string(17, ' ') : blender);
  line << seed_cells(path, faces, seed_rows, row);
  return line.str();
}

// Per method: one-piece share, medians by size band, peak memory, validity.
json bench_summary(const std::vector<std::string>& methods, const json& rows) {
  json summary;
  for (const auto& m : methods) {
    int one = 0, n = 0, valid = 0;
    double peak = 0;
    std::map<std::string, std::vector<double>> bands;
    for (const auto& row : rows) {
      const json& r = row["results"][m];
      ++n;
      if (r.contains("error")) continue;
      valid += r.value("valid", false) ? 1 : 0;
      one += r.value("piece_count", 0) == 1 ? 1 : 0;
      peak = std::max(peak, r.value("peak_mb", 0.0));
      int f = row["face_count"];
      std::string band = f < 300     ? "<300"
                         : f <= 550  ? "300-550"
                         : f <= 1100 ? "~1000"
                         : f <= 2200 ? "~2000"
                                     : "~5000";
      bands[band].push_back(r.value("unfold_s", 0.0));
    }
    json s{{"mesh_count", n}, {"one_piece_count", one}, {"valid_count", valid}, {"peak_mb", peak}};
    for (auto& [band, v] : bands)
      s["median_unfold_s"][band] = median(v);
    summary[m] = s;
  }
  return summary;
}

void print_summary(const std::vector<std::string>& methods, const json& summary) {
  for (const auto& m : methods) {
    const json& s = summary[m];
    std::cout << m << ": one piece " << s["one_piece_count"].get<int>() << "/" << s["mesh_count"].get<int>()
              << ", valid (check_unfolding) " << s["valid_count"].get<int>() << "/"
              << s["mesh_count"].get<int>() << ", peak " << fmt("%.1f", s["peak_mb"].get<double>())
              << " MB, median s:";
    if (s.contains("median_unfold_s"))
      for (auto& [band, v] : s["median_unfold_s"].items())
        std::cout << " " << band << " " << fmt("%.3f", v.get<double>());
    std::cout << "\n";
  }
}

// The unfolding table: rows as they finish (or JSON at the end), then the summary.
void run_unfold_bench(const BenchArgs& a, const fs::path& corpus) {
  fs::path reference = a.reference.empty() ? corpus.parent_path() / "reference" : fs::path(a.reference);
  std::vector<std::string> methods = split(a.methods, ',');
  for (const auto& m : methods)
    if (!parse_method(m))
      throw Error("--methods: unknown method '" + m + "' (" + joined(choice_names(unfold_methods())) + ")",
                  ExitCode::Usage);
  const auto meshes = bench_meshes(a, corpus);
  const CsvRows seed_rows = read_csv(reference / "seed_table1.csv");
  const CsvRows blender_rows = read_csv(reference / "blender_paper_model.csv");
  const std::string head = table_head(methods);
  if (!a.json_out)
    std::cout << "foldkit bench: " << corpus.string() << ", up to " << a.max_faces << " faces, time limit "
              << a.time_limit_s << " s, seed " << a.seed << ", one child process per run\n"
              << head << "\n"
              << std::string(head.size(), '-') << std::endl;
  json rows = json::array();
  for (const auto& [path, faces] : meshes) {
    json row;
    const std::string line = bench_mesh(a, path, faces, methods, seed_rows, blender_rows, row);
    rows.push_back(row);
    if (!a.json_out) std::cout << line << std::endl;
  }
  const json summary = bench_summary(methods, rows);
  if (a.json_out) {
    std::cout << versioned({{"corpus", corpus.string()},
                            {"max_face_count", a.max_faces},
                            {"time_limit_s", a.time_limit_s},
                            {"seed", a.seed},
                            {"rows", rows},
                            {"summary", summary}})
                     .dump(2)
              << "\n";
    return;
  }
  std::cout << std::string(head.size(), '-') << "\n";
  print_summary(methods, summary);
}

// The corpus named on the command line, else ../shared/meshes of a developer checkout run from the
// project folder; a usage error saying what to pass when there is neither.
fs::path corpus_folder(const std::string& given) {
  const fs::path corpus = given.empty() ? fs::path("../shared/meshes") : fs::path(given);
  if (fs::is_directory(corpus)) return corpus;
  if (given.empty())
    throw Error(
        "bench needs a folder of meshes (.obj, .off, .stl, .ply): foldkit bench /path/to/meshes "
        "(no ../shared/meshes here)",
        ExitCode::Usage);
  throw InputError(corpus.string(), "no such folder of meshes");
}

// The report of the runs before a change: the one given, none for "none", else the figures measured
// before the layout's issue 11 where a developer checkout has them (bench/layout-before.json).
std::string before_report(const std::string& given) {
  if (given == "none") return {};
  if (!given.empty()) return given;
  const fs::path checked_in = "bench/layout-before.json";
  return fs::is_regular_file(checked_in) ? checked_in.string() : std::string();
}

}  // namespace

void run_bench(const BenchArgs& a) {
  if (!a.one.empty()) return run_one(a);
  const fs::path corpus = corpus_folder(a.corpus);
  if (!a.layout) return run_unfold_bench(a, corpus);
  LayoutBenchArgs l;
  l.corpus = corpus.string();
  l.min_faces = a.min_faces;
  if (a.max_faces_given) l.max_faces = a.max_faces;
  l.filter = a.filter;
  if (a.time_limit_given) l.time_limit_s = a.time_limit_s;
  l.json_out = a.json_out;
  l.nest2d = a.nest2d;
  l.before = before_report(a.before);
  if (!a.sizes_mm.empty()) l.sizes_mm = a.sizes_mm;
  run_layout_bench(l);
}

void setup_bench(CLI::App& app) {
  auto a = std::make_shared<BenchArgs>();
  CLI::App* cmd = app.add_subcommand("bench", "Benchmark the unfolding methods over a folder of meshes");
  cmd->add_option("corpus,--corpus", a->corpus,
                  "Folder of meshes to benchmark (default ../shared/meshes when run from a developer "
                  "checkout)");
  cmd->add_option("--max-faces", a->max_faces, "Only meshes with at most N faces (default 5000)")
      ->check(number_in(0, 100e6, "faces"));
  cmd->add_option("--min-faces", a->min_faces, "Only meshes with at least N faces")
      ->check(number_in(0, 100e6, "faces"));
  cmd->add_option("--methods", a->methods, "Comma-separated methods to compare (default mst,search,ga)");
  cmd->add_option("--time-limit", a->time_limit_s, "Seconds each run may take (default 120)")
      ->check(number_in(0.01, 1e6, "s"));
  cmd->add_option("--seed", a->seed, "Random seed of every run (default 1)");
  cmd->add_option("--threads", a->threads, "Worker threads per run (0: all cores)")
      ->check(number_in(0, 256, "threads"));
  cmd->add_flag("--json", a->json_out, "Print the rows and the summary as JSON");
  cmd->add_option("--reference", a->reference,
                  "Folder of the reference CSVs (default CORPUS/../reference; none: no reference columns)");
  cmd->add_option("--filter", a->filter, "Only meshes whose file name contains this text");
  cmd->add_flag(
      "--layout", a->layout,
      "Benchmark the layout instead: sheets, area bound, parts, coverage and seams without a tab per "
      "mesh at 150 and 250 mm on A4 (meshes up to --max-faces, lowpoly/ included)");
  cmd->add_option("--sizes", a->sizes_mm, "With --layout: model sizes in mm (default 150 250)")
      ->delimiter(',')
      ->check(number_in(1, 10000, "mm"));
  cmd->add_flag("--nest2d", a->nest2d, "With --layout: pack with libnest2d instead of foldkit's packer");
  cmd->add_option("--before", a->before,
                  "With --layout: a report of bench --layout --json measured before a change, printed beside "
                  "the runs and totalled over the runs both share (default bench/layout-before.json when run "
                  "from a developer checkout; none: no such columns)");
  // Internal: what each child process runs.
  cmd->add_option("--one", a->one)->group("");
  cmd->add_option("--method", a->method)->group("");
  cmd->callback([a, cmd] {
    a->max_faces_given = cmd->count("--max-faces") > 0;
    a->time_limit_given = cmd->count("--time-limit") > 0;
    run_bench(*a);
  });
}

}  // namespace foldkit::cli
