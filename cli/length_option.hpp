#pragma once
// Bounded values on the command line. Every length option takes a number with an optional unit (mm, cm,
// in; none: mm), through one parser (layout::parse_non_negative_length_mm), bounded to what a sheet or a
// cutter can hold, with the bounds in the error ("--margin 1e300mm: must be between 0 mm and 200 mm");
// plain numbers (dpi, seconds, counts) get the same kind of bounds and message.
#include <string>

#include <CLI/CLI.hpp>

#include "foldkit/geom/vec.hpp"

namespace foldkit::cli {

/// The lengths an option accepts, mm, both ends included.
struct LengthRange {
  double min_mm = 0;
  double max_mm = 0;
};

/// "0.5 mm", "3000 mm": a length for messages, without a 309-digit number.
std::string format_length_mm(double mm);

/// A CLI11 transform that turns a length with units into its value in mm (as text, for CLI11 to convert)
/// or fails with the accepted range.
CLI::Validator length_in(LengthRange range);

/// Adds `--name LENGTH` storing millimetres in `target_mm`; help text gets the range and the default.
CLI::Option* add_length_option(CLI::App& cmd, const std::string& name, double& target_mm,
                               const std::string& help, LengthRange range);

/// A CLI11 check for a paper: a preset name or WxH with a unit, each side within `side`.
CLI::Validator paper_in(LengthRange side);

/// A CLI11 check for a plain number from `min` to `max` (both included), with the bounds in its message
/// the way lengths have them ("--dpi 1e300: must be between 10 and 2400 dpi"); `unit` may be empty.
CLI::Validator number_in(double min, double max, const std::string& unit = "");

}  // namespace foldkit::cli
