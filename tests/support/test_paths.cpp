#include "test_paths.hpp"

#include <sys/wait.h>
#include <unistd.h>
#include <algorithm>
#include <atomic>
#include <random>

#include <cstdlib>
#include <fstream>
#include <iterator>

#include "foldkit/devices/install_paths.hpp"

namespace foldkit::test {
namespace fs = std::filesystem;

fs::path source_dir() {
  return fs::path(FOLDKIT_SOURCE_DIR);
}

fs::path profiles_dir() {
  return source_dir() / "profiles";
}

fs::path stroke_font_path() {
  devices::InstallPaths paths;
  paths.data_dirs = devices::xdg_data_dirs(std::getenv("XDG_DATA_DIRS"));
  const std::vector<fs::path> candidates = devices::stroke_font_search_paths(paths, "futural");
  for (const fs::path& p : candidates) {
    if (fs::is_regular_file(p)) return p;
  }
  return candidates.front();
}

fs::path example_mesh(const std::string& name) {
  return source_dir() / "examples" / name;
}

std::optional<fs::path> shared_meshes() {
  fs::path p = fs::path(FOLDKIT_SHARED_DIR) / "meshes";
  if (fs::is_directory(p)) return p;
  return std::nullopt;
}

std::vector<fs::path> corpus_meshes(int max_faces) {
  std::vector<fs::path> out;
  auto dir = shared_meshes();
  if (!dir) return out;
  for (const auto& entry : fs::directory_iterator(*dir)) {
    if (entry.path().extension() != ".obj") continue;
    std::string stem = entry.path().stem().string();
    auto us = stem.rfind('_');
    if (us == std::string::npos) continue;
    int faces = std::atoi(stem.c_str() + us + 1);
    if (faces > 0 && faces <= max_faces) out.push_back(entry.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

fs::path foldkit_binary() {
  return fs::path(FOLDKIT_BINARY);
}

namespace {
// Every directory a test process asks for lives under one root of that process, removed when the process
// ends: each ctest case is a process, and a suite run used to leave about 450 directories (up to 12 MB
// each) in /tmp. A child forked by a test exits through _exit, and the owner's pid is checked anyway, so
// a child never removes what its parent still uses. FOLDKIT_KEEP_TEST_FILES keeps them for a post-mortem.
class TempRoot {
 public:
  TempRoot()
      : owner_(::getpid()), path_(fs::temp_directory_path() / ("foldkit-test-" + std::to_string(owner_))) {
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  TempRoot(const TempRoot&) = delete;
  TempRoot& operator=(const TempRoot&) = delete;
  ~TempRoot() {
    if (::getpid() != owner_ || std::getenv("FOLDKIT_KEEP_TEST_FILES") != nullptr) return;
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  const fs::path& path() const { return path_; }

 private:
  pid_t owner_;
  fs::path path_;
};
}  // namespace

fs::path temp_dir(const std::string& tag) {
  static const TempRoot root;
  static std::atomic<int> counter{0};
  fs::path p = root.path() / (tag + "-" + std::to_string(counter++));
  fs::remove_all(p);
  fs::create_directories(p);
  return p;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

CliRun run_foldkit(const std::vector<std::string>& args) {
  return run_foldkit_in({}, args);
}

namespace {

// Runs `program` with `args` (each quoted for the shell, so never interpreted), capturing its output.
CliRun run_program(const fs::path& cwd, const std::string& program, const std::vector<std::string>& args) {
  const fs::path dir = temp_dir("run_program");
  auto quote = [](const std::string& s) {
    std::string q;
    q.push_back('\'');
    for (char ch : s) {
      if (ch == '\'')
        q.append("'\\''");
      else
        q.push_back(ch);
    }
    q.push_back('\'');
    return q;
  };
  std::string cmd = cwd.empty() ? "" : "cd " + quote(cwd.string()) + " && exec ";
  cmd += quote(program);
  for (const auto& a : args) {
    cmd.push_back(' ');
    cmd.append(quote(a));
  }
  cmd.append(" >");
  cmd.append(quote((dir / "out").string()));
  cmd.append(" 2>");
  cmd.append(quote((dir / "err").string()));
  cmd.append(" </dev/null");
  const int status = std::system(cmd.c_str());
  CliRun r;
  if (WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
  r.signalled = WIFSIGNALED(status) || (WIFEXITED(status) && WEXITSTATUS(status) > 128);
  r.out = slurp(dir / "out");
  r.err = slurp(dir / "err");
  fs::remove_all(dir);
  return r;
}

}  // namespace

CliRun run_foldkit_in(const fs::path& cwd, const std::vector<std::string>& args) {
  return run_program(cwd, foldkit_binary().string(), args);
}

std::string debian_python() {
  return fs::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
}

CliRun run_python_tool(const std::string& tool, const std::vector<std::string>& args) {
  std::vector<std::string> all{(source_dir() / "tests" / "tools" / tool).string()};
  all.insert(all.end(), args.begin(), args.end());
  return run_program({}, debian_python(), all);
}

int count_entries(const std::filesystem::path& dir) {
  int n = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir))
    ++n;
  return n;
}

}  // namespace foldkit::test
