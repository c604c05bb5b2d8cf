#pragma once
// Order-preserving parallel selection: the indices i < n with keep(i), ascending, computed in
// fixed blocks (flags and counts per block, a prefix sum, then each block writes its own slice),
// so the result is the serial loop's whatever the thread count. The serial version of these
// loops over hundreds of thousands of record-ray hits left the second thread idle.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/parallel.h"

namespace rc {

// Indices per block of the selection: large enough that a block is worth a task, small enough
// that a few hundred thousand points still split between threads.
constexpr size_t kSelectBlock = 4096;

template <class Keep>
std::vector<size_t> parallelSelect(size_t n, Keep&& keep) {
  const size_t blocks = (n + kSelectBlock - 1) / kSelectBlock;
  std::vector<uint8_t> flag(n);
  std::vector<size_t> start(blocks + 1, 0);
  parallelFor(blocks, 1, [&](size_t b0, size_t b1) {
    for (size_t b = b0; b < b1; ++b) {
      const size_t end = std::min(n, (b + 1) * kSelectBlock);
      size_t count = 0;
      for (size_t i = b * kSelectBlock; i < end; ++i) count += (flag[i] = keep(i) ? 1 : 0);
      start[b + 1] = count;
    }
  });
  for (size_t b = 0; b < blocks; ++b) start[b + 1] += start[b];
  std::vector<size_t> out(start[blocks]);
  parallelFor(blocks, 1, [&](size_t b0, size_t b1) {
    for (size_t b = b0; b < b1; ++b) {
      const size_t end = std::min(n, (b + 1) * kSelectBlock);
      size_t k = start[b];
      for (size_t i = b * kSelectBlock; i < end; ++i)
        if (flag[i]) out[k++] = i;
    }
  });
  return out;
}

// The same over a list of indices: the elements x of `from` with keep(x), in order.
template <class Keep>
std::vector<size_t> parallelSelectFrom(const std::vector<size_t>& from, Keep&& keep) {
  std::vector<size_t> pos = parallelSelect(from.size(), [&](size_t j) { return keep(from[j]); });
  parallelFor(pos.size(), kSelectBlock, [&](size_t b, size_t e) {
    for (size_t j = b; j < e; ++j) pos[j] = from[pos[j]];
  });
  return pos;
}

}  // namespace rc
