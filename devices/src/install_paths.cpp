#include "foldkit/devices/install_paths.hpp"

#include <string_view>
#include <system_error>

#include "foldkit/error.hpp"

namespace foldkit::devices {
namespace fs = std::filesystem;

namespace {

// The prefix an installed program lives in: <prefix>/bin/foldkit. A build tree has the same shape
// (build/cli/foldkit), and its build/share/foldkit/profiles links to the source's profiles/.
fs::path share_dir(const InstallPaths& paths) {
  if (paths.executable.empty()) return {};
  return paths.executable.parent_path().parent_path() / "share";
}

bool is_dir(const fs::path& p) {
  std::error_code ec;
  return fs::is_directory(p, ec);
}

bool is_file(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(p, ec);
}

std::string joined(const std::vector<fs::path>& paths) {
  std::string out;
  for (const fs::path& p : paths)
    out += (out.empty() ? "" : ", ") + p.string();
  return out;
}

}  // namespace

std::vector<fs::path> xdg_data_dirs(const char* xdg_data_dirs_value) {
  std::vector<fs::path> dirs;
  const std::string_view value = xdg_data_dirs_value ? xdg_data_dirs_value : "";
  std::size_t start = 0;
  while (start <= value.size()) {
    const std::size_t end = std::min(value.find(':', start), value.size());
    // Relative entries are to be ignored (XDG Base Directory Specification).
    const fs::path entry(value.substr(start, end - start));
    if (entry.is_absolute()) dirs.push_back(entry);
    start = end + 1;
  }
  if (dirs.empty()) dirs = {"/usr/local/share", "/usr/share"};
  return dirs;
}

std::vector<fs::path> profile_search_dirs(const InstallPaths& paths) {
  std::vector<fs::path> dirs;
  if (const fs::path share = share_dir(paths); !share.empty()) dirs.push_back(share / "foldkit" / "profiles");
  if (!paths.user_config_dir.empty()) dirs.push_back(paths.user_config_dir / "profiles");
  return dirs;
}

std::vector<fs::path> profile_dirs(const InstallPaths& paths) {
  std::vector<fs::path> found;
  for (const fs::path& dir : profile_search_dirs(paths)) {
    if (is_dir(dir / "devices") || is_dir(dir / "media")) found.push_back(dir);
  }
  return found;
}

std::vector<fs::path> stroke_font_search_paths(const InstallPaths& paths, const std::string& name) {
  const std::string file = name + ".jhf";
  std::vector<fs::path> out;
  if (const fs::path share = share_dir(paths); !share.empty()) {
    out.push_back(share / "foldkit" / "fonts" / file);
    out.push_back(share / "hershey-fonts" / file);
  }
  for (const fs::path& dir : paths.data_dirs) {
    fs::path candidate = dir / "hershey-fonts" / file;
    bool seen = false;
    for (const fs::path& p : out)
      seen = seen || p == candidate;
    if (!seen) out.push_back(std::move(candidate));
  }
  return out;
}

fs::path find_stroke_font(const InstallPaths& paths, const std::string& name) {
  const std::vector<fs::path> candidates = stroke_font_search_paths(paths, name);
  for (const fs::path& p : candidates) {
    if (is_file(p)) return p;
  }
  throw Error("no Hershey font " + name + ".jhf for single-stroke labels (looked for " + joined(candidates) +
                  "); install the Debian package hershey-fonts-data",
              ExitCode::Failure);
}

}  // namespace foldkit::devices
