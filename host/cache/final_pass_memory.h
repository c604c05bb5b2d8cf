#pragma once
// Memory the rcache final pass needs before it allocates it. The pass shades bands of whole film
// rows; a row whose samples exceed kFinalPassMaxBatchSamples is shaded in slices of each pixel's
// samples (final_pass.cpp), so the batch, and the memory, no longer grows with --spp (one row at
// --spp 1048576 on a 32-pixel film used to be 33 M samples, tens of GB). The estimate uses bytes
// per sample measured on the CLI test scene (bench/RESULTS.md, "Hostile inputs"); the budget is
// half the physical memory, or half the address-space limit when one is set (ulimit -v),
// whichever is smaller.
#include <cstddef>

namespace rc {

// Bytes of one final-pass sample (primary shade point, lookup, radiance, film splat).
constexpr double kFinalPassBytesPerSample = 1200.0;

// Largest batch of samples shaded at once (~300 MB), unless one sample for each pixel of a row
// is more.
constexpr size_t kFinalPassMaxBatchSamples = 262144;

// Samples the final pass holds at once for a film `width` pixels wide at `spp` samples a pixel.
size_t finalPassBatchSamples(int width, int spp);

// Throws rc::Error naming --spp when the final pass's batch would not fit the budget.
void checkFinalPassMemory(int width, int spp);

}  // namespace rc
