#include "parallel.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace afford {

void parallel_for(std::size_t n, int threads, const std::function<void(std::size_t)>& task,
                  const std::function<void(std::size_t, std::size_t)>& progress, double every_s) {
  std::atomic<std::size_t> next{0}, done{0};
  std::atomic<bool> failed{false};
  std::exception_ptr error;
  std::mutex mutex;
  std::condition_variable finished;
  int running = std::max(1, threads);

  auto work = [&] {
    for (std::size_t i; !failed && (i = next++) < n;) {
      try {
        task(i);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(mutex);
        if (!error) error = std::current_exception();
        failed = true;
      }
      ++done;
    }
    const std::lock_guard<std::mutex> lock(mutex);
    --running;
    finished.notify_all();
  };
  std::vector<std::thread> pool;
  const int count = running;
  pool.reserve(static_cast<std::size_t>(count));
  for (int t = 0; t < count; ++t) pool.emplace_back(work);
  {
    std::unique_lock<std::mutex> lock(mutex);
    const auto period = std::chrono::duration<double>(every_s);
    while (!finished.wait_for(lock, period, [&] { return running == 0; })) {
      if (progress) {
        lock.unlock();
        progress(done, n);
        lock.lock();
      }
    }
  }
  for (std::thread& t : pool) t.join();
  if (error) std::rethrow_exception(error);
  if (progress) progress(done, n);
}

int default_threads() {
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

}  // namespace afford
