#pragma once
// The figures a layout benchmark measured before a change, read back from a `bench --layout --json`
// report, so that the table prints them beside the runs measured now and totals both over the runs they
// share. The report is input like any other: it is checked, and refused whole with one line naming the
// file where it is not such a report.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace foldkit::cli {

/// One run of the earlier benchmark (the keys of a `bench --layout --json` row).
struct BeforeRun {
  std::string mesh;  ///< as the bench names it ("bob_128.obj", "lowpoly/barn.obj")
  double size_mm = 0;
  long sheets = 0, area_bound = 0;
  long parts = 0, seams = 0, seams_without_tab = 0;
  double coverage = 0;
  double wall_s = 0;
};

struct BeforeRuns {
  std::string file;  ///< where they were read from, as given
  std::vector<BeforeRun> runs;
  /// The run of `mesh` at `size_mm`, or nullptr.
  const BeforeRun* find(const std::string& mesh, double size_mm) const;
};

/// The largest report read: far above the ~100 KB a full benchmark writes, and small enough that the
/// parsed tree of the worst such text (nested arrays) stays near 150 MB.
inline constexpr std::uintmax_t kMostBeforeReportBytes = 4u << 20;

/// Reads the runs of a `bench --layout --json` report. Rows that record an error are skipped. Throws
/// InputError when the file cannot be read, is larger than kMostBeforeReportBytes, is not JSON, has
/// another schema version, or a row lacks a figure or holds one that is negative or not a number.
BeforeRuns read_before_runs(const std::filesystem::path& file);

}  // namespace foldkit::cli
