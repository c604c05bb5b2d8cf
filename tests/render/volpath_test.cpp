// The volumetric path tracer (render/volpath.h) on media whose answer is known in closed form, and
// the phase functions (render/phase_function.h) against their definitions.
// Monte Carlo checks: volpath_test_util.h.
#include <gtest/gtest.h>

#include "core/rng.h"
#include "render/phase_function.h"
#include "render/volpath.h"
#include "volpath_test_util.h"

namespace rc {
namespace {

using test::rayAt;

// A purely absorbing sphere with an invisible boundary in front of the sky: exp(−σt·chord) per
// channel, for the camera path (free-flight sampling) and, exactly, for a shadow ray.
TEST(Volpath, AbsorbingSphereTransmitsBeersLaw) {
  const Color sigma(0.5f, 1.0f, 2.0f);
  const test::World w(mediumSphere(homogeneous(sigma, Color(0.0f)), nullBsdf()));
  const RenderContext ctx = w.context();
  for (const float b : {0.0f, 0.6f}) {  // impact parameter: chord 2·sqrt(1 − b²)
    const float chord = 2.0f * std::sqrt(1.0f - b * b);
    const Color exact = glm::exp(-sigma * chord);
    const Ray ray = rayAt({b, 0.0f, 5.0f}, {b, 0.0f, 0.0f});
    expectNear(estimate(w, IntegratorSettings(), ray, 20000, 1), exact, "camera path");
    Rng rng(1);  // a homogeneous medium draws nothing
    const Color tr = shadowTransmittance(ctx, ray, -1, rng);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(tr[c], exact[c], 1e-4f * exact[c] + 1e-6f) << "shadow ray, channel " << c;
  }
  // An opaque boundary blocks shadow rays (only null surfaces pass them).
  const test::World opaque(mediumSphere(homogeneous(sigma, Color(0.0f)), test::diffuse(Color(0.5f))));
  Rng rng(1);
  EXPECT_EQ(shadowTransmittance(opaque.context(), rayAt({0, 0, 5}, {0, 0, 0}), -1, rng), Color(0.0f));
}

// Shadow rays pass null-like surfaces by Mitsuba's eval_null_transmission: a mask lets 1 − opacity
// through, two masks the product, and an opaque surface behind stops everything.
TEST(Volpath, ShadowRaysPassMasksByTheirOpenShare) {
  Properties props;
  props.pluginType = "mask";
  props.set("opacity", test::floatProp(0.3f));
  Scene s;
  const int mask = test::addBsdf(s, createBsdf(props, {test::diffuse(Color(0.5f))}));
  s.meshes.push_back(test::quad({-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}, mask));
  s.meshes.push_back(test::quad({-1, -1, 2}, {1, -1, 2}, {1, 1, 2}, {-1, 1, 2}, mask));
  s.meshes.push_back(test::quad({-1, -1, 4}, {1, -1, 4}, {1, 1, 4}, {-1, 1, 4}, test::addBsdf(s, test::diffuse(Color(0.5f)))));
  const test::World w(std::move(s));
  Ray ray = rayAt({0, 0, 0}, {0, 0, 1});
  Rng rng(1);
  ray.tMax = 1.5f;
  EXPECT_NEAR(shadowTransmittance(w.context(), ray, -1, rng).g, 0.7f, 1e-6f);
  ray.tMax = 3.0f;
  EXPECT_NEAR(shadowTransmittance(w.context(), ray, -1, rng).g, 0.49f, 1e-6f);
  ray.tMax = 5.0f;
  EXPECT_EQ(shadowTransmittance(w.context(), ray, -1, rng), Color(0.0f));
}

// A lossless medium (albedo 1) inside a lossless boundary under a uniform sky of radiance 1 sees
// radiance 1 from everywhere: scattering, next-event estimation with transmittance, MIS, the
// boundary's refraction and Russian roulette (unbounded max_depth) must all balance.
TEST(Volpath, LosslessMediumFurnaceIsOne) {
  PhaseFunction hg;
  hg.type = PhaseFunction::Type::HenyeyGreenstein;
  hg.g = 0.7f;
  struct Case {
    const char* name;
    PhaseFunction phase;
    bool sampleEmitters;
    BsdfPtr boundary;
  };
  const Case cases[] = {{"isotropic, light sampling, null boundary", PhaseFunction(), true, nullBsdf()},
                        {"hg 0.7, no light sampling, null boundary", hg, false, nullBsdf()},
                        {"hg 0.7, light sampling, dielectric 1.5", hg, true, smoothDielectric(1.5f)}};
  IntegratorSettings settings;  // max_depth −1, rr_depth 5
  for (const Case& c : cases) {
    const test::World w(mediumSphere(homogeneous(Color(0.5f, 1.0f, 3.0f), Color(1.0f), c.phase, c.sampleEmitters), c.boundary));
    for (const float b : {0.0f, 0.7f})
      expectNear(estimate(w, settings, rayAt({b, 0.1f, 4.0f}, {b, 0.1f, 0.0f}), 30000, 2), Color(1.0f), c.name);
  }
}

// The camera inside a medium (the sensor's medium), nothing else in the scene: an absorbing medium
// everywhere shows black, an empty one (σt = 0) the sky.
TEST(Volpath, CameraMediumAttenuatesEverything) {
  Scene s;
  s.media.push_back(homogeneous(Color(0.0f, 0.3f, 0.0f), Color(0.0f)));
  s.cameraMedium = 0;
  test::addEmitter(s, test::constantEmitter(Color(1.0f)));
  const test::World w(std::move(s));
  EXPECT_TRUE(sceneUsesMedia(w.scene));
  expectNear(estimate(w, IntegratorSettings(), rayAt({0, 0, 0}, {0, 0, 1}), 2000, 3), Color(1.0f, 0.0f, 1.0f), "fog");
}

// Mitsuba's volpath, volpathmis and prbvolpath (the differentiable one, rendered as its primal
// image) follow media, its path, prb and direct render surfaces only; rcache renders what the file's
// integrator would.
TEST(Volpath, OnlyVolumetricIntegratorsFollowMedia) {
  Scene s = mediumSphere(homogeneous(Color(1.0f), Color(0.5f)), nullBsdf());
  s.integrator.type = "volpath";
  EXPECT_TRUE(followsMedia(s, "volpath"));
  EXPECT_TRUE(followsMedia(s, "volpathmis"));
  EXPECT_TRUE(followsMedia(s, "prbvolpath"));
  EXPECT_FALSE(followsMedia(s, "prb"));
  EXPECT_TRUE(followsMedia(s, "rcache"));
  EXPECT_FALSE(followsMedia(s, "path"));
  EXPECT_FALSE(followsMedia(s, "direct"));
  s.integrator.type = "path";
  EXPECT_FALSE(followsMedia(s, "rcache"));
  s.spheres[0].media = MediumInterface();  // the medium defined but not referred to
  EXPECT_FALSE(followsMedia(s, "volpath"));
}

TEST(Volpath, MaxDepthCountsScatteringNotNullCrossings) {
  // max_depth 1: only what the camera ray finds unscattered — the sky through the null boundary
  // (which does not count as a vertex), attenuated along the chord of 2.
  const Color sigma(1.0f);
  const test::World w(mediumSphere(homogeneous(sigma, Color(1.0f)), nullBsdf()));
  IntegratorSettings settings;
  settings.maxDepth = 1;
  expectNear(estimate(w, settings, rayAt({0, 0, 5}, {0, 0, 0}), 20000, 4), glm::exp(-2.0f * sigma), "max_depth 1");
}

// HG (and isotropic) densities integrate to 1 over the sphere, the sampled density is the value,
// and samples have the mean cosine g against the arriving direction (HG's defining moment).
TEST(PhaseFunction, HenyeyGreensteinIsNormalisedAndSamplesItsDensity) {
  const Vec3 wi = glm::normalize(Vec3(0.3f, -0.4f, 0.8f));
  for (const float g : {-0.6f, 0.0f, 0.3f, 0.9f}) {
    PhaseFunction phase;
    phase.type = PhaseFunction::Type::HenyeyGreenstein;
    phase.g = g;
    // Midpoint rule in cos θ about wi (the density depends on it alone): 2π ∫ p dμ.
    const int n = 200000;
    double integral = 0.0;
    for (int i = 0; i < n; ++i) integral += henyeyGreenstein(g, -1.0f + (i + 0.5f) * 2.0f / n);
    integral *= 2.0 * kPiD * 2.0 / n;
    EXPECT_NEAR(integral, 1.0, 1e-4) << g;
    Rng rng(7);
    double sum = 0.0, sum2 = 0.0;
    const int m = 100000;
    for (int i = 0; i < m; ++i) {
      const PhaseSample s = samplePhase(phase, wi, rng.next2D());
      ASSERT_NEAR(glm::length(s.wo), 1.0f, 1e-4f);
      ASSERT_NEAR(s.pdf, phaseValue(phase, wi, s.wo), 1e-4f * s.pdf);
      const double c = glm::dot(s.wo, -wi);
      sum += c;
      sum2 += c * c;
    }
    const double mean = sum / m, se = std::sqrt((sum2 / m - mean * mean) / m);
    EXPECT_NEAR(mean, g, 5.0 * se + 1e-6) << g;
  }
  EXPECT_FLOAT_EQ(phaseValue(PhaseFunction(), wi, Vec3(0, 0, 1)), 1.0f / (4.0f * kPi));
}

}  // namespace
}  // namespace rc
