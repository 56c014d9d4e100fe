#include "progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace foldkit::cli {

ProgressLine::ProgressLine(bool enabled)
    : enabled_(enabled),
      tty_(isatty(STDERR_FILENO) != 0),
      start_(std::chrono::steady_clock::now()),
      last_(start_) {}

ProgressLine::~ProgressLine() {
  clear();
}

bool ProgressLine::due() const {
  if (!enabled_) return false;
  const auto now = std::chrono::steady_clock::now();
  if (now - start_ < std::chrono::seconds(1)) return false;
  // A terminal gets at most ten redraws a second; a log file one line every five seconds.
  return !shown_ || now - last_ >= (tty_ ? std::chrono::milliseconds(100) : std::chrono::milliseconds(5000));
}

void ProgressLine::update(std::string_view text) {
  if (!due()) return;
  last_ = std::chrono::steady_clock::now();
  std::string line(text);
  if (tty_) {
    std::string padded = line;
    if (padded.size() < last_width_) padded.append(last_width_ - padded.size(), ' ');
    std::fprintf(stderr, "\r%s", padded.c_str());
    last_width_ = line.size();
  } else {
    std::fprintf(stderr, "%s\n", line.c_str());
  }
  std::fflush(stderr);
  shown_ = true;
}

void ProgressLine::clear() {
  if (!enabled_ || !shown_ || !tty_) return;
  std::fprintf(stderr, "\r%s\r", std::string(last_width_, ' ').c_str());
  std::fflush(stderr);
  shown_ = false;
  last_width_ = 0;
}

}  // namespace foldkit::cli
