// Rendering a MERL-format twin (the analytic BSDF tabulated by bsdf/merl_tabulate.h) equals
// rendering the analytic BSDF itself, with the path tracer and with rcache: the measured material
// enters only through eval/sample/pdf (path tracer) and its projected tables (rcache).
#include <gtest/gtest.h>

#include <cstdio>

#include "bsdf/merl_twins.h"
#include "core/image_metrics.h"
#include "test_scene.h"

namespace rc {
namespace {

Scene floorScene(const BsdfPtr& floor) {
  Scene s = test::boxScene(0.3f, 32, 24);
  s.bsdfs[0] = floor;
  return s;
}

// The box with the Beckmann α = 0.3 floor (a radiance-cached material) and with its twin.
struct TwinScenes {
  Scene analytic = floorScene(test::analyticForTwin("beckmann"));
  Scene twin = floorScene(test::merlTwin("beckmann"));
};

// Image means per channel within `relative` of each other.
void expectMeansAgree(const Image& test, const Image& reference, float relative) {
  Color a(0.0f), b(0.0f);
  for (const Color& c : test.pixels) a += c;
  for (const Color& c : reference.pixels) b += c;
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], relative * b[c]) << "channel " << c;
}

// Path tracer: the twin's image differs from the analytic one by no more than a second analytic
// render of other seeds does (noise; measured relMSE 0.00138 against 0.00135: 1.5× leaves room
// for other seeds), and the image means agree within 1% (the table's albedo error is ≤ 0.2%).
TEST(MerlTwinRender, PathTracerRendersTheTwinLikeTheAnalyticBsdf) {
  const TwinScenes s;
  const auto a1 = test::renderScene(s.analytic, test::pathSettings(s.analytic), 256, 1);
  const auto a2 = test::renderScene(s.analytic, test::pathSettings(s.analytic), 256, 2);
  const auto t = test::renderScene(s.twin, test::pathSettings(s.twin), 256, 3);
  const double noise = compareImages(a2.image.pixels, a1.image.pixels).relmse;
  const double twinErr = compareImages(t.image.pixels, a1.image.pixels).relmse;
  std::printf("path: relMSE twin vs analytic %.6f, analytic vs analytic %.6f\n", twinErr, noise);
  EXPECT_LT(twinErr, 1.5 * noise);
  expectMeansAgree(t.image, a1.image, 0.01f);
}

// rcache with the same seed and parameters: records, rays and lookups are the same, only the
// tables and the final pass's BSDF samples differ; the images agree far closer than rcache's own
// error against a converged reference (measured relMSE 0.00015 against 0.0029).
TEST(MerlTwinRender, RcacheRendersTheTwinLikeTheAnalyticBsdf) {
  const TwinScenes s;
  const auto ra = test::renderScene(s.analytic, test::rcacheSettings(s.analytic), 16, 5);
  const auto rt = test::renderScene(s.twin, test::rcacheSettings(s.twin), 16, 5);
  const auto ref = test::renderScene(s.analytic, test::pathSettings(s.analytic), 1024, 9);
  const double twinErr = compareImages(rt.image.pixels, ra.image.pixels).relmse;
  const double cacheErr = compareImages(ra.image.pixels, ref.image.pixels).relmse;
  std::printf("rcache: relMSE twin vs analytic %.6f, analytic vs reference %.6f\n", twinErr, cacheErr);
  EXPECT_LT(twinErr, 0.25 * cacheErr);
  expectMeansAgree(rt.image, ra.image, 0.01f);
}

}  // namespace
}  // namespace rc
