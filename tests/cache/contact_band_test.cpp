// Where a sphere touches a floor the floor's light falls steeply toward the contact and levels off
// a little way out. The cache must not carry the brighter neighbourhood into the contact: the
// floor pixels touching the sphere's silhouette in front of it have the path tracer's mean within
// the seeds' noise. Records whose gradient limit allowed a first-order change of their whole size
// over the reach a·R (before the eleventh session) made this band about +1 % bright at 16 spp
// (bench/RESULTS.md, contact17: with these seeds 1.014 of the path tracer, z 5.9; after 1.001).
// The budget shrinks a and r_min with spp, so the band is checked at 16 and at 64 spp. At 64 spp
// this scene's band (46 px, 4 reference renders) resolves an error of about 0.8 %, not the few
// tenths of a percent in front of other contacts (bench/RESULTS.md, bias17, twelfth session).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "test_scene.h"

namespace rc {
namespace {

constexpr int kSize = 48, kRefSpp = 1024, kRefSeeds = 4;

// A diffuse blue sphere resting on a grey floor under a uniform sky (cached whole: the sky's light
// reaches the floor through the records), seen from the front and above.
Scene sphereOnFloor() {
  Scene s;
  s.bsdfs.push_back(test::diffuse(0.5f, 0.5f, 0.5f));
  s.bsdfs.push_back(test::diffuse(0.2f, 0.3f, 0.8f));
  test::addQuad(s, {-6, 0, 6}, {6, 0, 6}, {6, 0, -6}, {-6, 0, -6}, 0);
  test::addSphere(s, "resting", Vec3(0, 0.5f, 0), 0.5f, 1);
  Emitter sky;
  sky.type = EmitterType::Constant;
  sky.radiance = Color(1.0f);
  s.emitters.push_back(sky);
  test::setTestCamera(s, Vec3(0, 1.55f, 2.6f), Vec3(0, 0.35f, 0), kSize, kSize);
  return s;
}

// The floor pixels within 1.5 px of the sphere's silhouette and below its centroid row (the floor
// in front of the contact). The sphere is where blue exceeds 1.6× red in the reference.
std::vector<size_t> contactBand(const Image& ref) {
  std::vector<char> sphere(ref.pixels.size());
  double rowSum = 0.0, count = 0.0;
  for (size_t i = 0; i < ref.pixels.size(); ++i) {
    sphere[i] = ref.pixels[i].b > 1.6f * ref.pixels[i].r;
    if (sphere[i]) rowSum += static_cast<double>(i / kSize), count += 1.0;
  }
  const double centroidRow = rowSum / count;
  std::vector<size_t> band;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      if (sphere[static_cast<size_t>(y) * kSize + x] || y <= centroidRow) continue;
      bool touches = false;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int u = x + dx, v = y + dy;
          touches |= u >= 0 && v >= 0 && u < kSize && v < kSize && sphere[static_cast<size_t>(v) * kSize + u] != 0;
        }
      if (touches) band.push_back(static_cast<size_t>(y) * kSize + x);
    }
  return band;
}

// Each image's mean over the band of the sum of its channels.
std::vector<double> bandMeans(const std::vector<Image>& images, const std::vector<size_t>& band) {
  std::vector<double> means;
  for (const Image& img : images) {
    double sum = 0.0;
    for (size_t i : band) sum += img.pixels[i].r + img.pixels[i].g + img.pixels[i].b;
    means.push_back(sum / static_cast<double>(band.size()));
  }
  return means;
}

void meanAndStandardError(const std::vector<double>& v, double& mean, double& se) {
  mean = 0.0;
  for (double x : v) mean += x / static_cast<double>(v.size());
  double sq = 0.0;
  for (double x : v) sq += (x - mean) * (x - mean);
  se = std::sqrt(sq / (static_cast<double>(v.size()) - 1.0) / static_cast<double>(v.size()));
}

// The band's mean of `seeds` rcache renders at `spp` against the path tracer's, in standard errors.
// The path tracer's renders, made once for both budgets.
const std::vector<Image>& pathReferences(const Scene& s) {
  static const std::vector<Image> refs = [&] {
    std::vector<Image> r;
    for (int seed = 0; seed < kRefSeeds; ++seed)
      r.push_back(test::renderScene(s, test::pathSettings(s), kRefSpp, 101 + seed).image);
    return r;
  }();
  return refs;
}

void expectContactBandUnbiased(int spp, int seeds) {
  const Scene s = sphereOnFloor();
  const std::vector<Image>& refs = pathReferences(s);
  std::vector<Image> renders;
  for (int seed = 0; seed < seeds; ++seed) {
    const auto r = test::renderScene(s, test::rcacheSettings(s), spp, 1 + seed);
    if (seed == 0) EXPECT_EQ(test::statText(r.stats, "env_cache"), "whole environment cached");
    renders.push_back(r.image);
  }
  const std::vector<size_t> band = contactBand(refs[0]);
  ASSERT_GE(band.size(), 20u);
  double mean, se, refMean, refSe;
  meanAndStandardError(bandMeans(renders, band), mean, se);
  meanAndStandardError(bandMeans(refs, band), refMean, refSe);
  const double combined = std::sqrt(se * se + refSe * refSe);
  std::printf("contact band (%zu px), %d spp: rcache / path tracer %.4f, z %.2f (standard error %.4f of the mean)\n",
              band.size(), spp, mean / refMean, (mean - refMean) / combined, combined / refMean);
  // Unbiased: within 4 standard errors, no slack.
  EXPECT_LT(std::fabs(mean - refMean), 4.0 * combined);
}

TEST(ContactBand, FloorAtASpheresContactHasThePathTracersMeanAt16Spp) { expectContactBandUnbiased(16, 12); }

TEST(ContactBand, FloorAtASpheresContactHasThePathTracersMeanAt64Spp) { expectContactBandUnbiased(64, 12); }

}  // namespace
}  // namespace rc
