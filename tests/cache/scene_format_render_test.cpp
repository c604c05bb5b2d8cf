// Scene-format features rendered end to end (XML → loader → both integrators) against closed forms.
#include <gtest/gtest.h>

#include <cmath>

#include "render/camera.h"
#include "scene/scene_test_util.h"
#include "test_scene.h"

namespace rc::test {
namespace {

// A 10×10 diffuse floor (reflectance ρ) at z = 0 seen from (0, 0, 5) straight down, box filter.
std::string floorScene(const std::string& lights, float rho = 0.5f) {
  return "<scene version=\"3.0.0\">\n"
         "<sensor type=\"perspective\"><float name=\"fov\" value=\"60\"/>"
         "<transform name=\"to_world\"><lookat origin=\"0, 0, 5\" target=\"0, 0, 0\" up=\"0, 1, 0\"/></transform>"
         "<film type=\"hdrfilm\"><integer name=\"width\" value=\"24\"/><integer name=\"height\" value=\"24\"/>"
         "<rfilter type=\"box\"/></film></sensor>\n"
         "<shape type=\"rectangle\"><transform name=\"to_world\"><scale value=\"5\"/></transform>"
         "<bsdf type=\"diffuse\"><rgb name=\"reflectance\" value=\"" + std::to_string(rho) + "\"/></bsdf></shape>\n" +
         lights + "\n</scene>\n";
}

struct PixelExpectation {
  float mean = 0.0f;    // average of radiance(p) over the pixel
  float spread = 0.0f;  // its standard deviation over the pixel: one sample's noise under a box filter
};

// radiance(p) over the floor points p the camera sees, per pixel (16×16 positions per pixel).
template <class Radiance>
std::vector<PixelExpectation> expectedFloorImage(const Scene& s, Radiance radiance) {
  const CameraModel cam(s.camera, s.film);
  const int w = s.film.imageWidth(), h = s.film.imageHeight();
  std::vector<PixelExpectation> out(size_t(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double sum = 0.0, sum2 = 0.0;
      for (int j = 0; j < 16; ++j)
        for (int i = 0; i < 16; ++i) {
          const Ray r = cam.generate(Vec2(x + (i + 0.5f) / 16.0f, y + (j + 0.5f) / 16.0f));
          const float t = -r.o.z / r.d.z;
          const double v = radiance(r.o + t * r.d);
          sum += v;
          sum2 += v * v;
        }
      const double mean = sum / 256.0;
      out[size_t(y) * w + x] = {float(mean), float(std::sqrt(std::max(0.0, sum2 / 256.0 - mean * mean)))};
    }
  return out;
}

// Spot at height 2 pointing down (cutoff 30°, beam 20°): the floor's radiance is
// ρ/π · I · falloff(θ) · cos θ / d², with Mitsuba's linear falloff in θ. Both integrators (the
// floor's indirect light is zero: nothing else reflects), every pixel within noise of the pixel
// average (5σ of the pixel's own spread at 64 spp, plus 0.5 % for float rounding), and exactly
// black where the whole pixel lies outside the cone.
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
    int dark = 0, lit = 0;
    for (size_t i = 0; i < expected.size(); ++i) {
      const float got = img.pixels[i].g;
      if (expected[i].mean == 0.0f) {
        EXPECT_EQ(got, 0.0f) << (cache ? "rcache" : "path") << " pixel " << i;
        ++dark;
      } else {
        // Only the pixel position varies between samples: the noise is the pixel's own spread.
        EXPECT_NEAR(got, expected[i].mean, 5.0f * expected[i].spread / 8.0f + 0.005f * expected[i].mean)
            << (cache ? "rcache" : "path") << " pixel " << i;
        lit += expected[i].mean > 0.9f * peak;
      }
    }
    EXPECT_GT(dark, 100);
    EXPECT_GT(lit, 10);
  }
}

}  // namespace
}  // namespace rc::test
