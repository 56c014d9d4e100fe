#include "length_option.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

#include "foldkit/layout/paper.hpp"

namespace foldkit::cli {

std::string format_length_mm(double mm) {
  char text[48];
  std::snprintf(text, sizeof text, "%.6g mm", mm);
  return text;
}

namespace {

// "1e308in" is a length too large to hold in mm, not text that is no length.
bool beyond_double_range(std::string text) {
  for (const char* unit : {"mm", "cm", "in"})
    if (text.size() > 2 && text.compare(text.size() - 2, 2, unit) == 0) text.resize(text.size() - 2);
  double v = 0;
  const auto [at, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  return at == text.data() + text.size() && !text.empty() &&
         (ec == std::errc::result_out_of_range || (ec == std::errc() && std::isfinite(v)));
}

}  // namespace

CLI::Validator length_in(LengthRange range) {
  const std::string bounds = format_length_mm(range.min_mm) + " and " + format_length_mm(range.max_mm);
  return CLI::Validator(
      [range, bounds](std::string& text) -> std::string {
        // A negative length is a length out of range, not an unreadable one.
        const bool negative = !text.empty() && text[0] == '-';
        const auto mm = layout::parse_non_negative_length_mm(negative ? text.substr(1) : text);
        if (!mm && beyond_double_range(text))
          return "'" + text.substr(0, 40) + "': must be between " + bounds;
        if (!mm) return "'" + text.substr(0, 40) + "': expected a length such as 5mm, 0.5cm or 0.2in";
        if (negative && *mm > 0) return "'" + text.substr(0, 40) + "': must be between " + bounds;
        if (*mm < range.min_mm || *mm > range.max_mm)
          return "'" + text.substr(0, 40) + "': must be between " + bounds;
        char exact[32];
        std::snprintf(exact, sizeof exact, "%.17g", *mm);
        text = exact;
        return "";
      },
      "LENGTH", "length");
}

CLI::Option* add_length_option(CLI::App& cmd, const std::string& name, double& target_mm,
                               const std::string& help, LengthRange range) {
  return cmd
      .add_option(name, target_mm,
                  help + " (" + format_length_mm(range.min_mm) + " to " + format_length_mm(range.max_mm) +
                      "; units mm, cm, in)")
      ->transform(length_in(range))
      ->capture_default_str();
}

CLI::Validator paper_in(LengthRange side) {
  return CLI::Validator(
      [side](std::string& text) -> std::string {
        const auto size = layout::parse_paper(text);
        if (!size) return "unknown paper '" + text.substr(0, 40) + "': use " + layout::paper_names();
        if (std::min(size->x, size->y) < side.min_mm || std::max(size->x, size->y) > side.max_mm)
          return "'" + text.substr(0, 40) + "': each side must be between " + format_length_mm(side.min_mm) +
                 " and " + format_length_mm(side.max_mm);
        return "";
      },
      "PAPER", "paper");
}

CLI::Validator number_in(double min, double max, const std::string& unit) {
  char text[96];
  std::snprintf(text, sizeof text, "%.15g and %.15g%s%s", min, max, unit.empty() ? "" : " ", unit.c_str());
  const std::string bounds = text;
  return CLI::Validator(
      [min, max, bounds](const std::string& value) -> std::string {
        double v = 0;
        const char* end = value.data() + value.size();
        const auto [at, ec] = std::from_chars(value.data(), end, v);
        const std::string shown = "'" + value.substr(0, 40) + "'";
        if (at != end || value.empty()) return shown + ": expected a number";
        // from_chars reports a value beyond double range as out of range, not as a bad number.
        if (ec == std::errc::result_out_of_range || !(v >= min && v <= max))
          return shown + ": must be between " + bounds;
        if (ec != std::errc()) return shown + ": expected a number";
        return "";
      },
      "NUMBER", "number");
}

}  // namespace foldkit::cli
