#pragma once
// What the device tests share: the project's profiles and the pen font, each loaded once per test
// binary (they are read-only), and bytes built from text.
#include <cstddef>
#include <string>
#include <vector>

#include "foldkit/devices/profile.hpp"
#include "foldkit/devices/stroke_font.hpp"
#include "test_paths.hpp"

namespace foldkit::test {

/// The built-in device and media profiles of the source tree.
inline const devices::ProfileSet& builtin_profiles() {
  static const devices::ProfileSet set = devices::load_profiles(profiles_dir());
  return set;
}

/// The Hershey font of pen labels.
inline const devices::StrokeFont& pen_font() {
  static const devices::StrokeFont font = devices::load_stroke_font(stroke_font_path());
  return font;
}

/// The bytes of `s`, as a transport sends them.
inline std::vector<std::byte> bytes_of(const std::string& s) {
  std::vector<std::byte> out;
  out.reserve(s.size());
  for (char c : s)
    out.push_back(static_cast<std::byte>(c));
  return out;
}

}  // namespace foldkit::test
