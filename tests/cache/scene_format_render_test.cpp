// Scene-format features rendered end to end (XML → loader → both integrators) against closed forms.
#include <gtest/gtest.h>

#include <cmath>

#include "closed_form_image.h"
#include "render/camera.h"
#include "scene/scene_test_util.h"
#include "test_scene.h"

namespace rc::test {
namespace {

// Every pixel of the green channel within 5σ of the pixel's own spread at `spp` (box filter,
// deterministic light: only the sample position varies) plus 0.5 % for float rounding; exactly
// black where the whole pixel is. Returns the number of non-black pixels checked.
int expectImageMatches(const Image& img, const std::vector<PixelExpectation>& expected, int spp, const char* what) {
  int lit = 0;
  for (size_t i = 0; i < expected.size(); ++i) {
    const float got = img.pixels[i].g;
    if (expected[i].mean == 0.0f) {
      EXPECT_EQ(got, 0.0f) << what << " pixel " << i;
    } else {
      EXPECT_NEAR(got, expected[i].mean, 5.0f * expected[i].spread / std::sqrt(float(spp)) + 0.005f * expected[i].mean)
          << what << " pixel " << i;
      ++lit;
    }
  }
  return lit;
}

// Spot at height 2 pointing down (cutoff 30°, beam 20°): the floor's radiance is
// ρ/π · I · falloff(θ) · cos θ / d², with Mitsuba's linear falloff in θ. Both integrators (the
// floor's indirect light is zero: nothing else reflects), every pixel within noise of the pixel
// average, and exactly black where the whole pixel lies outside the cone.
TEST(SceneFormatRender, SpotLightOnAFloorMatchesTheClosedForm) {
  TempDir dir;
  const Scene s = loadText(dir, floorScene("<emitter type=\"spot\"><rgb name=\"intensity\" value=\"6\"/>"
                                           "<float name=\"cutoff_angle\" value=\"30\"/><float name=\"beam_width\" value=\"20\"/>"
                                           "<transform name=\"to_world\"><lookat origin=\"0, 0, 2\" target=\"0, 0, 0\" up=\"0, 1, 0\"/>"
                                           "</transform></emitter>"));
  const float kPiF = 3.14159265358979f;
  const auto expected = expectedFloorImage(s, [&](const Vec3& p) {
    const float d2 = 4.0f + p.x * p.x + p.y * p.y, d = std::sqrt(d2), cosT = 2.0f / d;
    const float theta = std::acos(cosT), beam = 20.0f * kPiF / 180.0f, cut = 30.0f * kPiF / 180.0f;
    const float falloff = theta <= beam ? 1.0f : theta >= cut ? 0.0f : (cut - theta) / (cut - beam);
    return 0.5f / kPiF * 6.0f * falloff * cosT / d2;
  });
  const float peak = 0.5f / kPiF * 6.0f / 4.0f;
  for (const bool cache : {false, true}) {
    const auto settings = cache ? rcacheSettings(s, {{"fallback", "false"}}) : pathSettings(s);
    const Image img = renderScene(s, settings, 64, 1).image;
    const int lit = expectImageMatches(img, expected, 64, cache ? "rcache" : "path");
    EXPECT_GT(int(expected.size()) - lit, 100);
    int full = 0;
    for (const PixelExpectation& e : expected) full += e.mean > 0.9f * peak;
    EXPECT_GT(full, 10);
  }
}

}  // namespace
}  // namespace rc::test

namespace rc::test {
namespace {

// A diffuse cylinder (radius 0.5, axis z from 0 to 1) under a directional light perpendicular to
// its axis, seen from the side: L = ρ/π · E · max(0, n·l) on the lit half (the outside is convex:
// no shadows, no interreflection), black elsewhere. Hits computed here from the closed form.
TEST(SceneFormatRender, CylinderUnderADirectionalLightMatchesTheClosedForm) {
  TempDir dir;
  const Scene s = loadText(dir, "<scene version=\"3.0.0\">\n"
      "<sensor type=\"perspective\"><float name=\"fov\" value=\"30\"/>"
      "<transform name=\"to_world\"><lookat origin=\"0, -5, 0.5\" target=\"0, 0, 0.5\" up=\"0, 0, 1\"/></transform>"
      "<film type=\"hdrfilm\"><integer name=\"width\" value=\"24\"/><integer name=\"height\" value=\"24\"/>"
      "<rfilter type=\"box\"/></film></sensor>\n"
      "<shape type=\"cylinder\"><float name=\"radius\" value=\"0.5\"/>"
      "<bsdf type=\"diffuse\"><rgb name=\"reflectance\" value=\"0.5\"/></bsdf></shape>\n"
      "<emitter type=\"directional\"><vector name=\"direction\" value=\"1, 1, 0\"/><rgb name=\"irradiance\" value=\"2\"/></emitter>\n"
      "</scene>\n");
  const float kPiF = 3.14159265358979f;
  const Vec3 toLight = glm::normalize(Vec3(-1, -1, 0));
  const auto expected = expectedImage(s, [&](const Ray& r) -> double {
    // x² + y² = 0.25 along the ray; the nearest root with 0 ≤ z ≤ 1.
    const double a = double(r.d.x) * r.d.x + double(r.d.y) * r.d.y, b = 2.0 * (double(r.o.x) * r.d.x + double(r.o.y) * r.d.y),
                 c = double(r.o.x) * r.o.x + double(r.o.y) * r.o.y - 0.25, disc = b * b - 4 * a * c;
    if (disc < 0.0 || a == 0.0) return 0.0;
    for (const double t : {(-b - std::sqrt(disc)) / (2 * a), (-b + std::sqrt(disc)) / (2 * a)}) {
      const Vec3 p = r.o + float(t) * r.d;
      if (t <= 0.0 || p.z < 0.0f || p.z > 1.0f) continue;
      const Vec3 n = glm::normalize(Vec3(p.x, p.y, 0.0f));
      return 0.5 / kPiF * 2.0 * std::max(0.0f, glm::dot(n, toLight));
    }
    return 0.0;
  });
  for (const bool cache : {false, true}) {
    const auto settings = cache ? rcacheSettings(s, {{"fallback", "false"}}) : pathSettings(s);
    const int lit = expectImageMatches(renderScene(s, settings, 64, 1).image, expected, 64, cache ? "rcache" : "path");
    // Not vacuous: the tube spans about 9×9 of the 24×24 pixels (1 unit at distance 5 under a 30° fov,
    // ≈ 9 px per unit), and the light reaches about three quarters of its visible width.
    EXPECT_GT(lit, 60);
  }
}

}  // namespace
}  // namespace rc::test
