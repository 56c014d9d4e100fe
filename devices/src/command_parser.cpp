#include "foldkit/devices/command_parser.hpp"

#include <charconv>
#include <cmath>
#include <limits>

#include "foldkit/error.hpp"

namespace foldkit::devices {
namespace {

// A command with no terminator after this many bytes is garbage, not a long command: real GP-GL lines
// stay below 1 KiB and HP-GL PD lists are split by every sane sender.
constexpr std::size_t kMaxGpglCommand = 4096;
constexpr std::size_t kMaxHpglCommand = 65536;
constexpr std::size_t kUnbounded = std::numeric_limits<std::size_t>::max();

struct Arity {
  const char* name;
  std::size_t min, max;
  bool pairs;  // parameters come as coordinate pairs
};

// GP-GL mnemonics in the Silhouette dialect (docs/plotter-protocols.md 2.1-2.6); two-letter ones first
// so "FX" is not read as "F" + "X".
constexpr Arity kGpgl[] = {
    {"FG", 0, 0, false}, {"FA", 0, 0, false}, {"TC", 0, 0, false},        {"TB", 1, 5, false},
    {"TG", 1, 1, false}, {"FN", 1, 1, false}, {"FX", 1, 2, false},        {"FE", 1, 2, false},
    {"FF", 3, 3, false}, {"FC", 2, 3, false}, {"FY", 1, 1, false},        {"TF", 2, 2, false},
    {"SO", 1, 1, false}, {"FO", 1, 1, false}, {"FW", 1, 1, false},        {"TJ", 1, 1, false},
    {"*", 2, 3, false},  {"M", 2, 2, true},   {"D", 2, kUnbounded, true}, {"J", 1, 1, false},
    {"!", 1, 2, false},  {"\\", 2, 2, true},  {"Z", 2, 2, true},          {"L", 1, 1, false},
    {"H", 0, 0, false},  {"[", 0, 0, false},  {"U", 0, 0, false},
};

constexpr Arity kHpgl[] = {
    {"IN", 0, 0, false},         {"PA", 0, kUnbounded, true}, {"PR", 0, kUnbounded, true},
    {"PU", 0, kUnbounded, true}, {"PD", 0, kUnbounded, true}, {"SP", 0, 1, false},
    {"VS", 1, 2, false},         {"FS", 1, 2, false},         {"LT", 0, 2, false},
    {"OI", 0, 0, false},         {"OS", 0, 0, false},         {"OH", 0, 0, false},
    {"!FS", 1, 2, false},        {"!ST", 0, 1, false},  // Roland's force and (undocumented) ST [FM]
};

// HP-GL mnemonics are two letters; Roland's own start with '!' and have three.
std::size_t mnemonic_length(std::string_view text) {
  return !text.empty() && text[0] == '!' ? 3 : 2;
}

[[noreturn]] void fail(const char* dialect, std::size_t offset, const std::string& problem) {
  throw DeviceError(std::string(dialect) + " byte " + std::to_string(offset) + ": " + problem);
}

std::string printable(std::string_view s) {
  std::string out;
  for (char c : s.substr(0, 24)) {
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x20 && u < 0x7f) {
      out += c;
    } else {
      static const char* hex = "0123456789abcdef";
      out += "\\x";
      out += hex[u >> 4];
      out += hex[u & 15];
    }
  }
  return out;
}

double parse_number(const char* dialect, std::size_t offset, std::string_view text) {
  double v = 0;
  const char* first = text.data();
  const char* last = first + text.size();
  if (text.empty()) fail(dialect, offset, "empty parameter");
  // from_chars takes no '+', and HP-GL allows none either; reject exponents and such by checking that
  // only digits, one '.', and a leading '-' occur.
  bool dot = false, digit = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c >= '0' && c <= '9')
      digit = true;
    else if (c == '.' && !dot)
      dot = true;
    else if (!(c == '-' && i == 0))
      fail(dialect, offset, "parameter \"" + printable(text) + "\" is not a number");
  }
  if (!digit) fail(dialect, offset, "parameter \"" + printable(text) + "\" is not a number");
  auto [ptr, ec] = std::from_chars(first, last, v);
  if (ec != std::errc() || ptr != last || !std::isfinite(v))
    fail(dialect, offset, "parameter \"" + printable(text) + "\" is not a number");
  return v;
}

void check_arity(const char* dialect, const Arity& a, const ParsedCommand& c) {
  const std::size_t n = c.params.size();
  if (n < a.min || n > a.max || (a.pairs && n % 2 != 0)) {
    std::string want = a.min == a.max        ? std::to_string(a.min)
                       : a.max == kUnbounded ? "at least " + std::to_string(a.min)
                                             : std::to_string(a.min) + " to " + std::to_string(a.max);
    if (a.pairs) want += " (in x,y pairs)";
    fail(dialect, c.offset, std::string(a.name) + " takes " + want + " parameters, got " + std::to_string(n));
  }
}

}  // namespace

std::vector<ParsedCommand> GpglParser::feed(std::span<const std::byte> bytes) {
  pending_.append(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  std::vector<ParsedCommand> out;
  std::size_t pos = 0;
  while (pos < pending_.size()) {
    const std::size_t at = base_ + pos;
    if (pending_[pos] == '\x1b') {
      if (pos + 1 >= pending_.size()) break;
      const auto code = static_cast<unsigned char>(pending_[pos + 1]);
      if (code != 0x04 && code != 0x05 && code != 0x15)
        fail("GP-GL", at, "unknown escape sequence ESC " + printable(pending_.substr(pos + 1, 1)));
      static const char* hex = "0123456789ABCDEF";
      out.push_back({at, std::string("ESC") + hex[code >> 4] + hex[code & 15], {}});
      pos += 2;
      continue;
    }
    const std::size_t etx = pending_.find('\x03', pos);
    if (etx == std::string::npos) {
      if (pending_.size() - pos > kMaxGpglCommand)
        fail("GP-GL", at, "no ETX terminator within " + std::to_string(kMaxGpglCommand) + " bytes");
      break;
    }
    const std::string_view text(pending_.data() + pos, etx - pos);
    if (text.empty()) fail("GP-GL", at, "empty command (ETX without a command)");
    const Arity* arity = nullptr;
    for (const Arity& a : kGpgl) {
      if (text.starts_with(a.name)) {
        arity = &a;
        break;
      }
    }
    if (!arity) fail("GP-GL", at, "unknown command \"" + printable(text) + "\"");
    ParsedCommand c{at, arity->name, {}};
    std::string_view rest = text.substr(std::char_traits<char>::length(arity->name));
    while (!rest.empty()) {
      const std::size_t comma = rest.find(',');
      c.params.push_back(parse_number("GP-GL", at, rest.substr(0, comma)));
      if (comma == std::string_view::npos) break;
      rest = rest.substr(comma + 1);
      if (rest.empty()) fail("GP-GL", at, std::string(arity->name) + " ends with a comma");
    }
    check_arity("GP-GL", *arity, c);
    out.push_back(std::move(c));
    pos = etx + 1;
  }
  pending_.erase(0, pos);
  base_ += pos;
  return out;
}

void GpglParser::finish() const {
  if (!pending_.empty())
    fail("GP-GL", base_, "stream ends inside a command (\"" + printable(pending_) + "\" has no ETX)");
}

std::vector<ParsedCommand> HpglParser::feed(std::span<const std::byte> bytes) {
  pending_.append(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  std::vector<ParsedCommand> out;
  std::size_t pos = 0;
  while (pos < pending_.size()) {
    const char c0 = pending_[pos];
    if (c0 == '\n' || c0 == '\r' || c0 == ' ' || c0 == '\t') {
      ++pos;
      continue;
    }
    const std::size_t at = base_ + pos;
    const std::size_t semi = pending_.find(';', pos);
    if (semi == std::string::npos) {
      if (pending_.size() - pos > kMaxHpglCommand)
        fail("HP-GL", at, "no ';' terminator within " + std::to_string(kMaxHpglCommand) + " bytes");
      // A complete mnemonic can be checked before its terminator arrives: garbage fails early.
      const std::size_t len = mnemonic_length(std::string_view(pending_).substr(pos));
      if (pending_.size() - pos >= len) {
        const std::string_view name(pending_.data() + pos, len);
        bool known = false;
        for (const Arity& a : kHpgl)
          known |= name == a.name;
        if (!known) fail("HP-GL", at, "unknown command \"" + printable(name) + "\"");
      }
      break;
    }
    const std::string_view text(pending_.data() + pos, semi - pos);
    const std::size_t len = mnemonic_length(text);
    if (text.size() < len) fail("HP-GL", at, "command \"" + printable(text) + "\" is too short");
    const Arity* arity = nullptr;
    for (const Arity& a : kHpgl) {
      if (text.substr(0, len) == a.name) arity = &a;
    }
    if (!arity) fail("HP-GL", at, "unknown command \"" + printable(text.substr(0, len)) + "\"");
    ParsedCommand c{at, arity->name, {}};
    std::string_view rest = text.substr(len);
    while (!rest.empty()) {
      const std::size_t sep = rest.find_first_of(", ");
      c.params.push_back(parse_number("HP-GL", at, rest.substr(0, sep)));
      if (sep == std::string_view::npos) break;
      rest = rest.substr(sep + 1);
      if (rest.empty()) fail("HP-GL", at, std::string(arity->name) + " ends with a separator");
    }
    check_arity("HP-GL", *arity, c);
    out.push_back(std::move(c));
    pos = semi + 1;
  }
  pending_.erase(0, pos);
  base_ += pos;
  return out;
}

void HpglParser::finish() const {
  for (char c : pending_) {
    if (c != '\n' && c != '\r' && c != ' ' && c != '\t')
      fail("HP-GL", base_, "stream ends inside a command (\"" + printable(pending_) + "\" has no ';')");
  }
}

}  // namespace foldkit::devices
