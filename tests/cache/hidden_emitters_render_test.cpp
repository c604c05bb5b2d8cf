// hide_emitters with an area emitter in view (render/hidden_emitters.h), as Mitsuba 3 defines it
// (src/integrators/path.cpp, direct.cpp, volpath.cpp: Integrator::skip_area_emitters): a camera ray
// passes every area emitter it meets and shades what lies behind, while the emitter still lights the
// scene and still blocks light. The scene: the floor of closed_form_image.h, a one-sided emitting
// square (radiance 4, facing the camera) at height 2 covering the middle of the view, and a point
// light on the axis at height 1 (under the square: it lights the floor unshadowed) or 3 (over it: the
// square shadows the floor behind it). max_depth 2, so the floor's radiance is the point light's
// alone: ρ/π · I · cos θ / d², d² = 1 + x² + y², cos θ = 1/d; the square's back, which the floor sees,
// emits nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "closed_form_image.h"
#include "core/math.h"
#include "core/rng.h"
#include "render/camera.h"
#include "render/path_integrator.h"
#include "render/volpath.h"
#include "scene/scene_test_util.h"
#include "test_scene.h"

namespace rc::test {
namespace {

constexpr float kRho = 0.5f, kIntensity = 10.0f, kLe = 4.0f, kHalfSide = 0.6f, kSquareZ = 2.0f;

std::string squareInFront(bool hide, float lightZ) {
  return floorScene("<integrator type=\"path\"><integer name=\"max_depth\" value=\"2\"/><boolean name=\"hide_emitters\" value=\"" +
                        std::string(hide ? "true" : "false") + "\"/></integrator>\n"
                        "<shape type=\"rectangle\"><transform name=\"to_world\"><scale value=\"" + std::to_string(kHalfSide) +
                        "\"/><translate z=\"" + std::to_string(kSquareZ) + "\"/></transform>"
                        "<emitter type=\"area\"><rgb name=\"radiance\" value=\"" + std::to_string(kLe) + "\"/></emitter></shape>\n"
                        "<emitter type=\"point\"><point name=\"position\" x=\"0\" y=\"0\" z=\"" + std::to_string(lightZ) +
                        "\"/><rgb name=\"intensity\" value=\"" + std::to_string(kIntensity) + "\"/></emitter>",
                    kRho);
}

// The floor's radiance at p under the light at height 1.
double floorRadiance(const Vec3& p) {
  const double d2 = 1.0 + double(p.x) * p.x + double(p.y) * p.y;
  return kRho / kPiD * kIntensity / (d2 * std::sqrt(d2));
}

// Pixels whose whole footprint lies behind the square (all four corners' rays cross it).
std::vector<size_t> pixelsBehindTheSquare(const Scene& s) {
  const CameraModel cam(s.camera, s.film);
  const int w = s.film.imageWidth(), h = s.film.imageHeight();
  std::vector<size_t> out;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      bool inside = true;
      for (const Vec2 corner : {Vec2(x, y), Vec2(x + 1, y), Vec2(x, y + 1), Vec2(x + 1, y + 1)}) {
        const Ray r = cam.generate(corner);
        const Vec3 p = r.o + ((kSquareZ - r.o.z) / r.d.z) * r.d;
        inside = inside && std::fabs(p.x) < kHalfSide && std::fabs(p.y) < kHalfSide;
      }
      if (inside) out.push_back(size_t(y) * w + x);
    }
  return out;
}

IntegratorSettings settingsFor(const Scene& s, const std::string& integrator) {
  if (integrator == "rcache") return rcacheSettings(s, {{"fallback", "false"}});
  IntegratorSettings is = s.integrator;
  is.type = integrator;
  return is;
}

// Shown, the square covers its pixels with exactly its radiance; hidden, they show the lit floor
// behind it: the ratio to the closed form, averaged over those pixels, within 5σ of its scatter
// (light selection makes each sample noisy) plus 0.5 %.
TEST(HiddenEmitters, CameraRaysPassAnAreaEmitterToTheFloorBehind) {
  TempDir dir;
  for (const std::string integrator : {"path", "direct", "rcache"}) {
    for (const bool hide : {false, true}) {
      const Scene s = loadText(dir, squareInFront(hide, 1.0f));
      const std::vector<size_t> behind = pixelsBehindTheSquare(s);
      ASSERT_GE(behind.size(), 25u);
      const std::vector<PixelExpectation> floor = expectedFloorImage(s, floorRadiance);
      const Image img = renderScene(s, settingsFor(s, integrator), 64, 3).image;
      double sum = 0.0, sum2 = 0.0;
      for (const size_t i : behind) {
        const double got = img.pixels[i].g;
        if (!hide) EXPECT_NEAR(got, kLe, 1e-4 * kLe) << integrator << " pixel " << i;
        const double ratio = got / floor[i].mean;
        sum += ratio;
        sum2 += ratio * ratio;
      }
      if (!hide) continue;
      const double n = double(behind.size()), mean = sum / n;
      const double stderr_ = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / (n - 1.0));
      EXPECT_NEAR(mean, 1.0, 5.0 * stderr_ + 0.005) << integrator;
    }
  }
}

// With the light over the square the floor behind it lies in the square's shadow: hidden from the
// camera, the square still blocks the light, so those pixels are exactly black.
TEST(HiddenEmitters, AHiddenEmitterStillCastsItsShadow) {
  TempDir dir;
  const Scene s = loadText(dir, squareInFront(true, 3.0f));
  const std::vector<size_t> behind = pixelsBehindTheSquare(s);
  ASSERT_GE(behind.size(), 25u);
  for (const std::string integrator : {"path", "direct", "rcache"}) {
    const Image img = renderScene(s, settingsFor(s, integrator), 16, 5).image;
    for (const size_t i : behind) EXPECT_EQ(img.pixels[i].g, 0.0f) << integrator << " pixel " << i;
    // Around the square's shadow (light at height 3: it reaches |x|, |y| ≤ 1.8 on the floor) the floor is lit.
    EXPECT_GT(img.pixels[0].g, 0.0f) << integrator;
  }
}

// The scalar path tracer and the volumetric one (which the path integrator runs on scenes with media)
// take the same camera ray through the square: the mean of many samples of the ray onto the floor's
// centre is the closed form there, ρ/π · I.
TEST(HiddenEmitters, ScalarAndVolumetricPathTracersPassTheEmitterToo) {
  TempDir dir;
  const Scene s = loadText(dir, squareInFront(true, 1.0f));
  const Accel accel(s);
  const LightSampler lights(s);
  const RenderContext ctx{s, accel, lights, {}};
  Ray down;
  down.o = Vec3(0.01f, 0.02f, 5.0f);
  down.d = Vec3(0.0f, 0.0f, -1.0f);
  const double expected = floorRadiance(Vec3(0.01f, 0.02f, 0.0f));
  for (const bool volumetric : {false, true}) {
    double sum = 0.0, sum2 = 0.0;
    const int n = 20000;
    for (int i = 0; i < n; ++i) {
      Rng rng(hashMix(13, volumetric, i));
      const double v = (volumetric ? volPathRadiance(ctx, s.integrator, down, rng) : pathRadiance(ctx, s.integrator, down, rng))[1];
      sum += v;
      sum2 += v * v;
    }
    const double mean = sum / n, stderr_ = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / (n - 1.0));
    EXPECT_NEAR(mean, expected, 5.0 * stderr_ + 1e-3 * expected) << (volumetric ? "volpath" : "path");
  }
}

}  // namespace
}  // namespace rc::test
