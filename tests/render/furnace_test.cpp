// White-furnace tests of the path tracer: scenes whose exact answer is known.
// Tolerances: each estimate is a mean of N independent path samples, so it is compared against the
// exact value within 5 standard errors (estimated from the same samples) — a false failure rate
// below 1e-6 per check, while a bias larger than ~5σ (a fraction of a percent here) fails.
#include <gtest/gtest.h>

#include "core/rng.h"
#include "render/path_integrator.h"
#include "render_test_scenes.h"

namespace rc {
namespace {

struct Estimate {
  double mean = 0, stderr_ = 0;
};

Estimate estimate(const test::World& w, const IntegratorSettings& s, const Ray& ray, int n, uint64_t seed) {
  const RenderContext ctx = w.context();
  double sum = 0, sum2 = 0;
  for (int i = 0; i < n; ++i) {
    Rng rng(hashMix(seed, static_cast<uint64_t>(i)));
    const double v = luminance(pathRadiance(ctx, s, ray, rng));
    sum += v;
    sum2 += v * v;
  }
  Estimate e;
  e.mean = sum / n;
  e.stderr_ = std::sqrt(std::max(0.0, sum2 / n - e.mean * e.mean) / n);
  return e;
}

using test::rayAt;

// Convex ρ = 1 diffuse sphere under a constant emitter of radiance 1: every path sees radiance 1.
TEST(Furnace, DiffuseSphereUnderConstantEmitter) {
  Scene s;
  Sphere sp;
  sp.radius = 1.0f;
  sp.bsdf = test::addBsdf(s, test::diffuse(Color(1.0f)));
  s.spheres.push_back(sp);
  test::addEmitter(s, test::constantEmitter(Color(1.0f)));
  const test::World w(std::move(s));
  IntegratorSettings settings;
  for (const Vec3 target : {Vec3(0, 0, 1), Vec3(0.9f, 0, 0.3f), Vec3(0.3f, 0.95f, 0.0f)}) {
    const Estimate e = estimate(w, settings, rayAt({0.2f, 0.1f, 5.0f}, target), 4000, 1);
    EXPECT_NEAR(e.mean, 1.0, 5.0 * e.stderr_ + 1e-4) << target.x;
  }
  settings.hideEmitters = true;  // background hidden, the sphere still shows the reflected furnace
  const Estimate e = estimate(w, settings, rayAt({0, 0, 5}, {0, 0, 0}), 4000, 2);
  EXPECT_NEAR(e.mean, 1.0, 5.0 * e.stderr_ + 1e-4);
  EXPECT_EQ(estimate(w, settings, rayAt({0, 0, 5}, {0, 3, 0}), 10, 3).mean, 0.0);
}

// Closed box of albedo ρ whose walls all emit Le: L = Le + ρ L → L = Le / (1 − ρ), exercising
// area-light sampling, MIS and Russian roulette over many bounces (unbounded max_depth).
TEST(Furnace, EmissiveClosedBox) {
  Scene s;
  const float rho = 0.8f, Le = 0.2f;
  const int bsdf = test::addBsdf(s, test::diffuse(Color(rho)));
  const int em = test::addEmitter(s, test::areaEmitter(Color(Le)));
  for (Mesh& m : test::insideOfBox({-1, -1, -1}, {1, 2, 3}, bsdf, em)) s.meshes.push_back(m);
  Sphere ball;  // an inner convex object with the same material/emission: still exactly 1
  ball.center = Vec3(0.2f, 0.3f, 1.0f);
  ball.radius = 0.4f;
  ball.bsdf = bsdf;
  ball.emitter = em;
  s.spheres.push_back(ball);
  const test::World w(std::move(s));
  IntegratorSettings settings;
  for (const Vec3 target : {Vec3(0.2f, 0.3f, 1.0f), Vec3(-1.0f, 0.0f, 2.0f), Vec3(0.5f, 2.0f, 0.0f)}) {
    const Estimate e = estimate(w, settings, rayAt({0.1f, 0.5f, 2.5f}, target), 3000, 4);
    EXPECT_NEAR(e.mean, Le / (1.0 - rho), 5.0 * e.stderr_ + 1e-4) << target.x;
  }
  // max_depth bounds the series: depth 1 = Le, depth 3 = Le (1 + ρ + ρ²).
  settings.maxDepth = 1;
  EXPECT_NEAR(estimate(w, settings, rayAt({0.1f, 0.5f, 2.5f}, {0, 0, -1}), 50, 5).mean, Le, 1e-6);
  settings.maxDepth = 3;
  const Estimate e3 = estimate(w, settings, rayAt({0.1f, 0.5f, 2.5f}, {0, 0, -1}), 3000, 6);
  EXPECT_NEAR(e3.mean, Le * (1 + rho + rho * rho), 5.0 * e3.stderr_ + 1e-4);
}

// Rough conductor with F ≡ 1 under a constant emitter returns its directional albedo, which for a
// single-scattering microfacet model is below 1. The expected value is computed independently by
// uniform hemisphere quadrature of eval() (no BSDF sampling code involved).
TEST(Furnace, RoughMirrorSphereReturnsItsAlbedo) {
  for (float alpha : {0.1f, 0.4f}) {
    Scene s;
    Sphere sp;
    sp.radius = 1.0f;
    sp.bsdf = test::addBsdf(s, test::roughMirror(alpha));
    s.spheres.push_back(sp);
    test::addEmitter(s, test::constantEmitter(Color(1.0f)));
    const Bsdf& bsdf = *s.bsdfs[0];
    const test::World w(std::move(s));
    IntegratorSettings settings;
    settings.maxDepth = 2;  // one bounce: the sphere is convex, the reflected ray escapes
    const Vec3 eye(0, 0, 5);
    const Vec3 target(0.5f, 0.0f, std::sqrt(0.75f));  // hit at 30° from the view direction
    const Ray ray = rayAt(eye, target);
    const Hit hit = w.accel->intersect(ray);
    ASSERT_TRUE(hit.valid());
    const Vec3 wo = hit.frame().toLocal(-ray.d);
    // Albedo by stratified uniform hemisphere quadrature.
    double albedo = 0;
    const int M = 400;
    Rng rng(7);
    for (int j = 0; j < M; ++j)
      for (int k = 0; k < M; ++k) {
        const float z = (j + rng.nextFloat()) / M, phi = 2 * kPi * (k + rng.nextFloat()) / M;
        const float r = std::sqrt(std::max(0.0f, 1 - z * z));
        albedo += luminance(bsdf.eval(wo, Vec3(r * std::cos(phi), r * std::sin(phi), z)));
      }
    albedo *= 2 * kPiD / (double(M) * M);
    // Quadrature error: stratified jittered, smooth lobe: well below 0.5% for these alphas.
    const Estimate e = estimate(w, settings, ray, 20000, 8);
    EXPECT_LT(albedo, 1.0);
    // Single-scattering GGX loses energy to masking: ~1.5% at α = 0.1, ~23% at α = 0.4 here.
    EXPECT_GT(albedo, alpha < 0.2f ? 0.97 : 0.7);
    EXPECT_NEAR(e.mean, albedo, 5.0 * e.stderr_ + 0.005 * albedo) << "alpha " << alpha;
  }
}

Scene glassSphereUnderConstantEmitter(const char* plugin, float intIor) {
  Properties props;
  props.pluginType = plugin;
  props.set("int_ior", test::floatProp(intIor));
  props.set("ext_ior", test::floatProp(1.0f));
  Scene s;
  Sphere sp;
  sp.radius = 1.0f;
  sp.bsdf = test::addBsdf(s, createBsdf(props, {}));
  s.spheres.push_back(sp);
  test::addEmitter(s, test::constantEmitter(Color(1.0f)));
  return s;
}

// A lossless dielectric sphere under a constant emitter of radiance 1 (Mitsuba 3 dielectric.cpp,
// thindielectric.cpp, path.cpp): reflection and refraction conserve energy, the η² radiance
// scaling of entering and leaving cancel, and every path escapes, so every pixel is exactly 1 —
// through Russian roulette whose probability carries η² (min(max β · η², 0.95)), from the first
// segment (rr_depth 1) or Mitsuba's default 5. Seen from inside, every path leaves the sphere once
// more than it enters: radiance η² (1 for the thin sheet, which does not bend or scale).
TEST(Furnace, LosslessGlassSphereUnderConstantEmitter) {
  for (const char* plugin : {"dielectric", "thindielectric"})
    for (const float ior : {1.5f, 2.42f}) {
      const test::World w(glassSphereUnderConstantEmitter(plugin, ior));
      for (const int rrDepth : {1, 5}) {
        IntegratorSettings settings;
        settings.rrDepth = rrDepth;
        for (const Vec3 target : {Vec3(0, 0, 0), Vec3(0.6f, 0.2f, 0.0f), Vec3(0.1f, 0.93f, 0.0f)}) {
          const Estimate e = estimate(w, settings, rayAt({0.1f, 0.2f, 5.0f}, target), 20000, 9);
          EXPECT_NEAR(e.mean, 1.0, 5.0 * e.stderr_ + 1e-4) << plugin << " ior " << ior << " rr_depth " << rrDepth;
        }
        const double inside = std::string(plugin) == "dielectric" ? double(ior) * ior : 1.0;
        const Estimate e = estimate(w, settings, rayAt({0.1f, 0.2f, 0.3f}, {0.5f, -0.4f, 0.6f}), 20000, 11);
        EXPECT_NEAR(e.mean, inside, 5.0 * e.stderr_ + 1e-4) << plugin << " inside, ior " << ior << " rr_depth " << rrDepth;
      }
    }
}

// Mitsuba's max_depth counts path segments through glass like any other: a ray through the centre
// of a smooth sphere (normal incidence twice, F = ((η − 1)/(η + 1))²) sees the front reflection
// alone at max_depth 2 (its second vertex, inside on the back face, may not extend the path), and
// adds the straight-through path (1 − F)² at max_depth 3; the back face's inner reflection needs 4.
TEST(Furnace, MaxDepthCountsSegmentsThroughGlass) {
  const float ior = 1.5f;
  const double F = (ior - 1.0) * (ior - 1.0) / ((ior + 1.0) * (ior + 1.0));
  const test::World w(glassSphereUnderConstantEmitter("dielectric", ior));
  const Ray ray = rayAt({0, 0, 5}, {0, 0, 0});
  IntegratorSettings settings;
  settings.hideEmitters = true;
  for (const auto& [depth, expected] : {std::pair{1, 0.0}, {2, F}, {3, F + (1 - F) * (1 - F)}}) {
    settings.maxDepth = depth;
    const Estimate e = estimate(w, settings, ray, 20000, 10);
    EXPECT_NEAR(e.mean, expected, 5.0 * e.stderr_ + 1e-4) << "max_depth " << depth;
  }
}

}  // namespace
}  // namespace rc
