#include "cache/final_pass_memory.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/error.h"

namespace rc {

namespace {

double memoryBudgetBytes() {
  const double pages = static_cast<double>(sysconf(_SC_PHYS_PAGES)), pageSize = static_cast<double>(sysconf(_SC_PAGESIZE));
  double budget = pages > 0 && pageSize > 0 ? 0.5 * pages * pageSize : 8.0 * (1ull << 30);
  rlimit as{};
  if (getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY) budget = std::min(budget, 0.5 * double(as.rlim_cur));
  return budget;
}

std::string gib(double bytes) {
  char s[32];
  std::snprintf(s, sizeof s, "%.1f GiB", bytes / double(1ull << 30));
  return s;
}

}  // namespace

void checkFinalPassMemory(size_t samplesPerBatch, int width, int spp) {
  const double need = kFinalPassBytesPerSample * static_cast<double>(samplesPerBatch);
  const double budget = memoryBudgetBytes();
  if (need <= budget) return;
  const long long fits = static_cast<long long>(budget / (kFinalPassBytesPerSample * std::max(1, width)));
  throw Error("--spp " + std::to_string(spp) + ": the rcache final pass shades a film row of " + std::to_string(width) +
              " pixels at once, about " + gib(need) + ", more than the " + gib(budget) +
              " this process may use; at most --spp " + std::to_string(std::max(1LL, fits)) +
              " fits (or use --integrator path, which needs no such buffer)");
}

}  // namespace rc
