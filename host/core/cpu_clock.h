#pragma once
// CPU time, which waiting for a core does not add to: the measure of where work goes on a machine
// shared with other processes (bench/RESULTS.md, tenth session), where wall-clock time is not.
#include <sys/resource.h>
#include <time.h>

namespace rc {

inline double cpuSeconds(clockid_t clock) {
  timespec t{};
  clock_gettime(clock, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}
inline double processCpuSeconds() { return cpuSeconds(CLOCK_PROCESS_CPUTIME_ID); }  // all threads
inline double threadCpuSeconds() { return cpuSeconds(CLOCK_THREAD_CPUTIME_ID); }    // the caller's

// Times the calling thread has gone to sleep (voluntary context switches: a lock, a condition
// variable, a kernel's completion); each costs a scheduler wake-up before it runs again.
inline long threadSleeps() {
  rusage u{};
  getrusage(RUSAGE_THREAD, &u);
  return u.ru_nvcsw;
}

}  // namespace rc
