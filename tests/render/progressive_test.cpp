// renderProgressive (render/progressive.h): passes are disjoint sample indices of one render, the
// film sums them with their filter weights, and the budget never cuts the first pass.
#include <gtest/gtest.h>

#include <cmath>

#include "render/path_integrator.h"
#include "render/progressive.h"
#include "render_test_scenes.h"

namespace rc {
namespace {

// A Gaussian filter: splats reach neighbouring pixels with weights that differ per sample, so a
// pass-by-pass average of developed images would differ from the render; summing films does not.
test::World gaussianBox(const std::string& sampler) {
  Scene s = test::cornellLike(16, 16);
  s.film.filter = "gaussian";
  s.sampler.type = sampler;
  return test::World(std::move(s));
}

Image renderPasses(const test::World& w, int passSpp, const ProgressiveSettings& settings, RenderStats& stats) {
  RenderContext ctx = w.context();
  ctx.options.spp = passSpp;
  ctx.options.seed = 11;
  return renderProgressive(*makePathIntegrator(w.scene.integrator), ctx, settings, stats);
}

// Equal up to the order of the film's double sums, rounded to float once.
void expectSameImage(const Image& a, const Image& b) {
  ASSERT_EQ(a.pixels.size(), b.pixels.size());
  for (size_t i = 0; i < a.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) ASSERT_NEAR(a.pixels[i][c], b.pixels[i][c], 1e-5f * (1.0f + std::fabs(b.pixels[i][c]))) << i;
}

TEST(Progressive, PassesAreTheSamplesOfOneRender) {
  for (const char* sampler : {"independent", "ldsampler"}) {
    const test::World w = gaussianBox(sampler);
    RenderStats stats;
    const Image passes = renderPasses(w, 2, {1e6, 3}, stats);
    RenderOptions whole;
    whole.spp = 6;
    whole.seed = 11;
    expectSameImage(passes, w.renderPath(whole));
    EXPECT_EQ(stats.get("passes"), 3.0);
    EXPECT_EQ(stats.get("pass_spp"), 2.0);
    EXPECT_EQ(stats.get("spp"), 6.0);
    EXPECT_EQ(stats.get("passes_dropped"), 0.0);
    // ... and not the render of another set of samples.
    RenderOptions fewer = whole;
    fewer.spp = 4;
    const Image four = w.renderPath(fewer);
    double diff = 0.0;
    for (size_t i = 0; i < four.pixels.size(); ++i) diff += std::fabs(four.pixels[i].r - passes.pixels[i].r);
    EXPECT_GT(diff, 0.0);
  }
}

TEST(Progressive, BudgetNeverCutsTheFirstPass) {
  const test::World w = gaussianBox("independent");
  RenderStats stats;
  const Image one = renderPasses(w, 2, {1e-9, 0}, stats);
  EXPECT_EQ(stats.get("passes"), 1.0);
  EXPECT_EQ(stats.get("spp"), 2.0);
  EXPECT_EQ(stats.get("interrupted"), 0.0);
  RenderOptions whole;
  whole.spp = 2;
  whole.seed = 11;
  expectSameImage(one, w.renderPath(whole));
}

}  // namespace
}  // namespace rc
