#pragma once
// What a command line that CLI11 refused prints: CLI11's own message (what it did not understand), the
// nearest subcommand or option when a word looks like a typo of one ("did you mean make?"), and where
// the help is. One line, for exit code 2.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

namespace foldkit::cli {

/// The name in `names` closest to `word` (a unique prefix, or within a small edit distance that grows
/// with the word's length), or nullopt when none is close enough to be a likely typo.
std::optional<std::string> nearest_name(std::string_view word, const std::vector<std::string>& names);

/// The message for `error` raised while `app` parsed its arguments, starting "foldkit: " and ending in a
/// newline.
std::string usage_error_message(const CLI::App& app, const CLI::ParseError& error);

}  // namespace foldkit::cli
