#pragma once
// Where foldkit finds the data it ships and the data it uses from other packages, installed or run from
// its build tree. Everything is found relative to the running executable or through the folders the
// caller learnt from the environment; no path of the source tree is compiled in, so an installed copy
// works after the clone is deleted and a build tree never reads a stale install.
#include <filesystem>
#include <string>
#include <vector>

namespace foldkit::devices {

/// What the lookup starts from. The CLI fills it from the process: /proc/self/exe, the XDG base
/// directory variables.
struct InstallPaths {
  std::filesystem::path executable;  ///< the running program, symlinks resolved; empty when unknown
  std::filesystem::path
      user_config_dir;  ///< $XDG_CONFIG_HOME/foldkit or ~/.config/foldkit; empty when unknown
  std::vector<std::filesystem::path>
      data_dirs;  ///< $XDG_DATA_DIRS, in order (default /usr/local/share, /usr/share)
};

/// The data folders of the XDG base directory rule from the value of $XDG_DATA_DIRS (null when unset):
/// its absolute entries in order, or /usr/local/share and /usr/share when it names none.
std::vector<std::filesystem::path> xdg_data_dirs(const char* xdg_data_dirs_value);

/// Profile folders in the order they are read (a later profile with the same id replaces an earlier
/// one), whether or not they exist: `<exe dir>/../share/foldkit/profiles`, the built-in profiles of an
/// installed prefix (a build tree links the same place to its source's profiles/), then
/// `<user config>/profiles`, the user's own.
std::vector<std::filesystem::path> profile_search_dirs(const InstallPaths& paths);

/// The folders of profile_search_dirs that hold a devices/ or media/ folder.
std::vector<std::filesystem::path> profile_dirs(const InstallPaths& paths);

/// Where a Hershey font named `name` (e.g. "futural") is looked for, in order: foldkit's own share
/// folder and the hershey-fonts folder beside it (`<exe dir>/../share/{foldkit/fonts,hershey-fonts}`), then
/// `<data dir>/hershey-fonts` for each data dir, where Debian's hershey-fonts-data puts them.
std::vector<std::filesystem::path> stroke_font_search_paths(const InstallPaths& paths,
                                                            const std::string& name);

/// The first existing file of stroke_font_search_paths. Throws Error naming the font, every path
/// looked at and the Debian package that ships it when there is none.
std::filesystem::path find_stroke_font(const InstallPaths& paths, const std::string& name = "futural");

}  // namespace foldkit::devices
