#include "render/progressive.h"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <limits>
#include <mutex>
#include <thread>

#include "core/error.h"
#include "core/timing.h"
#include "render/film.h"

namespace rc {

namespace {

// Raises `stop` when the caller's cancel flag (SIGINT) is set, or — once armed — at the deadline.
// Polled: the signal handler can only set an atomic, and passes check `stop` between chunks anyway.
class PassStopper {
 public:
  PassStopper(const std::atomic<bool>* cancel, SteadyClock::time_point deadline)
      : cancel_(cancel), deadline_(deadline), thread_([this] { watch(); }) {}
  ~PassStopper() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      done_ = true;
    }
    wake_.notify_one();
    thread_.join();
  }
  std::atomic<bool>* flag() { return &stop_; }
  void arm() { armed_ = true; }
  bool cancelled() const { return cancel_ && cancel_->load(); }

 private:
  void watch() {
    std::unique_lock<std::mutex> lock(mutex_);
    while (!done_) {
      if (cancelled() || (armed_ && SteadyClock::now() >= deadline_)) stop_ = true;
      wake_.wait_for(lock, std::chrono::milliseconds(10));
    }
  }

  const std::atomic<bool>* cancel_;
  SteadyClock::time_point deadline_;
  std::atomic<bool> stop_{false}, armed_{false};
  bool done_ = false;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::thread thread_;  // last: started once the members it reads exist
};

}  // namespace

Image renderProgressive(Integrator& integrator, const RenderContext& ctx, const ProgressiveSettings& settings,
                        RenderStats& stats) {
  if (!(settings.seconds > 0.0)) throw Error("--time: the budget must be a positive number of seconds");
  if (ctx.options.adaptive.enabled())
    throw Error("--time: not with --adaptive (every pass takes spp samples per pixel)");
  const auto start = SteadyClock::now();
  const auto deadline = start + std::chrono::duration_cast<SteadyClock::duration>(
                                    std::chrono::duration<double>(settings.seconds));
  PassStopper stopper(ctx.cancel, deadline);
  RenderContext passCtx = ctx;
  passCtx.cancel = stopper.flag();

  std::unique_ptr<PassRender> session = integrator.beginPasses(passCtx, stats);
  // The passes' own progress restarts every pass: the bar shows the budget spent instead (the
  // session reads passCtx by reference, and no pass is running while it changes).
  if (ctx.progress)
    passCtx.progress = [&ctx, start, budget = settings.seconds](const std::string&, double, double) {
      ctx.progress("passes (--time)", std::min(secondsSince(start), budget), budget);
    };
  const auto passesStart = SteadyClock::now();
  Film film(ctx.scene.film);
  int passes = 0, dropped = 0;
  for (;;) {
    const auto passStart = SteadyClock::now();
    Film passFilm(ctx.scene.film);
    if (!session->addPass(passFilm, passes * session->passSpp())) {
      if (passes == 0) film.add(passFilm);  // a cut pass stays only when it is all there is
      else ++dropped;
      break;
    }
    film.add(passFilm);
    ++passes;
    stopper.arm();
    if (settings.maxPasses > 0 && passes >= settings.maxPasses) break;
    if (passes >= std::numeric_limits<int>::max() / session->passSpp() - 1) break;  // sample indices are ints
    // The next pass is started only if, lasting as long as this one, it ends within the budget.
    const auto now = SteadyClock::now();
    if (now + (now - passStart) > deadline) break;
  }
  Image image = session->finish(film, std::max(passes, 1), stopper.cancelled(), stats);
  stats.set("time_budget_s", settings.seconds);
  stats.set("passes", passes);
  stats.set("pass_spp", session->passSpp());
  stats.set("spp", double(passes) * session->passSpp());
  stats.set("passes_dropped", dropped);
  stats.set("time_passes_s", secondsSince(passesStart));
  stats.set("time_s", secondsSince(start));
  if (stopper.cancelled()) stats.set("interrupted", 1.0);
  return image;
}

}  // namespace rc
