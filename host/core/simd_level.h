#pragma once
// The vector instruction sets that the hand-dispatched passes over a wave (EnvmapLight::lookupAdd,
// the diffuse shading passes of render/diffuse_shading.h) are compiled for besides the baseline
// x86-64 build, and the widest this CPU runs: the binary stays runnable everywhere (CI machines may
// have AVX2 only), and each pass picks its version at run time. Tests run every version the CPU
// supports against the scalar reference.
namespace rc {

enum class SimdLevel { Baseline = 0, Avx2 = 1, Avx512 = 2 };

// The widest level this CPU runs (Baseline off x86-64 and with compilers other than GCC).
SimdLevel cpuSimdLevel();
const char* simdLevelName(SimdLevel level);

}  // namespace rc
