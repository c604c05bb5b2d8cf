// Heterogeneous media (render/medium_tracking.h): delta and ratio tracking against closed-form
// transmittance over a constant and a linear-ramp grid, the whole volumetric path tracer against a
// homogeneous medium of the same density and against a lossless furnace, and hostile numbers that
// must end in bounded work. Monte Carlo checks: volpath_test_util.h.
#include <chrono>

#include "render/medium_tracking.h"
#include "volpath_test_util.h"

namespace rc {
namespace {

using test::rayAt;

// A grid volume of nx·1·1 voxels (values per voxel, `channels` each) stretched over the box
// [lo, hi] by its to_world.
VolumePtr gridOver(const Vec3& lo, const Vec3& hi, uint32_t nx, uint32_t channels, std::vector<float> values) {
  GridVolumeData data;
  data.size = {nx, 1, 1};
  data.channels = channels;
  data.values = std::move(values);
  Mat4 toWorld(1.0f);
  for (int a = 0; a < 3; ++a) toWorld[a][a] = hi[a] - lo[a];
  toWorld[3] = Vec4(lo, 1.0f);
  return makeGridVolume(std::move(data), VolumeFilter::Trilinear, TextureWrap::Clamp, glm::inverse(toWorld));
}

Medium heterogeneous(VolumePtr density, float scale, const Color& albedo, PhaseFunction phase = {}) {
  Medium m;
  m.name = "test";
  m.homogeneous = false;
  m.density = std::move(density);
  m.scale = scale;
  m.majorant = scale * maxComponent(m.density->maximum());
  m.albedo = makeConstVolume(albedo);
  m.phase = phase;
  return m;
}

// The unbiased transmittance of both estimators: ratio tracking's product, and the weight a free
// flight carries where it passes the segment's end (0 where it scattered).
void expectTransmittance(const Medium& m, const Ray& ray, float tEnd, const Color& exact, const char* what) {
  const int n = 40000;
  expectNear(meanOf(n, 11, [&](Rng& rng) { return mediumTransmittance(m, ray, tEnd, rng); }), exact,
             (std::string(what) + ": ratio tracking").c_str());
  expectNear(meanOf(n, 12,
                    [&](Rng& rng) {
                      const FreeFlight f = sampleFreeFlight(m, ray, tEnd, rng);
                      return f.scattered ? Color(0.0f) : f.weight;
                    }),
             exact, (std::string(what) + ": delta tracking").c_str());
}

// A constant grid over [0,2]×[−1,1]² is Beer–Lambert inside the box and nothing outside it: a ray
// along x from −3 to 5 crosses 2 units of it.
TEST(HeterogeneousMedium, ConstantGridTransmitsBeersLawInsideItsBounds) {
  const Medium m = heterogeneous(gridOver({0, -1, -1}, {2, 1, 1}, 2, 1, {0.4f, 0.4f}), 1.5f, Color(0.5f));
  EXPECT_FLOAT_EQ(m.majorant, 0.6f);
  const Ray ray = rayAt({-3, 0.2f, 0.1f}, {5, 0.2f, 0.1f});
  expectTransmittance(m, ray, 8.0f, Color(std::exp(-0.6f * 2.0f)), "through the box");
  expectTransmittance(m, ray, 4.0f, Color(std::exp(-0.6f * 1.0f)), "ending halfway");
  expectTransmittance(m, ray, std::numeric_limits<float>::infinity(), Color(std::exp(-0.6f * 2.0f)), "leaving for good");
}

// A 4-voxel ramp 0, 1, 2, 3 along x over [0,1]: trilinear between the voxel centres at 1/8, 3/8,
// 5/8, 7/8 and held at the ends, so ∫₀¹ density dx = 0·1/8 + (½ + 3/2 + 5/2)/4 + 3·1/8 = 1.5.
// Three channels with different scales test the spectral (per-channel) null weights.
TEST(HeterogeneousMedium, RampGridTransmitsTheIntegralOfItsDensity) {
  std::vector<float> values;
  const Color channelScale(1.0f, 0.5f, 0.1f);
  for (int i = 0; i < 4; ++i)
    for (int c = 0; c < 3; ++c) values.push_back(float(i) * channelScale[c]);
  const Medium m = heterogeneous(gridOver({0, 0, 0}, {1, 1, 1}, 4, 3, values), 0.8f, Color(0.0f));
  const Ray ray = rayAt({-1, 0.5f, 0.5f}, {2, 0.5f, 0.5f});
  expectTransmittance(m, ray, 3.0f, glm::exp(-0.8f * 1.5f * channelScale), "ramp");
  // Half the ray: ∫₀^½ = 0·1/8 + ½·1/4 + (1 + 1.5)/2·1/8 = 0.28125.
  expectTransmittance(m, ray, 1.5f, glm::exp(-0.8f * 0.28125f * channelScale), "half the ramp");
}

// The same density as a heterogeneous (constant grid) and a homogeneous medium inside the unit
// sphere, lossy with an HG phase and light sampling: both estimators are unbiased, so the radiance
// agrees within the noise of both.
TEST(HeterogeneousMedium, ConstantGridRendersAsTheHomogeneousMedium) {
  PhaseFunction hg;
  hg.type = PhaseFunction::Type::HenyeyGreenstein;
  hg.g = 0.5f;
  const Color albedo(0.9f, 0.6f, 0.3f);
  const test::World het(mediumSphere(heterogeneous(gridOver(Vec3(-1), Vec3(1), 2, 1, {2.0f, 2.0f}), 1.0f, albedo, hg), nullBsdf()));
  const test::World hom(mediumSphere(homogeneous(Color(2.0f), albedo, hg), nullBsdf()));
  IntegratorSettings settings;
  for (const float b : {0.0f, 0.8f}) {
    const Ray ray = rayAt({b, 0.1f, 4.0f}, {b, 0.1f, 0.0f});
    const Estimate a = estimate(het, settings, ray, 20000, 21), h = estimate(hom, settings, ray, 20000, 22);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(a.mean[c], h.mean[c], 5.0f * std::hypot(a.stderr_[c], h.stderr_[c]) + 1e-4f) << "b " << b << " channel " << c;
  }
}

// The image mean of a small volpath render of `medium` filling the box [−1,1]³, whose null walls
// coincide with a heterogeneous medium's bounds, over a diffuse floor under a sky: per channel the
// mean over `seeds` renders and its standard error from their spread.
Estimate boxRenderMean(const Medium& medium, int seeds) {
  Scene s;
  s.media.push_back(medium);
  const int null = test::addBsdf(s, nullBsdf());
  for (Mesh wall : test::insideOfBox(Vec3(-1), Vec3(1), null)) {
    wall.media.exterior = 0;  // the walls face inwards: their exterior is the box
    s.meshes.push_back(wall);
  }
  s.meshes.push_back(test::quad({-4, -1.01f, 4}, {4, -1.01f, 4}, {4, -1.01f, -4}, {-4, -1.01f, -4}, test::addBsdf(s, test::diffuse(Color(0.5f)))));
  test::addEmitter(s, test::constantEmitter(Color(1.0f)));
  s.integrator.type = "volpath";
  s.camera.toWorld = test::lookAt({0.3f, 1.5f, 5}, {0, 0, 0}, {0, 1, 0});
  s.camera.fovDegrees = 40.0f;
  s.film.width = s.film.height = 16;
  s.film.filter = "box";
  const test::World w(std::move(s));
  int seed = 0;
  return meanOf(seeds, 31, [&](Rng&) {
    RenderOptions o;
    o.spp = 16;
    o.seed = static_cast<uint64_t>(++seed);
    const Image img = w.renderPath(o);
    Color sum(0.0f);
    for (const Color& c : img.pixels) sum += c;
    return sum / float(img.pixels.size());
  });
}

// The same scene rendered (the path integrator's volpath core, whole images) with the box filled by a
// constant grid exactly over its walls and by the homogeneous medium of that density: both
// unbiased, so the image means agree within their seeds' noise.
TEST(HeterogeneousMedium, ConstantGridBoxRendersAsTheHomogeneousBox) {
  const Color albedo(0.8f, 0.6f, 0.4f);
  const Estimate a = boxRenderMean(heterogeneous(gridOver(Vec3(-1), Vec3(1), 2, 1, {1.5f, 1.5f}), 1.0f, albedo), 16);
  const Estimate h = boxRenderMean(homogeneous(Color(1.5f), albedo), 16);
  EXPECT_GT(a.mean.r, 0.1f);
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(a.mean[c], h.mean[c], 5.0f * std::hypot(a.stderr_[c], h.stderr_[c]) + 1e-4f) << "channel " << c;
}

// A lossless ramp medium (albedo 1) in a null sphere under a sky of 1 sees 1 everywhere: null
// collisions, ratio-tracked shadow rays, MIS and Russian roulette must balance. The 3-channel ramp
// (densities 1 : 0.4 : 0.1) needs Mitsuba's spectral weights at real collisions as well as at null ones.
TEST(HeterogeneousMedium, LosslessRampFurnaceIsOne) {
  std::vector<float> grey, rgb;
  for (int i = 0; i < 8; ++i) {
    grey.push_back(0.5f * float(i));
    for (const float c : {1.0f, 0.4f, 0.1f}) rgb.push_back(0.5f * float(i) * c);
  }
  for (const VolumePtr& density : {gridOver(Vec3(-1), Vec3(1), 8, 1, grey), gridOver(Vec3(-1), Vec3(1), 8, 3, rgb)}) {
    const test::World w(mediumSphere(heterogeneous(density, 1.0f, Color(1.0f)), nullBsdf()));
    for (const float b : {0.0f, 0.7f})
      expectNear(estimate(w, IntegratorSettings(), rayAt({b, 0.1f, 4.0f}, {b, 0.1f, 0.0f}), 20000, 23), Color(1.0f), "furnace");
  }
}

// Hostile numbers end in bounded work: a zero majorant is a vacuum (nothing drawn), and a majorant
// far beyond the loader's bound (built here by hand) stops at the collision cap with nothing
// transmitted instead of looping for ~10⁹ collisions.
TEST(HeterogeneousMedium, HostileMajorantsEndInBoundedWork) {
  const Ray ray = rayAt({-3, 0.5f, 0.5f}, {5, 0.5f, 0.5f});
  Medium empty = heterogeneous(gridOver(Vec3(0), Vec3(1), 2, 1, {0.0f, 0.0f}), 1.0f, Color(0.5f));
  Rng rng(5);
  EXPECT_EQ(mediumTransmittance(empty, ray, 8.0f, rng), Color(1.0f));
  const FreeFlight f = sampleFreeFlight(empty, ray, 8.0f, rng);
  EXPECT_FALSE(f.scattered);
  EXPECT_EQ(f.weight, Color(1.0f));

  Medium dense = heterogeneous(gridOver(Vec3(0), Vec3(1), 2, 1, {0.0f, 0.0f}), 1.0f, Color(0.5f));
  dense.majorant = 1e9f;  // σt 0 below it: every collision is null, transmittance stays 1
  EXPECT_EQ(mediumTransmittance(dense, ray, 8.0f, rng), Color(0.0f));
  const FreeFlight g = sampleFreeFlight(dense, ray, 8.0f, rng);
  EXPECT_FALSE(g.scattered);
  EXPECT_EQ(g.weight, Color(0.0f));
}

}  // namespace
}  // namespace rc
