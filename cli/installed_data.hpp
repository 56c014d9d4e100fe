#pragma once
// Where this process finds foldkit's data: the running program's path and the XDG folders of its
// environment, handed to devices/install_paths.hpp, which knows the layout.
#include "foldkit/devices/install_paths.hpp"
#include "foldkit/devices/stroke_font.hpp"

namespace foldkit::cli {

/// The executable (/proc/self/exe), the user's configuration folder and $XDG_DATA_DIRS of this process.
devices::InstallPaths this_install();

/// The single-stroke font of pen and DXF labels. Throws Error naming every path looked at when the
/// font is not installed.
devices::StrokeFont load_label_font();

}  // namespace foldkit::cli
