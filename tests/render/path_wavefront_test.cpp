// The batched (wavefront) path-tracing core against the scalar pathRadiance it replaces: the same
// numbers per sample, the same image within noise, and Embree's three batched query forms agreeing.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>

#include "core/image_metrics.h"
#include "core/parallel.h"
#include "render/film.h"
#include "render/camera.h"
#include "render/direct_light.h"
#include "render/path_integrator.h"
#include "render/path_wavefront.h"
#include "render/render_loop.h"
#include "render_test_scenes.h"

namespace rc {
namespace {

Image render(const test::World& w, PathCore core, BatchQuery query, int spp, uint64_t seed) {
  RenderContext ctx = w.context();
  ctx.options.spp = spp;
  ctx.options.seed = seed;
  RenderStats stats;
  return makePathIntegrator(w.scene.integrator, core, query)->render(ctx, stats);
}

// The test world: the Cornell-like box with a glossy back wall and an analytic sphere, paths of up
// to 8 segments with Russian roulette from the 3rd, so waves shrink unevenly over the bounces.
test::World world(int size) {
  Scene s = test::cornellLike(size, size);
  s.integrator.maxDepth = 8;
  s.integrator.rrDepth = 3;
  return test::World(std::move(s));
}

// An envmap lights the box from outside: the camera sees it beside the box, bounces leave through
// the open front (the wave's escaped segments, looked up in one vectorised pass).
test::World worldUnderEnvmap(int size) {
  Scene s = test::cornellLike(size, size);
  s.integrator.maxDepth = 8;
  s.integrator.rrDepth = 3;
  s.camera.fovDegrees = 70.0f;  // wider than the box
  Emitter env;
  env.type = EmitterType::Envmap;
  env.envWidth = 24;
  env.envHeight = 12;
  for (int y = 0; y < 12; ++y)
    for (int x = 0; x < 24; ++x)
      env.envPixels.push_back((x == 5 && y == 4) ? Color(30.0f, 20.0f, 10.0f) : Color(0.2f + 0.05f * y, 0.3f, 0.5f));
  test::addEmitter(s, env);
  return test::World(std::move(s));
}

// Per sample: the wave gives exactly pathRadiance's radiance. With one Embree call per ray
// (BatchQuery::Single) the rays and hits are the scalar path's own, so the results must be
// bit-identical; the stream and packet forms must agree on all but a negligible fraction (Embree's
// packet kernels may round a hit differently; none did on this scene when the test was written).
void expectSameRadiancePerSample(const test::World& w) {
  const RenderContext ctx = w.context();
  const CameraModel camera(w.scene.camera, 16, 16);
  const size_t n = 16 * 16 * 4;
  PathWave wave;
  std::vector<Rng> rngs0(n);
  std::vector<Color> scalar(n);
  std::vector<Ray> cameraRays(n);
  std::vector<Hit> cameraHits(n);
  for (size_t k = 0; k < n; ++k) {
    const int px = static_cast<int>(k / 4) % 16, py = static_cast<int>(k / 64);
    rngs0[k] = pixelRng(7, 16, px, py, static_cast<int>(k % 4));
    cameraRays[k] = camera.generate(Vec2(static_cast<float>(px), static_cast<float>(py)) + rngs0[k].next2D());
    cameraHits[k] = w.accel->intersect(cameraRays[k]);
    Rng rng = rngs0[k];
    scalar[k] = pathRadiance(ctx, w.scene.integrator, cameraRays[k], rng, &cameraHits[k]);
  }
  size_t lit = 0;
  for (const Color& c : scalar) lit += maxComponent(c) > 0.0f;
  ASSERT_GT(lit, n / 2);
  for (BatchQuery query : {BatchQuery::Single, BatchQuery::Stream, BatchQuery::Packet16}) {
    std::vector<Rng> rngs = rngs0;
    std::vector<Color> batch(n);
    pathRadianceBatch(ctx, w.scene.integrator, cameraRays.data(), cameraHits.data(), rngs.data(), n, batch.data(), wave, query);
    size_t same = 0;
    for (size_t k = 0; k < n; ++k) same += batch[k] == scalar[k];
    if (query == BatchQuery::Single) EXPECT_EQ(same, n);
    else EXPECT_GE(same, n - n / 1000) << "query " << static_cast<int>(query);
  }
}

TEST(PathWavefront, SameRadiancePerSampleAsTheScalarPath) { expectSameRadiancePerSample(world(16)); }

TEST(PathWavefront, SameRadiancePerSampleAsTheScalarPathUnderAnEnvmap) {
  const test::World w = worldUnderEnvmap(16);
  // The escaped segments are many: camera rays beside the box and bounces out of its front.
  const CameraModel camera(w.scene.camera, 16, 16);
  size_t escaped = 0;
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) escaped += !w.accel->intersect(camera.generate(Vec2(x + 0.5f, y + 0.5f))).valid();
  ASSERT_GT(escaped, 16u);
  expectSameRadiancePerSample(w);
}

// The batched light strategy gives each point exactly lightStrategyMis's value and leaves its Rng
// where lightStrategyMis leaves it, for one and for several light samples per point.
TEST(PathWavefront, BatchedLightStrategyMatchesPerPoint) {
  const test::World w = world(16);
  const RenderContext ctx = w.context();
  const std::vector<Hit> hits = w.pixelCentreHits(16);
  ASSERT_GT(hits.size(), 100u);
  std::vector<LightStrategyPoint> points;
  for (const Hit& h : hits) {
    const Frame frame = h.frame();
    const Vec3 toCamera = glm::normalize(Vec3(0, 1, 3.6f) - h.p);
    points.push_back({&h, frame, frame.toLocal(toCamera), w.scene.bsdfs[h.bsdf].get()});
  }
  LightBatchScratch scratch;
  for (int lightSamples : {1, 3}) {
    std::vector<Rng> rngsA, rngsB;
    for (size_t i = 0; i < points.size(); ++i) rngsA.emplace_back(11 + i, i), rngsB.emplace_back(11 + i, i);
    std::vector<Color> batch(points.size());
    lightStrategyMisBatch(ctx, points.data(), rngsA.data(), points.size(), lightSamples, batch.data(), scratch);
    size_t lit = 0;
    for (size_t i = 0; i < points.size(); ++i) {
      const LightStrategyPoint& p = points[i];
      const Color one = lightStrategyMis(ctx, *p.hit, p.frame, p.woLocal, *p.bsdf, rngsB[i], lightSamples);
      EXPECT_EQ(batch[i], one) << i;
      EXPECT_EQ(rngsA[i].nextUint(), rngsB[i].nextUint()) << i;
      lit += maxComponent(one) > 0.0f;
    }
    EXPECT_GT(lit, points.size() / 3);
    EXPECT_LT(lit, points.size());  // some points are in shadow
  }
}

// Batched queries return the single-ray answers: hits (t, primitive) and occlusion, for rays
// leaving the box's surfaces in every direction, including the sphere (user geometry).
TEST(PathWavefront, BatchedQueriesAgreeWithSingleRays) {
  const test::World w = world(8);
  Rng rng(3, 1);
  const size_t n = 1000;  // not a multiple of 16: the last packet is partial
  std::vector<Ray> rays(n);
  for (Ray& r : rays) {
    r.o = Vec3(-0.9f, 0.1f, -0.9f) + Vec3(1.8f, 1.8f, 1.8f) * Vec3(rng.nextFloat(), rng.nextFloat(), rng.nextFloat());
    const float z = 1.0f - 2.0f * rng.nextFloat(), phi = 2.0f * kPi * rng.nextFloat(), s = std::sqrt(1.0f - z * z);
    r.d = Vec3(s * std::cos(phi), s * std::sin(phi), z);
    r.tMax = 0.2f + 2.0f * rng.nextFloat();  // some shadow-like rays stop short of any surface
  }
  std::vector<Hit> single(n);
  std::vector<uint8_t> singleBlocked(n);
  size_t sphereHits = 0, blockedCount = 0;
  for (size_t i = 0; i < n; ++i) {
    single[i] = w.accel->intersect(rays[i]);
    singleBlocked[i] = w.accel->occluded(rays[i]) ? 1 : 0;
    sphereHits += single[i].sphere >= 0;
    blockedCount += singleBlocked[i];
  }
  ASSERT_GT(sphereHits, 10u);
  ASSERT_GT(blockedCount, n / 10);
  ASSERT_LT(blockedCount, n - n / 10);
  for (BatchQuery query : {BatchQuery::Stream, BatchQuery::Packet16}) {
    std::vector<Hit> hits(n);
    std::vector<uint8_t> blocked(n);
    w.accel->intersectBatch(rays.data(), hits.data(), n, query);
    w.accel->occludedBatch(rays.data(), blocked.data(), n, query);
    for (size_t i = 0; i < n; ++i) {
      EXPECT_EQ(hits[i].valid(), single[i].valid()) << i;
      EXPECT_EQ(hits[i].prim, single[i].prim) << i;
      EXPECT_EQ(hits[i].mesh, single[i].mesh) << i;
      EXPECT_EQ(hits[i].sphere, single[i].sphere) << i;
      if (single[i].valid()) EXPECT_NEAR(hits[i].t, single[i].t, 1e-5f * single[i].t) << i;
      EXPECT_EQ(blocked[i], singleBlocked[i]) << i;
      EXPECT_EQ(blocked[i] != 0, single[i].valid() && single[i].t <= rays[i].tMax) << i;
    }
  }
}

// Whole images: the wavefront image is within noise of a high-spp reference of the scalar path,
// as close as the scalar image at the same spp (relMSE), and no 16×16 block is biased: each
// block's mean over independent seeds matches the reference block within 5 standard errors
// (estimated from the seeds' spread, plus the reference's own, kRefSpp/kSpp times smaller in variance).
TEST(PathWavefront, ImageAgreesWithTheScalarPathWithinNoise) {
  constexpr int kSize = 48, kSeeds = 4, kSpp = 16, kRefSpp = 256;
  const test::World w = world(kSize);
  setThreadCount(2);
  const Image ref = render(w, PathCore::Scalar, BatchQuery::Single, kRefSpp, 999);
  std::vector<Image> wave, scalar;
  double relWave = 0.0, relScalar = 0.0;
  for (int s = 1; s <= kSeeds; ++s) {
    wave.push_back(render(w, PathCore::Wavefront, BatchQuery::Packet16, kSpp, 100 + s));
    scalar.push_back(render(w, PathCore::Scalar, BatchQuery::Single, kSpp, 200 + s));
    relWave += compareImages(wave.back().pixels, ref.pixels).relmse / kSeeds;
    relScalar += compareImages(scalar.back().pixels, ref.pixels).relmse / kSeeds;
  }
  setThreadCount(0);
  EXPECT_GT(relScalar, 0.0);
  EXPECT_LT(relWave, 1.25 * relScalar);
  EXPECT_GT(relWave, 0.8 * relScalar);
  const int blocks = kSize / 16;
  int checked = 0;
  for (int by = 0; by < blocks; ++by)
    for (int bx = 0; bx < blocks; ++bx)
      for (int c = 0; c < 3; ++c) {
        auto blockMean = [&](const Image& img) {
          double sum = 0.0;
          for (int y = by * 16; y < by * 16 + 16; ++y)
            for (int x = bx * 16; x < bx * 16 + 16; ++x) sum += img.pixels[static_cast<size_t>(y) * kSize + x][c];
          return sum / 256.0;
        };
        double mean = 0.0, sq = 0.0;
        for (const Image& img : wave) mean += blockMean(img) / kSeeds;
        for (const Image& img : wave) sq += (blockMean(img) - mean) * (blockMean(img) - mean);
        const double renderVariance = sq / (kSeeds - 1);
        const double se = std::sqrt(renderVariance / kSeeds + renderVariance * kSpp / kRefSpp);
        const double r = blockMean(ref);
        if (r <= 0.0) continue;
        // A floor of 0.1 % of the block's mean keeps a noiseless block from demanding exact equality.
        EXPECT_LT(std::fabs(mean - r), 5.0 * std::max(se, 1e-3 * r)) << "block " << bx << "," << by << " channel " << c;
        ++checked;
      }
  EXPECT_GE(checked, blocks * blocks * 3 / 2);
}

// The sample loop fills its per-row Rngs in place (reused from row to row): every sample must still
// get exactly pixelRng's stream, with its film position drawn first, for both samplers.
TEST(PathWavefront, SampleLoopGivesEverySampleItsPixelRng) {
  for (bool lowDiscrepancy : {false, true}) {
    FilmSettings fs;
    fs.width = 40;
    fs.height = 36;
    Film film(fs);
    RenderLoopSettings loop;
    loop.spp = 3;
    loop.seed = 17;
    loop.lowDiscrepancy = lowDiscrepancy;
    loop.tileSize = 16;
    std::atomic<int> mismatches{0}, samples{0};
    setThreadCount(2);
    const test::World w = world(8);
    const RenderContext ctx = w.context();
    renderSamples(ctx, film, loop, [&](const SampleInput& in, Rng& rng, TileFilm&) {
      Rng expected = pixelRng(loop.seed, fs.width, in.px, in.py, in.sampleIndex, lowDiscrepancy);
      const Vec2 filmPos = Vec2(static_cast<float>(in.px), static_cast<float>(in.py)) + expected.next2D();
      bool same = filmPos == in.filmPos;
      for (int i = 0; i < 30; ++i) same &= rng.nextUint() == expected.nextUint();
      mismatches += !same;
      ++samples;
      return Color(0.0f);
    });
    setThreadCount(0);
    EXPECT_EQ(samples.load(), 40 * 36 * 3);
    EXPECT_EQ(mismatches.load(), 0) << "lowDiscrepancy " << lowDiscrepancy;
  }
}

}  // namespace
}  // namespace rc
