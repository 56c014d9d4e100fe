#pragma once
// A CLI stage (a run_* function of cli/cmd_<name>.hpp) run in the test's own process, with what it
// printed on stdout: the CLI tests that check results need no process of their own. Exit codes, one-line
// errors and signals stay with the subprocess tests (run_foldkit).
#include <gtest/gtest.h>

#include <cstdio>
#include <functional>
#include <string>

namespace foldkit::test {

/// Runs `stage` and returns its standard output; an exception from it passes on after the capture ends.
inline std::string stdout_of(const std::function<void()>& stage) {
  testing::internal::CaptureStdout();
  try {
    stage();
  } catch (...) {
    std::fflush(stdout);
    (void)testing::internal::GetCapturedStdout();
    throw;
  }
  std::fflush(stdout);
  return testing::internal::GetCapturedStdout();
}

}  // namespace foldkit::test
