#pragma once
// Memory the rcache final pass needs before it allocates it. The pass shades bands of whole film
// rows, at least one row at a time, so a row of W pixels at `spp` samples is one batch: with
// --spp 1048576 on a 32-pixel row that is 33 M samples and tens of GB of shade points and lookups.
// The estimate uses bytes per sample measured on the CLI test scene (bench/RESULTS.md, "Hostile
// inputs"); the budget is half the physical memory, or half the address-space limit when one is
// set (ulimit -v), whichever is smaller.
#include <cstddef>

namespace rc {

// Bytes of one final-pass sample (primary shade point, lookup, radiance, film splat).
constexpr double kFinalPassBytesPerSample = 1200.0;

// Throws rc::Error naming --spp when `samplesPerBatch` samples would not fit the budget.
void checkFinalPassMemory(size_t samplesPerBatch, int width, int spp);

}  // namespace rc
