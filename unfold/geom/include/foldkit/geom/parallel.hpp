#pragma once
// The one thread pool of foldkit: jobs 0..count-1 handed out in order to `threads` threads, the calling
// thread among them. Which thread runs a job never changes what the job computes, so callers that keep
// their jobs independent stay deterministic whatever the thread count.
#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace foldkit {

/// The threads `threads` asks for: itself when positive, else as many as the hardware has (at least 1).
inline int resolve_threads(int threads) {
  return threads > 0 ? threads : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

/// Runs job(k) for every k in 0..count-1 on up to `threads` threads (the caller's included) and returns
/// when all are done. A job that throws stops the jobs not yet started; the first exception is
/// rethrown on the calling thread once every thread has finished.
template <class Job>
void run_parallel(int count, int threads, const Job& job) {
  std::atomic<int> next{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  auto worker = [&] {
    for (int k; (k = next.fetch_add(1)) < count;) {
      try {
        job(k);
      } catch (...) {
        const std::lock_guard lock(failure_mutex);
        if (!failure) failure = std::current_exception();
        next.store(count);
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < std::min(threads, count); ++t)
    pool.emplace_back(worker);
  worker();
  for (auto& t : pool)
    t.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace foldkit
