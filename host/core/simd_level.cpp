#include "core/simd_level.h"

namespace rc {

namespace {
SimdLevel detect() {
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
  __builtin_cpu_init();
  if (__builtin_cpu_supports("avx512f")) return SimdLevel::Avx512;
  if (__builtin_cpu_supports("avx2")) return SimdLevel::Avx2;
#endif
  return SimdLevel::Baseline;
}
}  // namespace

SimdLevel cpuSimdLevel() {
  static const SimdLevel level = detect();
  return level;
}

const char* simdLevelName(SimdLevel level) {
  switch (level) {
    case SimdLevel::Avx512: return "avx512f";
    case SimdLevel::Avx2: return "avx2";
    case SimdLevel::Baseline: break;
  }
  return "baseline";
}

}  // namespace rc
