#pragma once
// `foldkit bench`: the unfolding table over a corpus (one child process per run), or with --layout the
// layout table (bench_layout.hpp).
#include <cstdint>
#include <string>
#include <vector>

namespace foldkit::cli {

/// What `foldkit bench` was asked; the parser fills it, run_bench does the work.
struct BenchArgs {
  int max_faces = 5000;
  bool max_faces_given =
      false;  ///< --max-faces was on the command line (the layout table's default is lower)
  int min_faces = 0;
  std::string methods = "mst,search,ga";
  double time_limit_s = 120;
  bool time_limit_given = false;  ///< --time-limit was on the command line
  std::uint64_t seed = 1;
  int threads = 0;
  bool json_out = false;
  std::string corpus;
  std::string reference;
  std::string filter;
  bool layout = false;           ///< --layout: the layout table instead
  std::vector<double> sizes_mm;  ///< with --layout; empty: its default
  bool nest2d = false;           ///< with --layout: pack with libnest2d
  std::string before;            ///< with --layout: the report before a change ("none": none; empty: default)
  // Child mode: unfold one mesh with one method and print one JSON line.
  std::string one;
  std::string method;
};

/// Runs the benchmark asked for and prints its table (or JSON) on stdout. The unfolding table re-runs this
/// executable (/proc/self/exe) once per mesh and method. Throws Error (usage) or InputError.
void run_bench(const BenchArgs& args);

}  // namespace foldkit::cli
