#include "length_option.hpp"

#include <cmath>
#include <cstdio>

#include "foldkit/layout/paper.hpp"

namespace foldkit::cli {

std::string format_length_mm(double mm) {
  char text[48];
  std::snprintf(text, sizeof text, "%.6g mm", mm);
  return text;
}

CLI::Validator length_in(LengthRange range) {
  const std::string bounds = format_length_mm(range.min_mm) + " and " + format_length_mm(range.max_mm);
  return CLI::Validator(
      [range, bounds](std::string& text) -> std::string {
        // A negative length is a length out of range, not an unreadable one.
        const bool negative = !text.empty() && text[0] == '-';
        const auto mm = layout::parse_non_negative_length_mm(negative ? text.substr(1) : text);
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

}  // namespace foldkit::cli
