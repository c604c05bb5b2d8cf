#pragma once
// The shading stage of a wave's bounce for its diffuse lanes (bsdf "diffuse": BsdfBatchKind::Diffuse),
// as passes over arrays (structure of arrays, one entry per lane of the group) in loops the compiler
// vectorises: the light sample's BSDF value, density and MIS weight, then the BSDF sample (cosine-
// weighted hemisphere), its weight and the updated throughput and direction. What stays per lane is
// what is not arithmetic on the group's arrays: drawing the numbers, the light sample itself
// (LightSampler::sample), the trigonometry of the concentric map (libm's cosf/sinf, which a vector
// polynomial would not round alike), the rays' origins and Russian roulette (render/path_wavefront.cpp).
//
// Every lane computes what lightSampleUnshadowed (render/direct_light.h) and DiffuseBsdf::sample
// compute for it, bit for bit: the arithmetic is the same inline definitions (bsdf/diffuse_lobe.h,
// bsdf/warp.h, powerHeuristic), and no version contracts a·b + c into an FMA (diffuse_shading.cpp).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/frame.h"
#include "core/simd_level.h"
#include "geometry/accel.h"
#include "render/light_sampler.h"

namespace rc {

struct DiffuseGroup {
  size_t size = 0;
  // Per entry: its lane in the wave, the vertex it shades (valid while the bounce is shaded), the light
  // sample (for its shadow ray).
  std::vector<uint32_t> lane;
  std::vector<const Hit*> hit;
  std::vector<LightSample> light;
  // Inputs: the shading frame's axes, the viewer's cos θo, ρ, the throughput at the vertex.
  std::vector<float> tx, ty, tz, bx, by, bz, nx, ny, nz;
  std::vector<float> woZ, rhoR, rhoG, rhoB, thrR, thrG, thrB;
  // The light sample (LightSample's wi, radiance and pdf; delta 1 for a delta light; on 0 where there
  // is none: no emitter, or a sample that lightSampleUnshadowed drops before evaluating the BSDF).
  std::vector<float> lightX, lightY, lightZ, lightR, lightG, lightB, lightPdf, lightDelta, lightOn;
  std::vector<float> u, v;  // the BSDF sample's 2-D number
  // Out of diffuseShadingTerms: what the light sample adds if its shadow ray is unoccluded (the
  // throughput included), and whether it adds anything (1) — lightSampleUnshadowed's value and result.
  std::vector<float> valueR, valueG, valueB, valueOn;
  // Also out of it: the sampled world direction and its density, the throughput times the sample's
  // weight (in thr*), and whether the path goes on along it (1: sampled, throughput finite and > 0).
  std::vector<float> dirX, dirY, dirZ, pdf, extends;
  // Scratch of diffuseShadingTerms: the concentric map's polar form and its trigonometry.
  std::vector<float> r, phi, cosPhi, sinPhi;

  // Room for n entries (kept between waves) and size 0.
  void reset(size_t n);
  // Appends an entry with its inputs; the light sample's fields are set by setLight. (Inline: every
  // diffuse vertex calls both.)
  size_t add(uint32_t laneId, const Hit& vertex, const Frame& frame, float cosThetaO, const Color& rho,
             const Color& throughput, const Vec2& bsdfNumbers);
  void setLight(size_t k, const LightSample& sample);
};

inline size_t DiffuseGroup::add(uint32_t laneId, const Hit& vertex, const Frame& frame, float cosThetaO,
                                const Color& rho, const Color& throughput, const Vec2& bsdfNumbers) {
  const size_t k = size++;
  lane[k] = laneId;
  hit[k] = &vertex;
  tx[k] = frame.t.x, ty[k] = frame.t.y, tz[k] = frame.t.z;
  bx[k] = frame.b.x, by[k] = frame.b.y, bz[k] = frame.b.z;
  nx[k] = frame.n.x, ny[k] = frame.n.y, nz[k] = frame.n.z;
  woZ[k] = cosThetaO;
  rhoR[k] = rho.r, rhoG[k] = rho.g, rhoB[k] = rho.b;
  thrR[k] = throughput.r, thrG[k] = throughput.g, thrB[k] = throughput.b;
  lightOn[k] = 0.0f;
  u[k] = bsdfNumbers.x;
  v[k] = bsdfNumbers.y;
  return k;
}

inline void DiffuseGroup::setLight(size_t k, const LightSample& sample) {
  light[k] = sample;
  lightX[k] = sample.wi.x, lightY[k] = sample.wi.y, lightZ[k] = sample.wi.z;
  lightR[k] = sample.radiance.r, lightG[k] = sample.radiance.g, lightB[k] = sample.radiance.b;
  lightPdf[k] = sample.pdf;
  lightDelta[k] = sample.delta ? 1.0f : 0.0f;
  lightOn[k] = 1.0f;
}

// For every entry: lightSampleUnshadowed's value (before the shadow ray; the light sample MIS-weighted
// as one light sample beside one BSDF sample) times the entry's throughput, then DiffuseBsdf::sample
// from the entry's numbers, the throughput times its weight, and the world direction.
void diffuseShadingTerms(DiffuseGroup& g, SimdLevel level = SimdLevel::Avx512);

}  // namespace rc
