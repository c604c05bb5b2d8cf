#pragma once
// Where a phase's CPU time went, measured on the thread that runs the phase (the render's control
// thread): its own work outside parallel loops (serial: no other thread can help), its share inside
// them, and every other thread's (the pool's workers, and PoCL's kernel threads while the control
// thread waits for a kernel). At -t 1, serial / (serial + loops + other) is the phase's serial
// fraction, from which bench/thread_speedup.py --estimate predicts the N-thread speed-up.
#include <cstdint>

#include "core/cpu_clock.h"
#include "core/parallel.h"

namespace rc {

struct PhaseCpu {
  double serialS = 0.0, loopsS = 0.0, otherThreadsS = 0.0;
  double loopsSpanAt2S = 0.0;  // the loops' time on 2 threads (LoopAccount::spanAt2S)
  uint64_t loops = 0;  // parallel loops started (each wakes the pool's workers)
  uint64_t sleeps = 0;  // times the phase's thread slept (waiting for workers, kernels, locks)
  void add(const PhaseCpu& o) {
    serialS += o.serialS;
    loopsS += o.loopsS;
    loopsSpanAt2S += o.loopsSpanAt2S;
    otherThreadsS += o.otherThreadsS;
    loops += o.loops;
    sleeps += o.sleeps;
  }
};

// Started on the phase's thread; elapsed() read on the same thread.
class PhaseCpuMeter {
 public:
  PhaseCpuMeter()
      : process_(processCpuSeconds()), thread_(threadCpuSeconds()), sleeps_(threadSleeps()),
        loop_(loopAccountOfThisThread()) {}
  PhaseCpu elapsed() const {
    const LoopAccount now = loopAccountOfThisThread();
    const double thread = threadCpuSeconds() - thread_;
    PhaseCpu p;
    p.loopsS = now.cpuS - loop_.cpuS;
    p.loopsSpanAt2S = now.spanAt2S - loop_.spanAt2S;
    p.serialS = thread - p.loopsS;
    p.otherThreadsS = processCpuSeconds() - process_ - thread;
    p.loops = now.loops - loop_.loops;
    p.sleeps = static_cast<uint64_t>(threadSleeps() - sleeps_);
    return p;
  }

 private:
  double process_, thread_;
  long sleeps_;
  LoopAccount loop_;
};

}  // namespace rc
