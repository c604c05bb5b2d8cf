#pragma once
// The vector instruction sets that the hand-dispatched passes over a wave (EnvmapLight::lookupAdd)
// are compiled for besides the baseline x86-64 build, and the widest this CPU runs: the binary
// stays runnable everywhere (CI machines may have AVX2 only), and each pass picks its version at
// run time. Tests run every version the CPU supports against the scalar reference.
namespace rc {

enum class SimdLevel { Baseline = 0, Avx2 = 1, Avx512 = 2 };

// The widest level this CPU runs (Baseline off x86-64 and with compilers other than GCC).
SimdLevel cpuSimdLevel();
const char* simdLevelName(SimdLevel level);

// Runs `pass` (a lambda marked [[gnu::always_inline]], so that it is compiled inside the version
// that calls it) compiled for the widest instruction set up to `level` that this CPU runs. A pass's
// loops over lanes vectorise there; the file that calls this states the flags its passes need.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define RC_SIMD_VERSIONS 1
template <class Pass>
[[gnu::target("avx2")]] void runAvx2(const Pass& pass) {
  pass();
}
template <class Pass>
[[gnu::target("avx512f")]] void runAvx512(const Pass& pass) {
  pass();
}
#endif
template <class Pass>
void runBaseline(const Pass& pass) {
  pass();
}
template <class Pass>
void runSimd(SimdLevel level, const Pass& pass) {
  const SimdLevel run = level < cpuSimdLevel() ? level : cpuSimdLevel();
#ifdef RC_SIMD_VERSIONS
  if (run == SimdLevel::Avx512) return runAvx512(pass);
  if (run == SimdLevel::Avx2) return runAvx2(pass);
#endif
  (void)run;
  runBaseline(pass);
}

}  // namespace rc
