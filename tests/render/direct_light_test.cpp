// Light sampling and the MIS direct-light estimator.
#include <gtest/gtest.h>

#include "core/rng.h"
#include "render/direct_light.h"
#include "render/light_sampler.h"
#include "render_test_scenes.h"

namespace rc {
namespace {

// Floor (glossy or diffuse) lit by a mesh area light, a sphere light, and an environment map
// (a programmatic lat-long image with a bright spot), partly occluded by a blocker.
Scene litFloor(BsdfPtr floorBsdf) {
  Scene s;
  const int floor = test::addBsdf(s, std::move(floorBsdf));
  const int grey = test::addBsdf(s, test::diffuse(Color(0.5f)));
  s.meshes.push_back(test::quad({-5, -5, 0}, {5, -5, 0}, {5, 5, 0}, {-5, 5, 0}, floor));
  const int quadLight = test::addEmitter(s, test::areaEmitter(Color(4.0f, 3.0f, 2.0f)));
  s.meshes.push_back(test::quad({-1.5f, -0.5f, 2}, {-1.5f, 0.5f, 2}, {-0.5f, 0.5f, 2}, {-0.5f, -0.5f, 2}, grey, quadLight));
  const int ballLight = test::addEmitter(s, test::areaEmitter(Color(2.0f, 5.0f, 3.0f)));
  Sphere ball;
  ball.center = Vec3(1.2f, 0.3f, 1.0f);
  ball.radius = 0.3f;
  ball.bsdf = grey;
  ball.emitter = ballLight;
  s.spheres.push_back(ball);
  s.meshes.push_back(test::quad({0.2f, -2, 0.6f}, {0.2f, 2, 0.6f}, {0.4f, 2, 0.9f}, {0.4f, -2, 0.9f}, grey));  // blocker
  Emitter env;
  env.type = EmitterType::Envmap;
  env.envWidth = 32;
  env.envHeight = 16;
  env.scale = 0.5f;
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 32; ++x)
      env.envPixels.push_back((x == 20 && y == 5) ? Color(20.0f, 15.0f, 10.0f) : Color(0.3f, 0.4f, 0.6f) * (1.0f + y / 8.0f));
  env.toWorld = Mat4(glm::mat3(Vec3(1, 0, 0), Vec3(0, 0, 1), Vec3(0, -1, 0)));  // local +y (up) → world +z
  test::addEmitter(s, env);
  return s;
}

// sample() and pdf() agree: the pdf reported with a light sample equals pdf() of the emitter point
// the sample's direction actually hits (area lights) or environmentPdf (infinite lights).
TEST(LightSampler, SamplePdfMatchesPdfOfTheHit) {
  const test::World w(litFloor(test::diffuse(Color(0.5f))));
  Rng rng(1);
  const Vec3 p(0.1f, -0.2f, 0.01f);
  int area = 0, infinite = 0;
  for (int i = 0; i < 3000; ++i) {
    const auto ls = w.lights->sample(p, Vec2(rng.nextFloat(), rng.nextFloat()), rng.nextFloat());
    if (!ls) continue;
    ASSERT_GT(ls->pdf, 0.0f);
    ASSERT_FALSE(ls->delta);
    if (std::isinf(ls->dist)) {
      EXPECT_NEAR(ls->pdf, w.lights->environmentPdf(ls->wi), 1e-4f * ls->pdf);
      ++infinite;
      continue;
    }
    Ray r;
    r.o = p;
    r.d = ls->wi;
    const Hit h = w.accel->intersect(r);
    ASSERT_TRUE(h.valid());
    if (h.emitter < 0 || std::fabs(h.t - ls->dist) > 1e-3f * ls->dist) continue;  // blocked by another object
    EXPECT_NEAR(w.lights->pdf(h, p), ls->pdf, 2e-3f * ls->pdf);
    ++area;
  }
  EXPECT_GT(area, 200);
  EXPECT_GT(infinite, 200);
}

// ∫ environmentPdf dω over the sphere = probability of picking an infinite emitter.
TEST(LightSampler, EnvironmentPdfIntegratesToItsSelectionProbability) {
  const test::World w(litFloor(test::diffuse(Color(0.5f))));
  Rng rng(2);
  double integral = 0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    const float z = 1 - 2 * rng.nextFloat(), phi = 2 * kPi * rng.nextFloat(), r = std::sqrt(1 - z * z);
    integral += w.lights->environmentPdf(Vec3(r * std::cos(phi), r * std::sin(phi), z));
  }
  integral *= 4 * kPiD / n;
  // Fraction of light samples that are infinite, measured by sampling.
  int inf = 0, total = 20000;
  for (int i = 0; i < total; ++i) {
    const auto ls = w.lights->sample(Vec3(0, 0, 0.5f), Vec2(rng.nextFloat(), rng.nextFloat()), rng.nextFloat());
    if (ls && std::isinf(ls->dist)) ++inf;
  }
  const double frac = double(inf) / total;
  // Both are MC estimates: the pdf is peaked (a 20× spot), so allow 3% relative plus binomial noise.
  EXPECT_NEAR(integral, frac, 0.03 * frac + 4 * std::sqrt(frac * (1 - frac) / total));
  EXPECT_GT(frac, 0.01);
}

// environment() (radiance alone, for escaping camera rays) is environmentLookup()'s radiance bit for
// bit, with an envmap and a constant emitter summed in entry order.
TEST(LightSampler, EnvironmentIsTheLookupsRadianceExactly) {
  Scene s = litFloor(test::diffuse(Color(0.5f)));
  Emitter constant;
  constant.type = EmitterType::Constant;
  constant.radiance = Color(0.1f, 0.2f, 0.3f);
  test::addEmitter(s, constant);
  const test::World w(std::move(s));
  Rng rng(5);
  for (int i = 0; i < 10000; ++i) {
    const float z = 1 - 2 * rng.nextFloat(), phi = 2 * kPi * rng.nextFloat(), r = std::sqrt(std::max(0.0f, 1 - z * z));
    const Vec3 d(r * std::cos(phi), r * std::sin(phi), z);
    const Color a = w.lights->environment(d), b = w.lights->environmentLookup(d).radiance;
    ASSERT_EQ(a.r, b.r);
    ASSERT_EQ(a.g, b.g);
    ASSERT_EQ(a.b, b.b);
    ASSERT_GT(a.r, 0.1f);  // both emitters reached
  }
}

// environmentLookups (a wave's escaped directions as arrays, the envmap's pass vectorised) gives
// environmentLookup's radiance and density bit for bit, with an envmap and a constant emitter
// summed in entry order; without the densities it leaves them 0.
TEST(LightSampler, EnvironmentLookupsAreTheLookupsExactly) {
  Scene s = litFloor(test::diffuse(Color(0.5f)));
  test::addEmitter(s, test::constantEmitter(Color(0.1f, 0.2f, 0.3f)));
  const test::World w(std::move(s));
  LightSampler::EnvironmentWave wave;
  const size_t n = 1001;
  wave.fit(n);
  Rng rng(6);
  for (size_t k = 0; k < n; ++k) {
    const float z = 1 - 2 * rng.nextFloat(), phi = 2 * kPi * rng.nextFloat(), r = std::sqrt(std::max(0.0f, 1 - z * z));
    wave.x[k] = r * std::cos(phi), wave.y[k] = r * std::sin(phi), wave.z[k] = z;
  }
  for (bool withPdf : {true, false}) {
    w.lights->environmentLookups(wave, n, withPdf);
    for (size_t k = 0; k < n; ++k) {
      const LightSampler::EnvironmentLookup one = w.lights->environmentLookup(Vec3(wave.x[k], wave.y[k], wave.z[k]));
      const LightSampler::EnvironmentLookup batch = wave.at(k);
      ASSERT_EQ(batch.radiance, one.radiance) << k;
      ASSERT_EQ(batch.pdf, withPdf ? one.pdf : 0.0f) << k;
      ASSERT_GT(one.pdf, 0.0f);
    }
  }
}

using test::Stat;

// The MIS estimator (light + BSDF sampling) is unbiased: it matches pure BSDF sampling (which
// counts emission where its rays land, weight 1) and pure light sampling within the statistical
// error of both (5σ). A wrong MIS weight on either strategy (weights not summing to 1) is a bias
// that the light-only comparison resolves (checked by mutating the weight by 2×: fails).
TEST(DirectLight, MisMatchesPureBsdfSampling) {
  for (int which = 0; which < 2; ++which) {
    const test::World w(litFloor(which == 0 ? test::diffuse(Color(0.7f, 0.5f, 0.3f)) : test::roughMirror(0.25f)));
    const RenderContext ctx = w.context();
    Ray down;
    down.o = Vec3(0.3f, 0.1f, 3.0f);
    down.d = glm::normalize(Vec3(0.0f, 0.05f, 0.0f) - down.o);
    const Hit hit = w.accel->intersect(down);
    ASSERT_TRUE(hit.valid());
    ASSERT_EQ(hit.mesh, 0);
    const Bsdf& bsdf = *w.scene.bsdfs[hit.bsdf];
    const Frame frame = hit.frame();
    const Vec3 wo = frame.toLocal(-down.d);
    Stat mis, pure, lightOnly, mis4, lightOnlyFn;
    const int n = 60000;
    for (int i = 0; i < n; ++i) {
      Rng rng(hashMix(3, i));
      mis.add(directLight(ctx, hit, frame, wo, bsdf, rng));
      Rng rng4(hashMix(4, i));
      mis4.add(directLight(ctx, hit, frame, wo, bsdf, rng4, 4));
      Rng rngL(hashMix(5, i));
      lightOnlyFn.add(directLightLightOnly(ctx, hit, frame, wo, bsdf, rngL));
      const auto bs = bsdf.sample(wo, rng.nextFloat(), Vec2(rng.nextFloat(), rng.nextFloat()));
      Color L(0.0f);
      if (bs) {
        const Vec3 d = frame.toWorld(bs->wi);
        const Hit next = w.accel->intersect(Accel::spawnRay(hit, d));
        L = bs->weight * (next.valid() ? emitted(w.scene, next, -d) : w.lights->environment(d));
      }
      pure.add(L);
      // Light sampling alone (weight 1): unbiased on its own, and low-variance for these lights.
      const auto ls = w.lights->sample(hit.p, Vec2(rng.nextFloat(), rng.nextFloat()), rng.nextFloat());
      Color Ll(0.0f);
      if (ls && visible(*w.accel, hit, *ls)) Ll = bsdf.eval(wo, frame.toLocal(ls->wi)) * ls->radiance;
      lightOnly.add(Ll);
    }
    for (int k = 0; k < 3; ++k) {
      const double sigma = std::sqrt(mis.stderr_(k) * mis.stderr_(k) + pure.stderr_(k) * pure.stderr_(k));
      EXPECT_NEAR(mis.mean[k], pure.mean[k], 5 * sigma) << "bsdf " << which << " channel " << k;
      const double sigmaL = std::sqrt(mis.stderr_(k) * mis.stderr_(k) + lightOnly.stderr_(k) * lightOnly.stderr_(k));
      EXPECT_NEAR(mis.mean[k], lightOnly.mean[k], 5 * sigmaL) << "bsdf " << which << " channel " << k;
      // The point of MIS: lower variance than BSDF sampling alone on these small bright lights.
      EXPECT_LT(mis.stderr_(k), pure.stderr_(k)) << "bsdf " << which;
      // Four light samples beside one BSDF sample (weights against 4·pdf_light): same mean, less
      // variance; directLightLightOnly is the light-only estimator above as a function.
      const double sigma4 = std::sqrt(mis4.stderr_(k) * mis4.stderr_(k) + pure.stderr_(k) * pure.stderr_(k));
      EXPECT_NEAR(mis4.mean[k], pure.mean[k], 5 * sigma4) << "bsdf " << which << " channel " << k;
      EXPECT_LT(mis4.stderr_(k), mis.stderr_(k)) << "bsdf " << which;
      const double sigmaF = std::sqrt(lightOnlyFn.stderr_(k) * lightOnlyFn.stderr_(k) + pure.stderr_(k) * pure.stderr_(k));
      EXPECT_NEAR(lightOnlyFn.mean[k], pure.mean[k], 5 * sigmaF) << "bsdf " << which << " channel " << k;
    }
    EXPECT_GT(mis.mean[0], 0.01);
  }
}

// solidAngleBound: the cap of each area emitter's bounding sphere, 4π with an infinite emitter
// or from inside a bound; directLightCheapest picks light-only sampling only for a Lambertian
// BSDF under small lights and keeps the mean of full MIS.
TEST(DirectLight, CheapestChoosesLightOnlyUnderSmallLightsOnly) {
  Scene s;
  const int white = test::addBsdf(s, test::diffuse(Color(0.8f)));
  const int glossy = test::addBsdf(s, test::roughMirror(0.3f));
  s.meshes.push_back(test::quad({-5, -5, 0}, {5, -5, 0}, {5, 5, 0}, {-5, 5, 0}, white));
  s.meshes.push_back(test::quad({-5, -5, 0.001f}, {-4, -5, 0.001f}, {-4, -4, 0.001f}, {-5, -4, 0.001f}, glossy));
  const int light = test::addEmitter(s, test::areaEmitter(Color(10.0f)));
  // 0.2 × 0.2 light at height 2 facing down: bounding radius 0.1414.
  s.meshes.push_back(test::quad({-0.1f, -0.1f, 2}, {-0.1f, 0.1f, 2}, {0.1f, 0.1f, 2}, {0.1f, -0.1f, 2}, white, light));
  const test::World w(std::move(s));
  const float r = 0.1f * std::sqrt(2.0f);
  const Vec3 far(0, 0, 0), near(0, 0, 1.95f);
  EXPECT_NEAR(w.lights->solidAngleBound(far), 2 * kPi * (1 - std::sqrt(1 - r * r / 4)), 1e-5f);
  EXPECT_EQ(w.lights->solidAngleBound(Vec3(0, 0, 1.99f)), 4 * kPi);  // inside the bound
  EXPECT_GT(w.lights->solidAngleBound(near), kSmallLightsSolidAngle);

  const RenderContext ctx = w.context();
  auto hitAt = [&](const Vec3& o, const Vec3& target) {
    Ray ray;
    ray.o = o;
    ray.d = glm::normalize(target - o);
    return w.accel->intersect(ray);
  };
  const Hit floorHit = hitAt(Vec3(0.5f, 0.2f, 1.0f), Vec3(0.3f, 0.1f, 0.0f));
  const Hit glossyHit = hitAt(Vec3(-4.5f, -4.5f, 1.0f), Vec3(-4.5f, -4.4f, 0.0f));
  ASSERT_TRUE(floorHit.valid());
  ASSERT_TRUE(glossyHit.valid());
  ASSERT_EQ(glossyHit.bsdf, glossy);
  for (const Hit* h : {&floorHit, &glossyHit}) {
    const Bsdf& bsdf = *w.scene.bsdfs[h->bsdf];
    const Frame frame = h->frame();
    const Vec3 wo(0, 0, 1);
    Stat cheap, mis;
    bool lightOnly = false;
    for (int i = 0; i < 40000; ++i) {
      Rng a(hashMix(11, i)), b(hashMix(12, i));
      cheap.add(directLightCheapest(ctx, *h, frame, wo, bsdf, a, 1, &lightOnly));
      mis.add(directLight(ctx, *h, frame, wo, bsdf, b));
    }
    EXPECT_EQ(lightOnly, h == &floorHit);  // Lambertian under a small light: light only; glossy: MIS
    for (int k = 0; k < 3; ++k) {
      const double sigma = std::sqrt(cheap.stderr_(k) * cheap.stderr_(k) + mis.stderr_(k) * mis.stderr_(k));
      EXPECT_NEAR(cheap.mean[k], mis.mean[k], 5 * sigma);
      EXPECT_GT(cheap.mean[k], 0.0);
    }
  }
  // With an environment emitter every point keeps MIS.
  Scene e = w.scene;
  e.emitters.push_back(test::constantEmitter(Color(0.1f)));
  const test::World we(std::move(e));
  EXPECT_EQ(we.lights->solidAngleBound(far), 4 * kPi);
  // Many emitters: not summed per point (bounded cost), answered conservatively.
  Scene many = w.scene;
  for (int k = 0; k < 20; ++k) {
    const int em = test::addEmitter(many, test::areaEmitter(Color(1.0f)));
    const float x = -4.5f + 0.4f * k;
    many.meshes.push_back(test::quad({x, 4, 3}, {x, 4.1f, 3}, {x + 0.1f, 4.1f, 3}, {x + 0.1f, 4, 3}, white, em));
  }
  const test::World wm(std::move(many));
  EXPECT_EQ(wm.lights->solidAngleBound(far), 4 * kPi);
}

TEST(DirectLight, PointAndDirectionalLights) {
  // Delta lights are only reachable by light sampling: compare with the analytic answer.
  Scene s;
  const float rho = 0.6f;
  s.meshes.push_back(test::quad({-5, -5, 0}, {5, -5, 0}, {5, 5, 0}, {-5, 5, 0}, test::addBsdf(s, test::diffuse(Color(rho)))));
  test::addEmitter(s, test::pointEmitter(Vec3(1, 0, 2), Color(10.0f)));
  Emitter sun;
  sun.type = EmitterType::Directional;
  sun.direction = glm::normalize(Vec3(0, -1, -1));
  sun.irradiance = Color(3.0f);
  test::addEmitter(s, sun);
  const test::World w(std::move(s));
  const RenderContext ctx = w.context();
  Ray r;
  r.o = Vec3(0, 0, 1);
  r.d = Vec3(0, 0, -1);
  const Hit hit = w.accel->intersect(r);
  const Frame frame = hit.frame();
  Stat st;
  for (int i = 0; i < 20000; ++i) {
    Rng rng(hashMix(4, i));
    st.add(directLight(ctx, hit, frame, frame.toLocal(-r.d), *w.scene.bsdfs[0], rng));
  }
  // Point: I cosθ / d² · ρ/π with d² = 5, cosθ = 2/√5. Sun: E cosθ ρ/π with cosθ = 1/√2.
  const double expected = rho / kPiD * (10.0 * (2.0 / std::sqrt(5.0)) / 5.0 + 3.0 / std::sqrt(2.0));
  EXPECT_NEAR(st.mean[0], expected, 5 * st.stderr_(0) + 1e-6);
}

TEST(DirectLight, AreaEmitterIsOneSided) {
  Scene s;
  const int em = test::addEmitter(s, test::areaEmitter(Color(2.0f)));
  s.meshes.push_back(test::quad({-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, -1, em));
  const test::World w(std::move(s));
  Ray r;
  r.o = Vec3(0, 0, 1);
  r.d = Vec3(0, 0, -1);
  const Hit h = w.accel->intersect(r);
  EXPECT_EQ(emitted(w.scene, h, -r.d), Color(2.0f));
  EXPECT_EQ(emitted(w.scene, h, r.d), Color(0.0f));
  // From behind the light, light sampling finds nothing.
  Rng rng(1);
  for (int i = 0; i < 100; ++i)
    EXPECT_FALSE(w.lights->sample(Vec3(0.2f, 0.1f, -1.0f), Vec2(rng.nextFloat(), rng.nextFloat()), rng.nextFloat()));
}

}  // namespace
}  // namespace rc
