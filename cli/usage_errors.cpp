#include "usage_errors.hpp"

#include <algorithm>

namespace foldkit::cli {
namespace {

// Optimal string alignment distance: insertions, deletions, substitutions and swaps of neighbours
// ("mkae") each cost one.
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i)
    d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j)
    d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i)
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t change = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + change});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

// The deepest subcommand the arguments selected: the one whose options a mistyped word meant.
const CLI::App& selected_command(const CLI::App& app) {
  const CLI::App* at = &app;
  for (auto chosen = at->get_subcommands(); !chosen.empty(); chosen = at->get_subcommands())
    at = chosen.front();
  return *at;
}

std::vector<std::string> subcommand_names(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    names.push_back(sub->get_name());
  return names;
}

std::vector<std::string> option_names(const CLI::App& command) {
  std::vector<std::string> names;
  for (const CLI::Option* option : command.get_options()) {
    // Hidden options (the bench's child mode) are not offered.
    if (option->get_group().empty()) continue;
    for (const std::string& name : option->get_lnames())
      names.push_back("--" + name);
  }
  return names;
}

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& name : names)
    out += (out.empty() ? "" : ", ") + name;
  return out;
}

// A hint for the first word nothing took: the option or subcommand it most likely meant.
std::string hint_for(const CLI::App& app, const CLI::App& command, const std::vector<std::string>& left) {
  const bool top = &command == &app;
  for (const std::string& word : left) {
    const bool option_like = word.size() > 1 && word[0] == '-';
    // "--sizee=10" names the option before the '='.
    const std::string name = option_like ? word.substr(0, word.find('=')) : word;
    const auto candidates = option_like ? option_names(command)
                            : top       ? subcommand_names(app)
                                        : std::vector<std::string>{};
    if (const auto near = nearest_name(name, candidates)) return "did you mean " + *near + "?";
  }
  if (top) return "a command comes first: " + joined(subcommand_names(app));
  return "";
}

}  // namespace

std::optional<std::string> nearest_name(std::string_view word, const std::vector<std::string>& names) {
  if (word.empty()) return std::nullopt;
  // A unique prefix is what the user began to type.
  std::vector<std::string> prefixed;
  for (const std::string& name : names)
    if (name.size() > word.size() && name.compare(0, word.size(), word) == 0) prefixed.push_back(name);
  const std::size_t bare =
      word.find_first_not_of('-') == std::string_view::npos ? 0 : word.size() - word.find_first_not_of('-');
  if (prefixed.size() == 1 && bare >= 2) return prefixed.front();
  // One slip in four letters, at least one and at most three.
  const std::size_t allowed = std::clamp<std::size_t>(bare / 4, 1, 3);
  std::optional<std::string> best;
  std::size_t best_distance = allowed + 1;
  for (const std::string& name : names) {
    const std::size_t d = edit_distance(word, name);
    if (d < best_distance) {
      best_distance = d;
      best = name;
    }
  }
  return best;
}

std::string usage_error_message(const CLI::App& app, const CLI::ParseError& error) {
  const CLI::App& command = selected_command(app);
  const std::vector<std::string> left = app.remaining(true);
  std::string what = error.what();
  // Without a subcommand CLI11 reports the missing subcommand before the words it could not place,
  // which is the thing to show.
  if (&command == &app && !left.empty())
    what = std::string(left.size() == 1 ? "The following argument was not expected: "
                                        : "The following arguments were not expected: ") +
           joined(left);
  std::string hint =
      left.empty() ? (&command == &app ? hint_for(app, command, left) : "") : hint_for(app, command, left);
  const std::string help = &command == &app ? "foldkit --help" : "foldkit " + command.get_name() + " --help";
  std::string line = "foldkit: " + what;
  if (!hint.empty()) line += "; " + hint;
  return line + " (see " + help + ")\n";
}

}  // namespace foldkit::cli
