#pragma once
// Parallel sort whose result is std::sort's whatever the thread count: fixed runs sorted in
// parallel, then merged pairwise in rounds (the runs and the merges do not depend on threads).
// For element types where elements that compare equal are identical (e.g. pairs with a unique
// member), every correct sort gives the same sequence, so the result is also the serial one's.
#include <algorithm>
#include <cstddef>
#include <vector>

#include "core/parallel.h"

namespace rc {

// Elements per initially sorted run: a task's worth of work, and few merge rounds.
constexpr size_t kSortRun = 8192;

template <class T>
void parallelSort(std::vector<T>& v) {
  const size_t n = v.size();
  if (n <= kSortRun) {
    std::sort(v.begin(), v.end());
    return;
  }
  const size_t runs = (n + kSortRun - 1) / kSortRun;
  parallelFor(runs, 1, [&](size_t r0, size_t r1) {
    for (size_t r = r0; r < r1; ++r) std::sort(v.begin() + r * kSortRun, v.begin() + std::min(n, (r + 1) * kSortRun));
  });
  std::vector<T> merged(n);
  for (size_t width = kSortRun; width < n; width *= 2) {
    const size_t pairs = (n + 2 * width - 1) / (2 * width);
    parallelFor(pairs, 1, [&](size_t p0, size_t p1) {
      for (size_t p = p0; p < p1; ++p) {
        const size_t lo = p * 2 * width, mid = std::min(n, lo + width), hi = std::min(n, lo + 2 * width);
        std::merge(v.begin() + lo, v.begin() + mid, v.begin() + mid, v.begin() + hi, merged.begin() + lo);
      }
    });
    v.swap(merged);
  }
}

}  // namespace rc
