// The diffuse group's passes (render/diffuse_shading.h) against the scalar code they replace in the
// wave — the diffuse BSDF's evalPdf/eval and sample, the power heuristic as lightSampleUnshadowed
// weighs a light sample, the wave's test of the new throughput — bit for bit, on every
// instruction-set version this CPU runs. The whole wave against the scalar path tracer:
// tests/render/path_wavefront_test.cpp.
#include <gtest/gtest.h>

#include <iostream>

#include "common/float_bits.h"
#include "core/rng.h"
#include "render/diffuse_shading.h"
#include "render/direct_light.h"
#include "render_test_scenes.h"

namespace rc {
namespace {

using test::bits;

Vec3 uniformDirection(Rng& rng) {
  const float z = 1 - 2 * rng.nextFloat(), phi = 2 * kPi * rng.nextFloat(), r = std::sqrt(std::max(0.0f, 1 - z * z));
  return Vec3(r * std::cos(phi), r * std::sin(phi), z);
}

// One test vertex: a frame (half of them from a tangent), the viewer, ρ, the lane's throughput, the
// BSDF sample's numbers and the light sample (if any).
struct Vertex {
  Frame frame;
  Vec3 woWorld;
  Color rho, throughput;
  Vec2 u;
  bool lit = false;
  LightSample light;
};

// n vertices (not a multiple of any vector width: the loops' tails run too), with the special cases:
// the viewer along the normal, below the surface and in its plane; a black channel of ρ; the
// concentric map's centre, the square's edges and diagonal; light samples of every kind a
// LightSampler gives — area-like (finite pdf), delta, behind the surface, black, with an infinite
// density — and lanes without one.
std::vector<Vertex> vertices(size_t n) {
  Rng rng(23);
  const Vec2 specialU[] = {Vec2(0.5f), Vec2(0.0f), Vec2(0.0f, 0.5f), Vec2(0.5f, 0.0f), Vec2(0.25f, 0.75f), Vec2(0.999f, 0.5f)};
  std::vector<Vertex> v;
  for (size_t k = 0; k < n; ++k) {
    const Vec3 normal = uniformDirection(rng);
    Vertex x;
    x.frame = k % 2 ? Frame::fromNormal(normal) : Frame::fromNormalTangent(normal, uniformDirection(rng));
    x.woWorld = k == 0 ? x.frame.n : k == 1 ? -x.frame.n : k == 2 ? x.frame.t : uniformDirection(rng);
    x.rho = Color(rng.nextFloat(), k == 3 ? 0.0f : rng.nextFloat(), 0.9f);
    x.throughput = Color(0.5f + rng.nextFloat(), 2.0f * rng.nextFloat(), 1.0f);
    x.u = k < 6 ? specialU[k] : rng.next2D();
    x.lit = k % 5 != 2;
    LightSample& ls = x.light;
    ls.wi = uniformDirection(rng);
    ls.radiance = k % 13 == 6 ? Color(0.0f) : Color(10.0f * rng.nextFloat(), k % 7 == 3 ? 0.0f : rng.nextFloat(), 1.0f);
    ls.delta = k % 11 == 4;
    ls.pdf = ls.delta ? 0.0f : k % 17 == 8 ? INFINITY : 5.0f * rng.nextFloat();
    v.push_back(x);
  }
  return v;
}

TEST(DiffuseShading, EveryVersionIsTheScalarLightAndBsdfSampleBitForBit) {
  const size_t n = 1031;
  const std::vector<Vertex> vs = vertices(n);
  for (int l = 0; l <= static_cast<int>(cpuSimdLevel()); ++l) {
    const SimdLevel level = static_cast<SimdLevel>(l);
    std::cout << "[ version  ] " << simdLevelName(level) << "\n";
    DiffuseGroup g;
    g.reset(n);
    const Hit unused;
    for (size_t k = 0; k < n; ++k) {
      const Vertex& x = vs[k];
      g.add(static_cast<uint32_t>(k), unused, x.frame, x.frame.toLocal(x.woWorld).z, x.rho, x.throughput, x.u);
      if (x.lit) g.setLight(k, x.light);
    }
    diffuseShadingTerms(g, level);
    size_t lightsOn = 0, extended = 0;
    for (size_t k = 0; k < n; ++k) {
      const Vertex& x = vs[k];
      const BsdfPtr bsdf = test::diffuse(x.rho);
      const Vec3 wo = x.frame.toLocal(x.woWorld);
      // lightSampleUnshadowed's steps for one light sample beside one BSDF sample.
      const LightSample& ls = x.light;
      const Vec3 wi = x.frame.toLocal(ls.wi);
      const BsdfValue f = ls.delta ? BsdfValue{bsdf->eval(wo, wi), 0.0f} : bsdf->evalPdf(wo, wi);
      const bool lightOn = x.lit && !(maxComponent(f.f) <= 0.0f || maxComponent(ls.radiance) <= 0.0f);
      ASSERT_EQ(g.valueOn[k] != 0.0f, lightOn) << simdLevelName(level) << " vertex " << k;
      if (lightOn) {
        ++lightsOn;
        const Color value = ls.delta ? f.f * ls.radiance : f.f * ls.radiance * powerHeuristic(ls.pdf, f.pdf);
        const Color expected = x.throughput * value;
        ASSERT_EQ(bits(g.valueR[k]), bits(expected.r)) << simdLevelName(level) << " vertex " << k;
        ASSERT_EQ(bits(g.valueG[k]), bits(expected.g)) << simdLevelName(level) << " vertex " << k;
        ASSERT_EQ(bits(g.valueB[k]), bits(expected.b)) << simdLevelName(level) << " vertex " << k;
      }
      // The wave's extend: DiffuseBsdf::sample, the throughput times its weight, ended unless finite and > 0.
      const std::optional<BsdfSample> bs = bsdf->sample(wo, 0.5f, x.u);
      const Color throughput = bs ? x.throughput * bs->weight : x.throughput;
      const bool extends = bs && maxComponent(throughput) > 0.0f && isFinite(throughput);
      ASSERT_EQ(g.extends[k] != 0.0f, extends) << simdLevelName(level) << " vertex " << k;
      if (!extends) continue;
      ++extended;
      const Vec3 dir = x.frame.toWorld(bs->wi);
      const float got[] = {g.dirX[k], g.dirY[k], g.dirZ[k], g.pdf[k], g.thrR[k], g.thrG[k], g.thrB[k]};
      const float want[] = {dir.x, dir.y, dir.z, bs->pdf, throughput.r, throughput.g, throughput.b};
      for (int q = 0; q < 7; ++q)
        ASSERT_EQ(bits(got[q]), bits(want[q])) << simdLevelName(level) << " vertex " << k << " output " << q;
    }
    // The values compared are real ones: wo and wi both above the surface in about a quarter of the
    // vertices, wo above in half.
    EXPECT_GT(lightsOn, n / 8);
    EXPECT_GT(extended, n / 3);
  }
}

}  // namespace
}  // namespace rc
