#pragma once
// SIGINT and SIGTERM for every command: the temporary files of unfinished outputs are removed and the
// process ends with 130 (SIGINT) or 143 (SIGTERM), or, while a ScopedCancel is alive, the work in
// progress is told to stop cleanly (a cutter raises its tool and ends the job) and a second signal ends
// the process. The signals are taken by one thread through sigwait, so clean-up runs outside a signal
// handler and may lock.
#include <atomic>

namespace foldkit::cli {

/// Takes over SIGINT and SIGTERM for the process. Construct it in main before any other thread starts
/// (threads inherit the blocked signal mask; a thread started earlier could receive the signal).
class SignalHandling {
 public:
  SignalHandling();
  SignalHandling(const SignalHandling&) = delete;
  SignalHandling& operator=(const SignalHandling&) = delete;
};

/// While alive, the first SIGINT or SIGTERM sets `flag` instead of ending the process.
class ScopedCancel {
 public:
  explicit ScopedCancel(std::atomic<bool>& flag);
  ~ScopedCancel();
  ScopedCancel(const ScopedCancel&) = delete;
  ScopedCancel& operator=(const ScopedCancel&) = delete;
  /// The signal that set the flag (SIGINT or SIGTERM), 0 if none did.
  int signal() const;
};

}  // namespace foldkit::cli
