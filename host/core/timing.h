#pragma once
// Wall-clock phase timing for statistics (steady clock: immune to clock changes mid-render).
#include <chrono>

namespace rc {

using SteadyClock = std::chrono::steady_clock;

inline double secondsSince(SteadyClock::time_point start) {
  return std::chrono::duration<double>(SteadyClock::now() - start).count();
}

}  // namespace rc
