#pragma once
// Options that take one name of a table (--fold-method, --mountain, …): the table is written once, and its
// names make the help text and the parser's check.
#include <string>
#include <vector>

namespace foldkit::cli {

/// The names (first of each pair) of a table of (name, value) pairs, in the table's order.
template <class Table>
std::vector<std::string> choice_names(const Table& table) {
  std::vector<std::string> names;
  for (const auto& [name, value] : table)
    names.push_back(name);
  return names;
}

/// "a, b, c": the names for help text.
inline std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& n : names)
    text += (text.empty() ? "" : ", ") + n;
  return text;
}

}  // namespace foldkit::cli
