#include "bench_before.hpp"

#include <cmath>
#include <fstream>
#include <iterator>

#include <nlohmann/json.hpp>

#include "foldkit/error.hpp"
#include "json_report.hpp"

namespace foldkit::cli {
namespace {
namespace fs = std::filesystem;
using nlohmann::json;

std::string read_report_text(const fs::path& file) {
  std::error_code ec;
  if (!fs::exists(file, ec)) throw InputError(file.string(), "no such benchmark report");
  if (!fs::is_regular_file(file, ec))
    throw InputError(file.string(), "not a file: a benchmark report is one");
  const std::uintmax_t bytes = fs::file_size(file, ec);
  if (ec) throw InputError(file.string(), "cannot be read: " + ec.message());
  if (bytes > kMostBeforeReportBytes)
    throw InputError(file.string(), "too large for a benchmark report (" + std::to_string(bytes) + " bytes)");
  std::ifstream in(file, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in && !in.eof()) throw InputError(file.string(), "cannot be read");
  return text;
}

// The refusal of row `index` (0-based) of the report: "<file>: row <index + 1><problem>".
InputError row_error(const fs::path& file, std::size_t index, const std::string& problem) {
  return InputError(file.string(), "row " + std::to_string(index + 1) + problem);
}

// A figure of row `index`: a finite number, at least 0.
double figure(const json& row, const char* key, std::size_t index, const fs::path& file) {
  const auto it = row.find(key);
  if (it == row.end()) throw row_error(file, index, std::string(" has no figure '") + key + "'");
  if (!it->is_number() || !std::isfinite(it->get<double>()) || it->get<double>() < 0)
    throw row_error(file, index, std::string(": '") + key + "' is not a number of at least 0");
  return it->get<double>();
}

long count(const json& row, const char* key, std::size_t index, const fs::path& file) {
  const double v = figure(row, key, index, file);
  constexpr double kMostCount = 1e9;  // far above any sheet, part or seam count; fits the table's ints
  if (v != std::floor(v) || v > kMostCount)
    throw row_error(file, index, std::string(": '") + key + "' is not a count");
  return static_cast<long>(v);
}

BeforeRun run_of(const json& row, std::size_t index, const fs::path& file) {
  BeforeRun r;
  const auto mesh = row.find("mesh");
  if (mesh == row.end() || !mesh->is_string()) throw row_error(file, index, " names no mesh");
  r.mesh = mesh->get<std::string>();
  r.size_mm = figure(row, "size_mm", index, file);
  r.sheets = count(row, "sheet_count", index, file);
  r.area_bound = count(row, "area_bound_sheet_count", index, file);
  r.parts = count(row, "part_count", index, file);
  r.seams = count(row, "seam_count", index, file);
  r.seams_without_tab = count(row, "seams_without_tab_count", index, file);
  r.coverage = figure(row, "coverage", index, file);
  r.wall_s = figure(row, "wall_s", index, file);
  return r;
}

}  // namespace

const BeforeRun* BeforeRuns::find(const std::string& mesh, double size_mm) const {
  for (const BeforeRun& r : runs)
    if (r.mesh == mesh && r.size_mm == size_mm) return &r;
  return nullptr;
}

BeforeRuns read_before_runs(const fs::path& file) {
  const json report = json::parse(read_report_text(file), nullptr, /*allow_exceptions=*/false);
  if (report.is_discarded() || !report.is_object())
    throw InputError(file.string(), "not a JSON report of bench --layout --json");
  const auto version = report.find("schema_version");
  if (version == report.end() || *version != kJsonSchemaVersion)
    throw InputError(file.string(), "not a report of this foldkit's scheme (schema_version " +
                                        std::to_string(kJsonSchemaVersion) + " expected)");
  const auto rows = report.find("rows");
  if (rows == report.end() || !rows->is_array())
    throw InputError(file.string(), "no rows: not a report of bench --layout --json");
  BeforeRuns out;
  out.file = file.string();
  for (std::size_t k = 0; k < rows->size(); ++k) {
    const json& row = (*rows)[k];
    if (!row.is_object()) throw row_error(file, k, " is not an object");
    if (row.contains("error")) continue;  // a run that failed then has no figures to compare
    out.runs.push_back(run_of(row, k, file));
  }
  return out;
}

}  // namespace foldkit::cli
