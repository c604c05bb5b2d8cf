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

std::string mib(double bytes) {
  char s[32];
  std::snprintf(s, sizeof s, "%.0f MiB", bytes / double(1ull << 20));
  return s;
}

}  // namespace

size_t finalPassBatchSamples(int width, int spp) {
  const size_t row = static_cast<size_t>(std::max(1, width)) * static_cast<size_t>(std::max(1, spp));
  return std::min(row, std::max(kFinalPassMaxBatchSamples, static_cast<size_t>(std::max(1, width))));
}

void checkFinalPassMemory(int width, int spp) {
  const size_t batch = finalPassBatchSamples(width, spp);
  const double need = kFinalPassBytesPerSample * static_cast<double>(batch);
  const double budget = memoryBudgetBytes();
  if (need <= budget) return;
  const long long fits = static_cast<long long>(budget / (kFinalPassBytesPerSample * std::max(1, width)));
  throw Error("--spp " + std::to_string(spp) + ": the rcache final pass shades " + std::to_string(batch) +
              " samples at once (film rows of " + std::to_string(width) + " pixels), about " + mib(need) +
              ", more than the " + mib(budget) + " this process may use; at most --spp " +
              std::to_string(std::max(1LL, fits)) + " fits (or use --integrator path, which needs no such buffer)");
}

}  // namespace rc
