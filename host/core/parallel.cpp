#include "core/parallel.h"

#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace rc {

namespace {
int gThreads = 0;
}

void setThreadCount(int threads) { gThreads = threads < 0 ? 0 : threads; }

int threadCount() {
  if (gThreads > 0) return gThreads;
  const unsigned hw = std::thread::hardware_concurrency();
  return hw ? static_cast<int>(hw) : 1;
}

void parallelFor(size_t n, size_t chunk, const std::function<void(size_t, size_t)>& body) {
  if (n == 0) return;
  if (chunk == 0) chunk = 1;
  const size_t chunks = (n + chunk - 1) / chunk;
  const int workers = static_cast<int>(std::min<size_t>(chunks, static_cast<size_t>(threadCount())));
  std::atomic<size_t> next{0};
  std::exception_ptr failure;
  std::mutex failureMutex;
  auto work = [&]() {
    for (;;) {
      const size_t c = next.fetch_add(1);
      if (c >= chunks) return;
      try {
        body(c * chunk, std::min(n, (c + 1) * chunk));
      } catch (...) {
        std::lock_guard<std::mutex> lock(failureMutex);
        if (!failure) failure = std::current_exception();
        next = chunks;  // stop handing out work
      }
    }
  };
  if (workers <= 1) {
    work();
  } else {
    std::vector<std::thread> pool;
    for (int i = 1; i < workers; ++i) pool.emplace_back(work);
    work();
    for (auto& t : pool) t.join();
  }
  if (failure) std::rethrow_exception(failure);
}

}  // namespace rc
