// The diffuse group's passes (render/diffuse_shading.h) against the scalar code they replace in the
// wave — the diffuse BSDF's evalPdf/eval and sample, the power heuristic as lightSampleUnshadowed
// weighs a light sample — bit for bit, on every instruction-set version this CPU runs. The whole
// wave against the scalar path tracer: tests/render/path_wavefront_test.cpp.
#include <gtest/gtest.h>

#include <cstring>
#include <iostream>

#include "core/rng.h"
#include "render/diffuse_shading.h"
#include "render/direct_light.h"
#include "render_test_scenes.h"

namespace rc {
namespace {

uint32_t bits(float f) {
  uint32_t u;
  std::memcpy(&u, &f, sizeof u);
  return u;
}

Vec3 uniformDirection(Rng& rng) {
  const float z = 1 - 2 * rng.nextFloat(), phi = 2 * kPi * rng.nextFloat(), r = std::sqrt(std::max(0.0f, 1 - z * z));
  return Vec3(r * std::cos(phi), r * std::sin(phi), z);
}

// One test vertex: a frame (half of them from a tangent), the viewer and the lane's throughput.
struct Vertex {
  Frame frame;
  Vec3 woWorld;
  Color rho, throughput;
};

// n vertices (not a multiple of any vector width: the loops' tails run too), with the special
// cases first: the viewer in the surface's plane and below it, and a black channel.
std::vector<Vertex> vertices(size_t n) {
  Rng rng(23);
  std::vector<Vertex> v;
  while (v.size() < n) {
    const Vec3 normal = uniformDirection(rng);
    Vertex x;
    x.frame = v.size() % 2 ? Frame::fromNormal(normal) : Frame::fromNormalTangent(normal, uniformDirection(rng));
    x.woWorld = uniformDirection(rng);
    if (v.size() == 0) x.woWorld = x.frame.n;
    if (v.size() == 1) x.woWorld = -x.frame.n;
    if (v.size() == 2) x.woWorld = x.frame.t;
    x.rho = Color(rng.nextFloat(), v.size() == 3 ? 0.0f : rng.nextFloat(), 0.9f);
    x.throughput = Color(0.5f + rng.nextFloat(), 2.0f * rng.nextFloat(), 1.0f);
    v.push_back(x);
  }
  return v;
}

constexpr size_t kVertices = 1031;

TEST(DiffuseShading, LightTermsAreTheScalarLightSampleBitForBit) {
  const std::vector<Vertex> vs = vertices(kVertices);
  Rng rng(5);
  // Light samples of every kind a LightSampler gives: area-like (finite pdf), delta, behind the
  // surface, a black one, one with an infinite density, and lanes without one.
  std::vector<LightSample> lights(kVertices);
  std::vector<bool> present(kVertices);
  for (size_t k = 0; k < kVertices; ++k) {
    LightSample& ls = lights[k];
    ls.wi = uniformDirection(rng);
    ls.radiance = Color(10.0f * rng.nextFloat(), k % 7 == 3 ? 0.0f : rng.nextFloat(), 1.0f);
    ls.pdf = k % 11 == 4 ? 0.0f : 5.0f * rng.nextFloat();
    ls.delta = k % 11 == 4;
    if (k % 13 == 6) ls.radiance = Color(0.0f);
    if (k % 17 == 8) ls.pdf = INFINITY;
    present[k] = k % 5 != 2;
  }
  for (int l = 0; l <= static_cast<int>(cpuSimdLevel()); ++l) {
    const SimdLevel level = static_cast<SimdLevel>(l);
    std::cout << "[ version  ] " << simdLevelName(level) << "\n";
    DiffuseGroup g;
    g.reset(kVertices);
    const Hit unused;
    for (size_t k = 0; k < kVertices; ++k) {
      const Vertex& x = vs[k];
      g.add(static_cast<uint32_t>(k), unused, x.frame, x.frame.toLocal(x.woWorld).z, x.rho, x.throughput, Vec2(0.5f));
      if (present[k]) g.setLight(k, lights[k]);
    }
    diffuseLightTerms(g, level);
    size_t on = 0;
    for (size_t k = 0; k < kVertices; ++k) {
      const Vertex& x = vs[k];
      const LightSample& ls = lights[k];
      // lightSampleUnshadowed's steps for one light sample beside one BSDF sample.
      const BsdfPtr bsdf = test::diffuse(x.rho);
      const Vec3 wo = x.frame.toLocal(x.woWorld), wi = x.frame.toLocal(ls.wi);
      const BsdfValue f = ls.delta ? BsdfValue{bsdf->eval(wo, wi), 0.0f} : bsdf->evalPdf(wo, wi);
      const bool expectOn = present[k] && !(maxComponent(f.f) <= 0.0f || maxComponent(ls.radiance) <= 0.0f);
      ASSERT_EQ(g.valueOn[k] != 0.0f, expectOn) << simdLevelName(level) << " vertex " << k;
      if (!expectOn) continue;
      ++on;
      const Color value = ls.delta ? f.f * ls.radiance : f.f * ls.radiance * powerHeuristic(ls.pdf, f.pdf);
      const Color expected = x.throughput * value;
      ASSERT_EQ(bits(g.valueR[k]), bits(expected.r)) << simdLevelName(level) << " vertex " << k;
      ASSERT_EQ(bits(g.valueG[k]), bits(expected.g)) << simdLevelName(level) << " vertex " << k;
      ASSERT_EQ(bits(g.valueB[k]), bits(expected.b)) << simdLevelName(level) << " vertex " << k;
    }
    EXPECT_GT(on, kVertices / 8);  // the values compared are real ones (wo and wi above: about a quarter)
  }
}

TEST(DiffuseShading, SampleTermsAreTheScalarSampleBitForBit) {
  const std::vector<Vertex> vs = vertices(kVertices);
  Rng rng(9);
  // The concentric map's special points first: its centre, the square's edges and diagonals.
  std::vector<Vec2> us = {Vec2(0.5f), Vec2(0.0f), Vec2(0.0f, 0.5f), Vec2(0.5f, 0.0f), Vec2(0.25f, 0.75f), Vec2(0.999f, 0.5f)};
  while (us.size() < kVertices) us.push_back(rng.next2D());
  for (int l = 0; l <= static_cast<int>(cpuSimdLevel()); ++l) {
    const SimdLevel level = static_cast<SimdLevel>(l);
    std::cout << "[ version  ] " << simdLevelName(level) << "\n";
    DiffuseGroup g;
    g.reset(kVertices);
    const Hit unused;
    for (size_t k = 0; k < kVertices; ++k) {
      const Vertex& x = vs[k];
      g.add(static_cast<uint32_t>(k), unused, x.frame, x.frame.toLocal(x.woWorld).z, x.rho, x.throughput, us[k]);
    }
    diffuseSampleTerms(g, level);
    size_t extended = 0;
    for (size_t k = 0; k < kVertices; ++k) {
      const Vertex& x = vs[k];
      // The wave's extend: DiffuseBsdf::sample, the throughput times its weight, ended unless finite and > 0.
      const std::optional<BsdfSample> bs = test::diffuse(x.rho)->sample(x.frame.toLocal(x.woWorld), 0.5f, us[k]);
      const Color throughput = bs ? x.throughput * bs->weight : x.throughput;
      const bool expectExtends = bs && maxComponent(throughput) > 0.0f && isFinite(throughput);
      ASSERT_EQ(g.extends[k] != 0.0f, expectExtends) << simdLevelName(level) << " vertex " << k;
      if (!expectExtends) continue;
      ++extended;
      const Vec3 dir = x.frame.toWorld(bs->wi);
      ASSERT_EQ(bits(g.dirX[k]), bits(dir.x)) << simdLevelName(level) << " vertex " << k;
      ASSERT_EQ(bits(g.dirY[k]), bits(dir.y)) << simdLevelName(level) << " vertex " << k;
      ASSERT_EQ(bits(g.dirZ[k]), bits(dir.z)) << simdLevelName(level) << " vertex " << k;
      ASSERT_EQ(bits(g.pdf[k]), bits(bs->pdf)) << simdLevelName(level) << " vertex " << k;
      ASSERT_EQ(bits(g.thrR[k]), bits(throughput.r)) << simdLevelName(level) << " vertex " << k;
      ASSERT_EQ(bits(g.thrG[k]), bits(throughput.g)) << simdLevelName(level) << " vertex " << k;
      ASSERT_EQ(bits(g.thrB[k]), bits(throughput.b)) << simdLevelName(level) << " vertex " << k;
    }
    EXPECT_GT(extended, kVertices / 3);
  }
}

}  // namespace
}  // namespace rc
