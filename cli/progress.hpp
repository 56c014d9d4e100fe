#pragma once
// A progress line on stderr for long work: silent for the first second (quick jobs stay quiet),
// then rewritten in place on a terminal, or one plain line every few seconds when stderr is a file.
#include <chrono>
#include <string>
#include <string_view>

namespace foldkit::cli {

class ProgressLine {
 public:
  /// `enabled` false (e.g. --quiet or --json) makes every call a no-op.
  explicit ProgressLine(bool enabled = true);
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;
  /// Clears the line.
  ~ProgressLine();
  /// Shows `text` (one line, no newline) if the work has run for over a second.
  void update(std::string_view text);
  /// Whether update() would show a line now: callers that report often can skip building the text.
  bool due() const;
  /// Removes the line from the terminal, so later messages start on a clean line.
  void clear();

 private:
  bool enabled_;
  bool tty_;
  bool shown_ = false;
  std::size_t last_width_ = 0;
  std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace foldkit::cli
