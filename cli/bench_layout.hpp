#pragma once
// `foldkit bench --layout`: per mesh and size, what a builder gets on paper (sheets against the area
// lower bound, parts, coverage, seams without a tab, seconds) and the totals the layout targets are
// judged by.
#include <string>
#include <vector>

namespace foldkit::cli {

struct LayoutBenchArgs {
  std::string corpus;  ///< folder of meshes; its lowpoly/ subfolder is included
  std::vector<double> sizes_mm{150, 250};
  std::string paper = "A4";
  int min_faces = 0, max_faces = 1000;
  std::string filter;
  double time_limit_s = 60;  ///< for the unfolding of each mesh
  bool json_out = false;
  bool nest2d = false;  ///< pack with libnest2d instead of the raster packer (the comparison)
  /// A `bench --layout --json` report measured before a change: its figures are printed beside the
  /// runs measured now, and both totalled over the runs they share. Empty: none.
  std::string before;
};

/// Runs the layout benchmark and prints the table (or JSON) on stdout. Throws InputError when the corpus
/// directory is missing or the report of the runs before is not one (before any run).
void run_layout_bench(const LayoutBenchArgs& args);

}  // namespace foldkit::cli
