#pragma once
// Paper sizes: named presets (A5, A4, A3, Letter, Legal, a 12x12 in cutting mat) and custom sizes
// such as "210x297mm", "8.5x11in" or "30x30cm", plus portrait/landscape orientation.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "foldkit/geom/vec.hpp"

namespace foldkit::layout {

enum class Orientation { Portrait, Landscape };

/// A named preset, size in portrait orientation.
struct PaperPreset {
  std::string name;
  Vec2 size_mm;
};

/// The presets, in the order shown to users.
const std::vector<PaperPreset>& paper_presets();

/// Width and height in millimetres for a preset name (case-insensitive: "a4", "Letter", "mat12",
/// "12x12in") or a custom "WxH" size with unit mm, cm or in (no unit: mm). nullopt when the text is
/// neither, or a dimension is not positive and finite. The size is returned as written.
std::optional<Vec2> parse_paper(std::string_view text);

/// The size turned to the orientation: portrait has width <= height, landscape width >= height.
Vec2 oriented(Vec2 size_mm, Orientation orientation);

/// A length such as "150mm", "15cm", "6in" or "150" (mm), in millimetres; nullopt unless it is a
/// positive finite number with an optional unit.
std::optional<double> parse_length_mm(std::string_view text);

/// As parse_length_mm, but zero is a length too (a margin, a gap).
std::optional<double> parse_non_negative_length_mm(std::string_view text);

/// "A4, A3, …" for help texts and error messages.
std::string paper_names();

}  // namespace foldkit::layout
