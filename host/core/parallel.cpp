#include "core/parallel.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "core/cpu_clock.h"

namespace rc {

namespace {

int gThreads = 0;
// True on a thread while it runs chunks of a parallel loop: a parallelFor nested inside a body
// runs serially on that thread (the outer loop already keeps every thread busy, and waiting for
// pool workers that are themselves inside the outer loop would deadlock).
thread_local bool tInsideLoop = false;
// The loops this thread started (loopAccountOfThisThread); set while one is being timed, so a loop
// nested in its body is not counted twice.
thread_local LoopAccount tLoopAccount;
thread_local bool tTimingLoop = false;

// How long a thread that has run out of work keeps polling for more before it sleeps. Sleeping
// at once costs a scheduler wake-up on the other side — on a virtual machine tens of
// microseconds, longer than many loops — during which one thread works alone. A worker after its
// loop polls for the next one (the render's next loop usually starts after a few microseconds of
// serial code; a longer gap is a kernel call, whose threads need the core: the poll yields, and
// ends). The loop's caller polls for the workers still in a chunk: they finish within a chunk's
// time, and the core has nothing else of the render to run meanwhile.
constexpr auto kWorkerPoll = std::chrono::microseconds(1000);
constexpr auto kCallerPoll = std::chrono::microseconds(5000);

// Polls ready() until it holds or `bound` has passed, yielding the core every few dozen tries;
// returns the last ready().
template <class Ready>
bool pollFor(std::chrono::microseconds bound, Ready&& ready) {
  const auto until = std::chrono::steady_clock::now() + bound;
  for (int spin = 0;; ++spin) {
    if (ready()) return true;
    if ((spin & 63) == 63) {
      if (std::chrono::steady_clock::now() >= until) return ready();
      std::this_thread::yield();
    }
  }
}

// Persistent workers: a render makes thousands of parallelFor calls (per batch of records, per
// band), and creating and joining threads for each cost ≈ 5 % of the run time.
class WorkerPool {
 public:
  explicit WorkerPool(int helpers) {
    for (int i = 0; i < helpers; ++i) workers_.emplace_back([this] { loop(); });
  }
  ~WorkerPool() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
    }
    wake_.notify_all();
    for (auto& t : workers_) t.join();
  }
  int helpers() const { return static_cast<int>(workers_.size()); }

  // Runs `work` on the calling thread and on every worker that joins in time; returns when all
  // that joined have returned. `work` must return only when the loop has no chunk left to hand
  // out: then the job is withdrawn, so the caller waits for the workers still running a chunk but
  // never for a worker that has yet to wake. Workers poll for the next job a while before they
  // sleep, and the caller polls for the last chunks before it sleeps (kWorkerPoll, kCallerPoll).
  // A second caller while the pool is busy (two loops started from different threads) runs its
  // work alone on its own thread.
  void run(const std::function<void()>& work) {
    std::unique_lock<std::mutex> owner(runMutex_, std::try_to_lock);
    if (!owner.owns_lock()) {
      work();
      return;
    }
    {
      std::lock_guard<std::mutex> lock(mutex_);
      job_ = &work;
      generation_.fetch_add(1, std::memory_order_release);
    }
    wake_.notify_all();
    work();
    {
      std::lock_guard<std::mutex> lock(mutex_);
      job_ = nullptr;
    }
    if (pollFor(kCallerPoll, [this] { return running_.load(std::memory_order_acquire) == 0; })) return;
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [this] { return running_.load(std::memory_order_acquire) == 0; });
  }

 private:
  void loop() {
    uint64_t seen = 0;
    for (;;) {
      const std::function<void()>* job = nullptr;
      pollFor(kWorkerPoll, [&] {
        return stop_.load(std::memory_order_acquire) || generation_.load(std::memory_order_acquire) != seen;
      });
      {
        std::unique_lock<std::mutex> lock(mutex_);
        wake_.wait(lock, [&] { return stop_.load() || generation_.load() != seen; });
        if (stop_) return;
        seen = generation_.load();
        job = job_;
        if (!job) continue;  // withdrawn: the loop ended before this worker joined
        running_.fetch_add(1, std::memory_order_relaxed);
      }
      (*job)();
      if (running_.fetch_sub(1, std::memory_order_acq_rel) == 1) {
        // The caller may be asleep in done_.wait: take the lock so the notification cannot fall
        // between its test of running_ and its wait.
        std::lock_guard<std::mutex> lock(mutex_);
        done_.notify_one();
      }
    }
  }

  std::mutex runMutex_;  // held by the caller whose loop the workers run
  std::mutex mutex_;     // guards job_ and the sleeps on wake_ and done_
  std::condition_variable wake_, done_;
  std::vector<std::thread> workers_;
  const std::function<void()>* job_ = nullptr;
  std::atomic<uint64_t> generation_{0};
  std::atomic<int> running_{0};  // workers inside the current job
  std::atomic<bool> stop_{false};
};

// The pool for the current thread count (rebuilt when setThreadCount changes it). parallelFor is
// called from one thread at a time outside loops (the render's control flow is serial).
std::mutex gPoolMutex;
std::shared_ptr<WorkerPool> gPool;

std::shared_ptr<WorkerPool> poolFor(int threads) {
  std::lock_guard<std::mutex> lock(gPoolMutex);
  if (!gPool || gPool->helpers() != threads - 1) gPool = std::make_shared<WorkerPool>(threads - 1);
  return gPool;
}

}  // namespace

void setThreadCount(int threads) { gThreads = threads < 0 ? 0 : threads; }

int threadCount() {
  if (gThreads > 0) return gThreads;
  const unsigned hw = std::thread::hardware_concurrency();
  return hw ? static_cast<int>(hw) : 1;
}

LoopAccount loopAccountOfThisThread() { return tLoopAccount; }

namespace {

// The chunks of a loop: full chunks, then its last two chunks' worth in quarters, so the threads
// finish close together — a thread that takes the last full chunk while the others have none left
// keeps them waiting for up to a chunk's time. Fixed by n and the chunk alone, so which items a body
// call gets does not depend on the thread count. Loops of fewer than two chunks are left whole.
class ChunkPlan {
 public:
  ChunkPlan(size_t n, size_t chunk) : n_(n), chunk_(chunk) {
    const bool split = chunk >= 4 && n >= 2 * chunk;
    head_ = split ? n - 2 * chunk : n;
    headChunks_ = (head_ + chunk - 1) / chunk;
    tail_ = split ? chunk / 4 : chunk;
    count_ = headChunks_ + (n - head_ + tail_ - 1) / tail_;
  }
  size_t count() const { return count_; }
  size_t begin(size_t c) const { return c < headChunks_ ? c * chunk_ : head_ + (c - headChunks_) * tail_; }
  size_t end(size_t c) const {
    return c < headChunks_ ? std::min(head_, (c + 1) * chunk_) : std::min(n_, head_ + (c - headChunks_ + 1) * tail_);
  }

 private:
  size_t n_, chunk_, head_, headChunks_, tail_, count_;
};

}  // namespace

void parallelFor(size_t n, size_t chunk, const std::function<void(size_t, size_t)>& body) {
  if (n == 0) return;
  if (chunk == 0) chunk = 1;
  const ChunkPlan plan(n, chunk);
  const size_t chunks = plan.count();
  const int threads = threadCount();
  std::atomic<size_t> next{0};
  std::exception_ptr failure;
  std::mutex failureMutex;
  auto work = [&]() {
    for (;;) {
      const size_t c = next.fetch_add(1);
      if (c >= chunks) return;
      try {
        body(plan.begin(c), plan.end(c));
      } catch (...) {
        std::lock_guard<std::mutex> lock(failureMutex);
        if (!failure) failure = std::current_exception();
        next = chunks;  // stop handing out work
      }
    }
  };
  const bool timed = chunks > 1 && !tInsideLoop && !tTimingLoop;
  const double cpuStart = timed ? threadCpuSeconds() : 0.0;
  tTimingLoop |= timed;
  if (chunks <= 1 || threads <= 1 || tInsideLoop) {
    work();
  } else {
    const std::function<void()> job = [&] {
      tInsideLoop = true;
      work();
      tInsideLoop = false;
    };
    poolFor(threads)->run(job);
  }
  if (timed) {
    tTimingLoop = false;
    const double cpu = threadCpuSeconds() - cpuStart;
    tLoopAccount.cpuS += cpu;
    tLoopAccount.spanAt2S += cpu * double((chunks + 1) / 2) / double(chunks);
    ++tLoopAccount.loops;
  }
  if (failure) std::rethrow_exception(failure);
}

}  // namespace rc
