#pragma once
// World-aligned copies of records (interpolation frame "world", docs/ARCHITECTURE.md §Conventions):
// a record's coefficients live in its own frame F = (t, b, n); the copy satisfies
// f_world(ω) = f_local(Fω) = f_local(R⁻¹ω) with R = Fᵀ, i.e. R's columns are the record's axes.
// Made once when records enter a cache, by the engine for new records and by the cache file
// loader for loaded ones.
#include <vector>

#include "cache/radiance_cache.h"

namespace rc {

class ShBackend;

struct WorldCopies {
  std::vector<float> lambda, gradT, gradB;  // [records][3][n²], like the record-frame arrays
};

// Rotates Λ, ∂Λ/∂t and ∂Λ/∂b of `infos.size()` records of SH order `order` into the world frame
// (one rotate batch of 3·records).
WorldCopies rotateToWorld(ShBackend& backend, int order, const std::vector<RecordInfo>& infos,
                          const std::vector<float>& lambda, const std::vector<float>& gradT,
                          const std::vector<float>& gradB);

}  // namespace rc
