// EnvmapLight::lookupAdd: the envmap looked up along a wave's directions in one pass over arrays.
//
// The loop body is EnvmapLight::lookup's (render/envmap_texels.h), one direction per vector lane;
// the texel and cell lookups become gathers. Baseline x86-64 has no gather, so the pass is also
// compiled for AVX2 and AVX-512 and picked at run time (core/simd_level.h).
// Each lane must compute what the scalar lookup computes, bit for bit (tests/render/
// envmap_light_test.cpp checks every version the CPU runs): no version may contract a·b + c into an
// FMA (one rounding instead of two) — the targets named here do not include FMA, and CMakeLists.txt
// builds this file with -ffp-contract=off as well. Its other two flags change no value:
// -fno-math-errno lets sqrt be the instruction alone (no branch to set errno), and
// -fno-trapping-math lets the selects of envmap_texels.h evaluate both of their sides (a division,
// a float → int conversion), which is what makes the loop body free of branches and so vectorisable.
#include "render/envmap_light.h"

#include <algorithm>

namespace rc {

namespace {

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define RC_HAVE_SIMD_VERSIONS 1
#endif

struct LookupOut {
  float* __restrict r;
  float* __restrict g;
  float* __restrict b;
  float* __restrict pdf;  // null: radiance alone
};

// The pass, inlined into each version below (compiled there for that version's instruction set).
[[gnu::always_inline]] inline void lookupAddLoop(const EnvmapTexels& t, const float* __restrict x,
                                                 const float* __restrict y, const float* __restrict z, size_t n,
                                                 float selectProb, const LookupOut& out) {
  const EnvmapTexels tab = t;  // a local copy: the loop's loads of the tables cannot alias its stores
  float* __restrict r = out.r;
  float* __restrict g = out.g;
  float* __restrict b = out.b;
  float* __restrict pdf = out.pdf;
  if (pdf) {
#pragma GCC ivdep
    for (size_t k = 0; k < n; ++k) {
      const Vec3 d = tab.local(Vec3(x[k], y[k], z[k]));
      const Vec4 c = tab.bilinear(envUv(d));
      r[k] += c.x;
      g[k] += c.y;
      b[k] += c.z;
      pdf[k] += selectProb * tab.density(c, EnvmapTexels::sinThetaOf(d));
    }
  } else {
#pragma GCC ivdep
    for (size_t k = 0; k < n; ++k) {
      const Vec4 c = tab.bilinear(envUv(tab.local(Vec3(x[k], y[k], z[k]))));
      r[k] += c.x;
      g[k] += c.y;
      b[k] += c.z;
    }
  }
}

void lookupAddBaseline(const EnvmapTexels& t, const float* x, const float* y, const float* z, size_t n,
                       float selectProb, const LookupOut& out) {
  lookupAddLoop(t, x, y, z, n, selectProb, out);
}

#ifdef RC_HAVE_SIMD_VERSIONS
[[gnu::target("avx2")]] void lookupAddAvx2(const EnvmapTexels& t, const float* x, const float* y, const float* z,
                                           size_t n, float selectProb, const LookupOut& out) {
  lookupAddLoop(t, x, y, z, n, selectProb, out);
}

[[gnu::target("avx512f")]] void lookupAddAvx512(const EnvmapTexels& t, const float* x, const float* y,
                                                const float* z, size_t n, float selectProb, const LookupOut& out) {
  lookupAddLoop(t, x, y, z, n, selectProb, out);
}
#endif

}  // namespace

void EnvmapLight::lookupAdd(const float* x, const float* y, const float* z, size_t n, float selectProb, float* r,
                            float* g, float* b, float* pdf, SimdLevel level) const {
  const LookupOut out{r, g, b, pdf};
  const SimdLevel run = std::min(level, cpuSimdLevel());
#ifdef RC_HAVE_SIMD_VERSIONS
  if (run == SimdLevel::Avx512) return lookupAddAvx512(tables(), x, y, z, n, selectProb, out);
  if (run == SimdLevel::Avx2) return lookupAddAvx2(tables(), x, y, z, n, selectProb, out);
#endif
  (void)run;
  lookupAddBaseline(tables(), x, y, z, n, selectProb, out);
}

}  // namespace rc
