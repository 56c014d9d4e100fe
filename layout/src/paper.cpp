#include "foldkit/layout/paper.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

namespace foldkit::layout {
namespace {

std::string lower(std::string_view text) {
  std::string out(text);
  for (char& c : out)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// Parses a non-negative decimal number; std::from_chars for double is in libstdc++ 11+.
std::optional<double> parse_number(std::string_view text) {
  double value = 0;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

// Removes a trailing unit (mm, cm, in) from `text` and returns its size in mm; no unit is mm.
double take_unit(std::string_view& text) {
  if (text.size() <= 2) return 1;
  const std::string_view unit = text.substr(text.size() - 2);
  const double unit_mm = unit == "mm" ? 1 : unit == "cm" ? 10 : unit == "in" ? 25.4 : 0;
  if (unit_mm == 0) return 1;
  text.remove_suffix(2);
  return unit_mm;
}

}  // namespace

const std::vector<PaperPreset>& paper_presets() {
  static const std::vector<PaperPreset> presets = {
      {"A5", {148, 210}},         {"A4", {210, 297}},        {"A3", {297, 420}},
      {"Letter", {215.9, 279.4}}, {"Legal", {215.9, 355.6}}, {"mat12", {304.8, 304.8}},
  };
  return presets;
}

std::optional<Vec2> parse_paper(std::string_view text) {
  const std::string name = lower(text);
  for (const PaperPreset& preset : paper_presets())
    if (lower(preset.name) == name) return preset.size_mm;
  if (name == "12x12" || name == "12x12in" || name == "mat") return Vec2{304.8, 304.8};

  std::string_view rest = name;
  const double unit_mm = take_unit(rest);
  auto x = rest.find('x');
  if (x == std::string_view::npos) return std::nullopt;
  auto w = parse_number(rest.substr(0, x));
  auto h = parse_number(rest.substr(x + 1));
  if (!w || !h) return std::nullopt;
  Vec2 size{*w * unit_mm, *h * unit_mm};
  if (!(size.x > 0 && size.y > 0 && std::isfinite(size.x) && std::isfinite(size.y))) return std::nullopt;
  return size;
}

std::optional<double> parse_non_negative_length_mm(std::string_view text) {
  const std::string s = lower(text);
  std::string_view rest = s;
  const double unit_mm = take_unit(rest);
  auto value = parse_number(rest);
  if (!value || !(*value >= 0) || !std::isfinite(*value * unit_mm)) return std::nullopt;
  return *value * unit_mm;
}

std::optional<double> parse_length_mm(std::string_view text) {
  const auto mm = parse_non_negative_length_mm(text);
  if (!mm || !(*mm > 0)) return std::nullopt;
  return mm;
}

Vec2 oriented(Vec2 size_mm, Orientation orientation) {
  const double small = std::min(size_mm.x, size_mm.y), large = std::max(size_mm.x, size_mm.y);
  return orientation == Orientation::Portrait ? Vec2{small, large} : Vec2{large, small};
}

std::string paper_names() {
  std::string out;
  for (const PaperPreset& preset : paper_presets())
    out += (out.empty() ? "" : ", ") + preset.name;
  return out + " (12x12in mat) or a size like 210x297mm, 8.5x11in";
}

}  // namespace foldkit::layout
