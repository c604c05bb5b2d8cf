// The batched direct light of secondary points (record-ray hits, path continuations) against the
// scalar estimators it stands for: the same value per point and the RNG left where they leave it.
#include <gtest/gtest.h>

#include "cache/direct_light_batch.h"
#include "render/camera.h"
#include "render/render_test_scenes.h"

namespace rc {
namespace {

TEST(DirectLightBatch, EachEstimatorMatchesItsScalarFunction) {
  const test::World w(test::cornellLike(16, 16));
  const RenderContext ctx = w.context();
  const std::vector<Hit> hits = w.pixelCentreHits(16);
  ASSERT_GT(hits.size(), 100u);
  DirectLightScratch scratch;
  for (DirectEstimator estimator : {DirectEstimator::LightOnly, DirectEstimator::LightStrategy, DirectEstimator::Full})
    for (int lightSamples : {1, 3}) {
      std::vector<DirectLightJob> jobs;
      for (size_t i = 0; i < hits.size(); ++i) {
        const Hit& h = hits[i];
        const Frame frame = h.frame();
        const Vec3 wo = frame.toLocal(glm::normalize(Vec3(0, 1, 3.6f) - h.p));
        jobs.push_back({&ctx, &h, frame, wo, w.scene.bsdfs[h.bsdf].get(), Rng(5 + i, 1), estimator, lightSamples});
      }
      std::vector<Color> batch(jobs.size());
      directLightBatch(jobs, batch.data(), scratch);
      size_t lit = 0;
      for (size_t i = 0; i < jobs.size(); ++i) {
        const Hit& h = hits[i];
        const Bsdf& bsdf = *w.scene.bsdfs[h.bsdf];
        Rng rng(5 + i, 1);
        const Color one =
            estimator == DirectEstimator::LightOnly       ? directLightLightOnly(ctx, h, jobs[i].frame, jobs[i].wo, bsdf, rng)
            : estimator == DirectEstimator::LightStrategy ? lightStrategyMis(ctx, h, jobs[i].frame, jobs[i].wo, bsdf, rng, lightSamples)
                                                          : directLight(ctx, h, jobs[i].frame, jobs[i].wo, bsdf, rng, lightSamples);
        EXPECT_EQ(batch[i], one) << "point " << i << " estimator " << static_cast<int>(estimator);
        EXPECT_EQ(jobs[i].rng.nextUint(), rng.nextUint()) << i;
        lit += maxComponent(one) > 0.0f;
      }
      EXPECT_GT(lit, jobs.size() / 3);
      EXPECT_LT(lit, jobs.size());  // some points are in shadow
    }
}

}  // namespace
}  // namespace rc
