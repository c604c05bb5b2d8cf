// Mitsuba's `direct` integrator (render/direct_integrator.h): its sample counts, including zero
// samples of a technique, against values derived from Mitsuba's weights (src/integrators/direct.cpp:
// a light sample weighs w_l/n_e and a BSDF sample w_b/n_b with w_l = (n_e·p_l)² / ((n_e·p_l)² +
// (n_b·p_b)²), w_b = 1 − w_l; a technique with no samples leaves the other weight 1).
#include <gtest/gtest.h>

#include "core/rng.h"
#include "geometry/shading_frame.h"
#include "render/direct_integrator.h"
#include "render/direct_light.h"
#include "render/path_integrator.h"
#include "render_test_scenes.h"

namespace rc {
namespace {

using test::Stat;

// A large ball close by: its light is reached often by both techniques, so both weights matter.
constexpr float kRho = 0.6f, kLe = 3.0f, kRadius = 1.5f, kHeight = 2.0f;

// A floor (z = 0) under an emitting sphere centred above the origin; nothing else.
Scene floorUnderBall(BsdfPtr floorBsdf) {
  Scene s;
  const int floor = test::addBsdf(s, std::move(floorBsdf));
  s.meshes.push_back(test::quad({-5, -5, 0}, {5, -5, 0}, {5, 5, 0}, {-5, 5, 0}, floor));
  Sphere ball;
  ball.center = Vec3(0, 0, kHeight);
  ball.radius = kRadius;
  ball.bsdf = test::addBsdf(s, test::diffuse(Color(0.5f)));
  ball.emitter = test::addEmitter(s, test::areaEmitter(Color(kLe)));
  s.spheres.push_back(ball);
  return s;
}

IntegratorSettings direct(int emitterSamples, int bsdfSamples) {
  IntegratorSettings s;
  s.type = "direct";
  s.emitterSamples = emitterSamples;
  s.bsdfSamples = bsdfSamples;
  s.maxDepth = 2;
  s.rrDepth = 3;
  return s;
}

// A ray onto the floor's origin from the side (it does not pass the ball).
Ray towardOrigin() {
  Ray r;
  r.o = Vec3(2.5f, 0.5f, 0.8f);
  r.d = glm::normalize(-r.o);
  return r;
}

// Radiance a Lambertian floor point reflects from a sphere of radiance Le centred on its normal:
// ρ/π · π·Le·sin²α, sin α = r/d (the sphere's irradiance on a point facing it).
constexpr double kFloorRadiance = kRho * kLe * (kRadius / kHeight) * (kRadius / kHeight);

TEST(DirectIntegrator, EveryCountIncludingZeroIsUnbiased) {
  const test::World w(floorUnderBall(test::diffuse(Color(kRho))));
  const RenderContext ctx = w.context();
  for (const auto& [ne, nb] : {std::pair{1, 1}, {1, 0}, {0, 1}, {4, 0}, {0, 3}, {3, 2}, {1, 4}}) {
    Stat st;
    for (int i = 0; i < 40000; ++i) {
      Rng rng(hashMix(7, ne * 8 + nb, i));
      st.add(directRadiance(ctx, direct(ne, nb), towardOrigin(), rng));
    }
    // Light sampling alone (emitter_samples > 0, bsdf_samples 0) is nearly noiseless here; the
    // relative 2e-3 is the float sum of the estimates, not noise.
    EXPECT_NEAR(st.mean[0], kFloorRadiance, 5 * st.stderr_(0) + 2e-3 * kFloorRadiance) << ne << " " << nb;
  }
}

// The light technique alone carries ∫ f·Le·cos·w_l dω: integrated over the ball's cone by quadrature
// with the sampler's own pdf (LightSampler::pdf) and the diffuse BSDF's cos/π, against the mean of
// lightStrategyMis.
TEST(DirectIntegrator, LightSamplesCarryMitsubasWeight) {
  const test::World w(floorUnderBall(test::diffuse(Color(kRho))));
  const RenderContext ctx = w.context();
  const Ray r = towardOrigin();
  const Hit hit = w.accel->intersect(r);
  ASSERT_TRUE(hit.valid());
  const Frame frame = hit.frame();
  const Vec3 wo = frame.toLocal(-r.d);
  const double sinAlpha = kRadius / kHeight, cosAlpha = std::sqrt(1.0 - sinAlpha * sinAlpha);
  // Midpoint rule over the cone θ ≤ α around +z (the floor's normal), dω = d(cosθ)·dφ.
  const auto lightShare = [&](int ne, int nb) {
    const int nTheta = 400, nPhi = 16;
    const double dOmega = (1.0 - cosAlpha) / nTheta * 2 * kPiD / nPhi;
    double sum = 0.0;
    for (int i = 0; i < nTheta; ++i)
      for (int j = 0; j < nPhi; ++j) {
        const double cosTheta = 1.0 - (i + 0.5) / nTheta * (1.0 - cosAlpha), phi = 2 * kPiD * (j + 0.5) / nPhi;
        const double sinTheta = std::sqrt(1.0 - cosTheta * cosTheta);
        const Vec3 d(float(sinTheta * std::cos(phi)), float(sinTheta * std::sin(phi)), float(cosTheta));
        const Hit onBall = w.accel->intersect(Accel::spawnRay(hit, d));
        if (onBall.emitter < 0) ADD_FAILURE() << "the cone misses the ball";
        const double pl = ne * double(w.lights->pdf(onBall, hit.p)), pb = nb * cosTheta / kPiD;
        sum += kRho / kPiD * kLe * cosTheta * pl * pl / (pl * pl + pb * pb) * dOmega;
      }
    return sum;
  };
  const double withoutCounts = lightShare(1, 1);
  for (const auto& [ne, nb] : {std::pair{1, 1}, {2, 1}, {1, 3}, {2, 5}}) {
    const double expected = lightShare(ne, nb);
    Stat st;
    for (int i = 0; i < 40000; ++i) {
      Rng rng(hashMix(9, ne * 8 + nb, i));
      st.add(lightStrategyMis(ctx, hit, frame, wo, *w.scene.bsdfs[hit.bsdf], rng, ne, nb));
    }
    const double allowance = 5 * st.stderr_(0) + 1e-3 * expected;
    EXPECT_NEAR(st.mean[0], expected, allowance) << ne << " " << nb;
    // The counts matter by far more than the allowance (weights of one sample each would fail).
    if (ne != nb) EXPECT_GT(std::fabs(expected - withoutCounts), 5 * allowance) << ne << " " << nb;
  }
}

// What one technique cannot reach stays dark without the other: a smooth mirror with no BSDF
// samples shows nothing of the ball, a point light with no emitter samples lights nothing.
TEST(DirectIntegrator, ZeroSamplesOfATechniqueMissWhatOnlyItFinds) {
  Properties mirror;
  mirror.pluginType = "conductor";
  mirror.set("material", test::stringProp("none"));
  const test::World wm(floorUnderBall(createBsdf(mirror, {})));
  Ray onMirror;  // reflects up into the ball
  onMirror.o = Vec3(0.05f, 0.0f, 0.3f);
  onMirror.d = glm::normalize(-onMirror.o);
  for (const auto& [ne, nb, lit] : {std::tuple{4, 0, false}, {0, 1, true}, {1, 1, true}}) {
    Rng rng(3);
    const Color L = directRadiance(wm.context(), direct(ne, nb), onMirror, rng);
    EXPECT_NEAR(L[0], lit ? kLe : 0.0f, 1e-4f) << ne << " " << nb;
  }

  Scene point;
  point.meshes.push_back(test::quad({-5, -5, 0}, {5, -5, 0}, {5, 5, 0}, {-5, 5, 0}, test::addBsdf(point, test::diffuse(Color(kRho)))));
  test::addEmitter(point, test::pointEmitter(Vec3(0, 0, 2), Color(8.0f)));
  const test::World wp(std::move(point));
  for (const auto& [ne, nb] : {std::pair{0, 2}, {1, 0}, {3, 1}}) {
    Rng rng(5);
    const Color L = directRadiance(wp.context(), direct(ne, nb), towardOrigin(), rng);
    // I/d² · ρ/π at normal incidence, from light samples only (each averaged, weight 1 for a delta light).
    EXPECT_NEAR(L[0], ne > 0 ? 8.0f / 4.0f * kRho / kPi : 0.0f, 1e-5f) << ne << " " << nb;
  }
}

// With one sample of each it is the path tracer cut at two segments: the same numbers in the same
// order give the same radiance, sample for sample.
TEST(DirectIntegrator, OneOfEachIsThePathTracerToDepthTwo) {
  const test::World w(test::cornellLike(16, 16));
  const RenderContext ctx = w.context();
  const CameraModel camera(w.scene.camera, 16, 16);
  IntegratorSettings path = direct(1, 1);
  path.type = "path";
  int lit = 0;
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      const Ray r = camera.generate(Vec2(x + 0.5f, y + 0.5f));
      Rng a(hashMix(11, x, y)), b(hashMix(11, x, y));
      const Color d = directRadiance(ctx, direct(1, 1), r, a);
      EXPECT_EQ(d, pathRadiance(ctx, path, r, b)) << x << " " << y;
      lit += maxComponent(d) > 0.0f;
    }
  EXPECT_GT(lit, 150);  // most pixels get light (the rest: the light's own back, shadow)
}

}  // namespace
}  // namespace rc
