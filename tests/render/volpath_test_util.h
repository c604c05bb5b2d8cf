#pragma once
// The volumetric path tracer's test scenes and estimates (render/volpath.h): a medium inside a
// unit sphere under a uniform sky, and per-ray means with their standard errors. Monte Carlo
// checks compare against the exact value within 5 standard errors of the same samples (false
// failure rate below 1e-6 per check; a bias beyond ~5σ fails).
#include <gtest/gtest.h>

#include "core/rng.h"
#include "render/volpath.h"
#include "render_test_scenes.h"

namespace rc {

inline BsdfPtr nullBsdf() {
  Properties props;
  props.pluginType = "null";
  return createBsdf(props, {});
}

inline BsdfPtr smoothDielectric(float intIor) {
  Properties props;
  props.pluginType = "dielectric";
  props.set("int_ior", test::floatProp(intIor));
  props.set("ext_ior", test::floatProp(1.0f));
  return createBsdf(props, {});
}

inline Medium homogeneous(const Color& sigmaT, const Color& albedo, PhaseFunction phase = {}, bool sampleEmitters = true) {
  Medium m;
  m.name = "test";
  m.sigmaT = sigmaT;
  m.albedo = makeConstVolume(albedo);
  m.phase = phase;
  m.sampleEmitters = sampleEmitters;
  return m;
}

// A unit sphere at the origin bounding `medium`, its surface `boundary`, under a constant sky of
// radiance 1.
inline Scene mediumSphere(const Medium& medium, BsdfPtr boundary) {
  Scene s;
  s.media.push_back(medium);
  Sphere sp;
  sp.radius = 1.0f;
  sp.bsdf = test::addBsdf(s, std::move(boundary));
  sp.media.interior = 0;
  s.spheres.push_back(sp);
  test::addEmitter(s, test::constantEmitter(Color(1.0f)));
  return s;
}

struct Estimate {
  Color mean{0.0f}, stderr_{0.0f};
};

// Per channel: the mean and standard error of `sample(rng)` over n draws, each with its own seed.
template <typename Sample>
Estimate meanOf(int n, uint64_t seed, Sample&& sample) {
  Color sum(0.0f), sum2(0.0f);
  for (int i = 0; i < n; ++i) {
    Rng rng(hashMix(seed, static_cast<uint64_t>(i)));
    const Color v = sample(rng);
    sum += v;
    sum2 += v * v;
  }
  Estimate e;
  e.mean = sum / float(n);
  e.stderr_ = glm::sqrt(glm::max(Color(0.0f), sum2 / float(n) - e.mean * e.mean) / float(n));
  return e;
}

// The radiance along `ray` (one volpath sample per draw).
inline Estimate estimate(const test::World& w, const IntegratorSettings& s, const Ray& ray, int n, uint64_t seed) {
  const RenderContext ctx = w.context();
  return meanOf(n, seed, [&](Rng& rng) { return volPathRadiance(ctx, s, ray, rng); });
}

inline void expectNear(const Estimate& e, const Color& exact, const char* what) {
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(e.mean[c], exact[c], 5.0f * e.stderr_[c] + 1e-4f) << what << " channel " << c;
}

}  // namespace rc
