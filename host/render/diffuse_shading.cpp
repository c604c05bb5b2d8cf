// The diffuse lanes of a bounce shaded in passes over arrays (render/diffuse_shading.h).
//
// Each pass's body is one inline loop compiled three times (baseline x86-64, AVX2, AVX-512) and
// picked at run time (core/simd_level.h), as EnvmapLight::lookupAdd is. Each lane must compute what
// the scalar code computes, bit for bit (tests/render/diffuse_shading_test.cpp checks every version
// the CPU runs): no version may contract a·b + c into an FMA — the targets named here do not include
// FMA, and CMakeLists.txt builds this file with -ffp-contract=off as well. Its other two flags change
// no value: -fno-math-errno lets sqrt be the instruction alone, and -fno-trapping-math lets the
// selects evaluate both of their sides (a division by a zero radius), which is what makes the loop
// bodies free of branches and so vectorisable.
#include "render/diffuse_shading.h"

#include <algorithm>
#include <cmath>

#include "bsdf/diffuse_lobe.h"
#include "bsdf/warp.h"
#include "render/direct_light.h"

namespace rc {

namespace {

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define RC_HAVE_SIMD_VERSIONS 1
#endif

template <class T>
void fit(std::vector<T>& v, size_t n) {
  if (v.size() < n) v.resize(n);
}

// ---- The concentric map's polar form (before the trigonometry) ----
[[gnu::always_inline]] inline void diskLoop(DiffuseGroup& g) {
  const size_t n = g.size;
  const float* __restrict u = g.u.data();
  const float* __restrict v = g.v.data();
  float* __restrict r = g.r.data();
  float* __restrict phi = g.phi.data();
#pragma GCC ivdep
  for (size_t k = 0; k < n; ++k) {
    const DiskPolar d = squareToDiskPolar(Vec2(u[k], v[k]));
    // At the centre r is +0 and φ (0/0) is set to 0: r·cos φ and r·sin φ are then +0, the point
    // squareToUniformDiskConcentric returns there, with no select left for the next pass.
    r[k] = d.r;
    phi[k] = d.centre ? 0.0f : d.phi;
  }
}

// ---- The light sample's value and the BSDF sample, one pass ----
// (Plain floats, and selects of values rather than of constants or of bools combined with & or &&:
// a Color local, either of those, or std::fmax's || keeps GCC 12 from vectorising the loop.)
[[gnu::always_inline]] inline void shadingLoop(DiffuseGroup& g) {
  const size_t n = g.size;
  const float *__restrict tx = g.tx.data(), *__restrict ty = g.ty.data(), *__restrict tz = g.tz.data();
  const float *__restrict bx = g.bx.data(), *__restrict by = g.by.data(), *__restrict bz = g.bz.data();
  const float *__restrict nx = g.nx.data(), *__restrict ny = g.ny.data(), *__restrict nz = g.nz.data();
  const float *__restrict woZ = g.woZ.data();
  const float *__restrict rhoR = g.rhoR.data(), *__restrict rhoG = g.rhoG.data(), *__restrict rhoB = g.rhoB.data();
  const float *__restrict lx = g.lightX.data(), *__restrict ly = g.lightY.data(), *__restrict lz = g.lightZ.data();
  const float *__restrict lr = g.lightR.data(), *__restrict lg = g.lightG.data(), *__restrict lb = g.lightB.data();
  const float *__restrict lpdf = g.lightPdf.data(), *__restrict ldelta = g.lightDelta.data(), *__restrict lon = g.lightOn.data();
  const float *__restrict r = g.r.data(), *__restrict cosPhi = g.cosPhi.data(), *__restrict sinPhi = g.sinPhi.data();
  float *__restrict thrR = g.thrR.data(), *__restrict thrG = g.thrG.data(), *__restrict thrB = g.thrB.data();
  float *__restrict valueR = g.valueR.data(), *__restrict valueG = g.valueG.data(), *__restrict valueB = g.valueB.data();
  float *__restrict valueOn = g.valueOn.data();
  float *__restrict dirX = g.dirX.data(), *__restrict dirY = g.dirY.data(), *__restrict dirZ = g.dirZ.data();
  float *__restrict pdf = g.pdf.data(), *__restrict extends = g.extends.data();
#pragma GCC ivdep
  for (size_t k = 0; k < n; ++k) {
    // -- Light sample (lightSampleUnshadowed): frame.toLocal(wi).z is all the lobe reads of wi.
    const float c = lambertCosineTerm(woZ[k], lx[k] * nx[k] + ly[k] * ny[k] + lz[k] * nz[k]);
    const float fR = rhoR[k] * c, fG = rhoG[k] * c, fB = rhoB[k] * c;  // DiffuseBsdf::eval; its pdf is c
    // f·Le/pdf, MIS-weighted unless the light is a delta one; then times the throughput.
    const float w = powerHeuristic(lpdf[k], c);
    const bool weighted = ldelta[k] == 0.0f;
    const float vR = fR * lr[k], vG = fG * lg[k], vB = fB * lb[k];
    valueR[k] = thrR[k] * (weighted ? vR * w : vR);
    valueG[k] = thrG[k] * (weighted ? vG * w : vG);
    valueB[k] = thrB[k] * (weighted ? vB * w : vB);
    const float fMax = maxComponent(fR, fG, fB), radianceMax = maxComponent(lr[k], lg[k], lb[k]);
    valueOn[k] = lon[k] != 0.0f ? (fMax <= 0.0f ? 0.0f : (radianceMax <= 0.0f ? 0.0f : 1.0f)) : 0.0f;
    // -- BSDF sample (DiffuseBsdf::sample): squareToCosineHemisphere from the polar form, as
    // squareToUniformDiskConcentric finishes it.
    const float px = r[k] * cosPhi[k], py = r[k] * sinPhi[k];
    const float pz = diskToHemisphereZ(px, py);
    const float density = squareToCosineHemispherePdf(Vec3(px, py, pz));
    // The sample's weight is ρ; the wave then ends the path unless the throughput stays finite and > 0.
    const float tR = thrR[k] * rhoR[k], tG = thrG[k] * rhoG[k], tB = thrB[k] * rhoB[k];
    thrR[k] = tR;
    thrG[k] = tG;
    thrB[k] = tB;
    // frame.toWorld(wi) = (t·x + b·y) + n·z.
    dirX[k] = tx[k] * px + bx[k] * py + nx[k] * pz;
    dirY[k] = ty[k] * px + by[k] * py + ny[k] * pz;
    dirZ[k] = tz[k] * px + bz[k] * py + nz[k] * pz;
    pdf[k] = density;
    // Sampled (wo above, density > 0), then the throughput finite and > 0: its largest component,
    // zeroed by each test that fails.
    const float finiteMax = isFinite(tR, tG, tB) ? maxComponent(tR, tG, tB) : 0.0f;
    const float sampledMax = woZ[k] > 0.0f ? (density > 0.0f ? finiteMax : 0.0f) : 0.0f;
    extends[k] = sampledMax > 0.0f ? 1.0f : 0.0f;
  }
}

// libm's trigonometry per lane: the scalar map's std::cos and std::sin, the same calls.
void trigonometry(DiffuseGroup& g) {
  for (size_t k = 0; k < g.size; ++k) {
    g.cosPhi[k] = std::cos(g.phi[k]);
    g.sinPhi[k] = std::sin(g.phi[k]);
  }
}

// A pass's versions: its loop compiled for baseline x86-64, AVX2 and AVX-512 (or baseline alone).
struct PassVersions {
  void (*baseline)(DiffuseGroup&);
  void (*avx2)(DiffuseGroup&);
  void (*avx512)(DiffuseGroup&);

  // Runs the version for the narrower of `level` and what this CPU runs.
  void operator()(SimdLevel level, DiffuseGroup& g) const {
    const SimdLevel run = std::min(level, cpuSimdLevel());
    if (run == SimdLevel::Avx512) return avx512(g);
    if (run == SimdLevel::Avx2) return avx2(g);
    baseline(g);
  }
};

#ifdef RC_HAVE_SIMD_VERSIONS
#define RC_PASS_VERSIONS(name, loop)                                   \
  void name##Baseline(DiffuseGroup& g) { loop(g); }                    \
  [[gnu::target("avx2")]] void name##Avx2(DiffuseGroup& g) { loop(g); } \
  [[gnu::target("avx512f")]] void name##Avx512(DiffuseGroup& g) { loop(g); } \
  constexpr PassVersions name{name##Baseline, name##Avx2, name##Avx512};
#else
#define RC_PASS_VERSIONS(name, loop)                \
  void name##Baseline(DiffuseGroup& g) { loop(g); } \
  constexpr PassVersions name{name##Baseline, name##Baseline, name##Baseline};
#endif
RC_PASS_VERSIONS(diskPass, diskLoop)
RC_PASS_VERSIONS(shadingPass, shadingLoop)
#undef RC_PASS_VERSIONS

}  // namespace

void DiffuseGroup::reset(size_t n) {
  size = 0;
  fit(lane, n);
  fit(hit, n);
  fit(light, n);
  for (std::vector<float>* a : {&tx, &ty, &tz, &bx, &by, &bz, &nx, &ny, &nz, &woZ, &rhoR, &rhoG, &rhoB, &thrR, &thrG,
                                &thrB, &lightX, &lightY, &lightZ, &lightR, &lightG, &lightB, &lightPdf, &lightDelta,
                                &lightOn, &u, &v, &valueR, &valueG, &valueB, &valueOn, &dirX, &dirY, &dirZ, &pdf,
                                &extends, &r, &phi, &cosPhi, &sinPhi})
    fit(*a, n);
}

void diffuseShadingTerms(DiffuseGroup& g, SimdLevel level) {
  diskPass(level, g);
  trigonometry(g);
  shadingPass(level, g);
}

}  // namespace rc
