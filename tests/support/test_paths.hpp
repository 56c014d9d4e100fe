#pragma once
// Where tests find their inputs: the project's own examples and, when present, the shared corpus.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace foldkit::test {

/// Root of the source tree (examples/, profiles/, tests/data/).
std::filesystem::path source_dir();
/// The project's built-in device and media profiles (profiles/ of the source tree).
std::filesystem::path profiles_dir();
/// The Hershey font "futural" of pen and DXF labels where this machine has it (hershey-fonts-data), else
/// the first place it was looked for (so loading it fails with that path).
std::filesystem::path stroke_font_path();
/// The project's bundled example mesh `name` (e.g. "spot_350.obj") under examples/.
std::filesystem::path example_mesh(const std::string& name);
/// ../shared/meshes when the corpus is present, else nullopt (tests then GTEST_SKIP with a message).
std::optional<std::filesystem::path> shared_meshes();
/// Corpus meshes (sorted by name) with at most `max_faces` faces, read from the file names; empty without
/// corpus.
std::vector<std::filesystem::path> corpus_meshes(int max_faces);
/// The built foldkit executable, for end-to-end tests of the CLI.
std::filesystem::path foldkit_binary();
/// The bytes of file `p` (empty when it cannot be read: the caller's expectations then fail).
std::string slurp(const std::filesystem::path& p);
/// How many entries directory `dir` holds (what a failed write may have left behind).
int count_entries(const std::filesystem::path& dir);
/// A fresh empty directory under the system temp dir, unique per call; all of a test process's are removed
/// when it exits (set FOLDKIT_KEEP_TEST_FILES to keep them).
std::filesystem::path temp_dir(const std::string& tag);

/// What a run of the foldkit executable produced.
struct CliRun {
  int exit_code = -1;
  bool signalled = false;  ///< killed by a signal (a crash): never acceptable
  std::string out, err;
};
/// Runs the built foldkit with `args` (no shell interpretation of their contents), capturing output.
CliRun run_foldkit(const std::vector<std::string>& args);
/// As run_foldkit, with `cwd` as the working directory (what a user outside the source tree sees).
CliRun run_foldkit_in(const std::filesystem::path& cwd, const std::vector<std::string>& args);
/// Debian's python3 (where python3-ezdxf and python3-shapely live, which bootstrap installs) before
/// whatever python3 the PATH finds first.
std::string debian_python();
/// Runs tests/tools/`tool` (an independent checker in Python) with debian_python() and `args`.
CliRun run_python_tool(const std::string& tool, const std::vector<std::string>& args);
}  // namespace foldkit::test
