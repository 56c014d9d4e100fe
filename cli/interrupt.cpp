#include "interrupt.hpp"

#include <pthread.h>
#include <unistd.h>

#include <csignal>
#include <cstring>
#include <thread>

#include "foldkit/devices/atomic_file.hpp"

namespace foldkit::cli {
namespace {

// Process-wide because signals are: the waiting thread finds the current cancel flag here.
std::atomic<std::atomic<bool>*> g_cancel{nullptr};
std::atomic<int> g_cancel_signal{0};

sigset_t handled_signals() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  return set;
}

[[noreturn]] void end_process(int sig) {
  devices::remove_pending_temporaries();
  const char* what = sig == SIGINT ? "foldkit: interrupted\n" : "foldkit: terminated\n";
  // A progress line may be on screen: start the message on a line of its own.
  if (isatty(STDERR_FILENO) != 0) (void)!::write(STDERR_FILENO, "\n", 1);
  (void)!::write(STDERR_FILENO, what, std::strlen(what));
  ::_exit(128 + sig);
}

void wait_for_signals(sigset_t set) {
  for (;;) {
    int sig = 0;
    if (sigwait(&set, &sig) != 0) continue;
    std::atomic<bool>* flag = g_cancel.load();
    if (flag != nullptr && g_cancel_signal.load() == 0) {
      g_cancel_signal.store(sig);
      flag->store(true);
      continue;
    }
    end_process(sig);
  }
}

}  // namespace

SignalHandling::SignalHandling() {
  const sigset_t set = handled_signals();
  pthread_sigmask(SIG_BLOCK, &set, nullptr);
  std::thread(wait_for_signals, set).detach();
}

ScopedCancel::ScopedCancel(std::atomic<bool>& flag) {
  flag.store(false);
  g_cancel_signal.store(0);
  g_cancel.store(&flag);
}

ScopedCancel::~ScopedCancel() {
  g_cancel.store(nullptr);
}

int ScopedCancel::signal() const {
  return g_cancel_signal.load();
}

}  // namespace foldkit::cli
