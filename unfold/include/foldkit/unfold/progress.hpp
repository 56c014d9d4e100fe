#pragma once
// What the unfolders report while they run, and how a caller cancels them: a callback that returns false.
#include <functional>
#include <string>

namespace foldkit::unfold {

/// Progress report while unfolding; return false to cancel (the best result so far is returned).
struct UnfoldProgress {
  std::string stage;  ///< e.g. "ga 70%", "search"
  int iteration = 0;  ///< generation or move count
  int pieces = 0;     ///< best number of pieces so far
  double best_score = 0;
  double seconds = 0;
};
using ProgressFn = std::function<bool(const UnfoldProgress&)>;

}  // namespace foldkit::unfold
