#pragma once
// The one thread pool of the unfolders: jobs 0..count-1 handed out in order to `threads` threads, the
// calling thread among them. Which thread runs a job never changes what the job computes, so callers
// that keep their jobs independent stay deterministic whatever the thread count.
#include <atomic>
#include <thread>
#include <vector>

namespace foldkit::unfold {

/// Runs job(k) for every k in 0..count-1 on up to `threads` threads (the caller's included) and returns
/// when all are done.
template <class Job>
void run_parallel(int count, int threads, const Job& job) {
  std::atomic<int> next{0};
  auto worker = [&] {
    for (int k; (k = next.fetch_add(1)) < count;)
      job(k);
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t)
    pool.emplace_back(worker);
  worker();
  for (auto& t : pool)
    t.join();
}

}  // namespace foldkit::unfold
