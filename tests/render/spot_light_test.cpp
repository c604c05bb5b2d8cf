// Mitsuba's `spot` emitter: its parameters as the loader reads them, and the intensity the light
// sampler returns in each part of its profile (full beam, linear transition, dark).
#include <gtest/gtest.h>

#include <cmath>

#include "render/light_sampler.h"
#include "render/spot_light.h"
#include "scene/scene_test_util.h"

namespace rc::test {
namespace {

constexpr float kDeg = 3.14159265358979f / 180.0f;

const std::string kDownSpot = "<transform name=\"to_world\"><lookat origin=\"0, 0, 2\" target=\"0, 0, 0\" up=\"0, 1, 0\"/></transform>";

TEST(SpotLight, LoadsMitsubasParametersAndDefaults) {
  TempDir dir;
  const Scene s = loadText(dir, sceneXml("<emitter type=\"spot\">" + kDownSpot + "<rgb name=\"intensity\" value=\"3, 2, 1\"/></emitter>"
                                         "<emitter type=\"spot\"><float name=\"cutoff_angle\" value=\"40\"/>"
                                         "<float name=\"beam_width\" value=\"10\"/></emitter>"));
  ASSERT_EQ(s.emitters.size(), 2u);
  const Emitter& a = s.emitters[0];
  EXPECT_EQ(a.type, EmitterType::Spot);
  EXPECT_FLOAT_EQ(a.intensity.r, 3.0f);
  EXPECT_NEAR(glm::length(a.position - Vec3(0, 0, 2)), 0.0f, 1e-6f);
  EXPECT_NEAR(a.spotCutoffRad, 20.0f * kDeg, 1e-6f);  // default cutoff 20°, beam 3/4 of it
  EXPECT_NEAR(a.spotBeamRad, 15.0f * kDeg, 1e-6f);
  EXPECT_NEAR(s.emitters[1].spotCutoffRad, 40.0f * kDeg, 1e-6f);
  EXPECT_NEAR(s.emitters[1].spotBeamRad, 10.0f * kDeg, 1e-6f);
}

TEST(SpotLight, MalformedParametersNameTheirLine) {
  TempDir dir;
  expectError([&] { loadText(dir, sceneXml("<emitter type=\"spot\">\n<float name=\"cutoff_angle\" value=\"20\"/>\n"
                                           "<float name=\"beam_width\" value=\"25\"/></emitter>")); },
              {"scene.xml:5:", "'beam_width' must be in [0, cutoff_angle]"});
  expectError([&] { loadText(dir, sceneXml("<emitter type=\"spot\">\n<float name=\"cutoff_angle\" value=\"-1\"/></emitter>")); },
              {"scene.xml:4:", "'cutoff_angle' must be in (0, 180]"});
  expectError([&] { loadText(dir, sceneXml("<emitter type=\"spot\">\n<rgb name=\"intensity\" value=\"-1\"/></emitter>")); },
              {"scene.xml:4:", "'intensity' must be non-negative"});
  expectError([&] { loadText(dir, sceneXml("<emitter type=\"spot\">\n<texture type=\"bitmap\" name=\"texture\"/></emitter>")); },
              {"scene.xml:4:", "projected 'texture' is not supported"});
  expectError([&] { loadText(dir, sceneXml("<shape type=\"cube\"><emitter type=\"spot\"/></shape>")); },
              {"only an area emitter can be nested inside a <shape>"});
  LoadOptions lenient;
  lenient.lenient = true;
  std::vector<std::string> warnings;
  const Scene s = loadText(dir, sceneXml("<emitter type=\"spot\"><texture type=\"bitmap\" name=\"texture\"/></emitter>"), lenient, &warnings);
  EXPECT_EQ(s.emitters.size(), 1u);
  EXPECT_EQ(warnings.size(), 1u);
}

// From points on the plane z = 0 below a spot at height 2 pointing down, the light sample carries
// I·falloff(θ)/d² with Mitsuba's profile: 1 inside beam_width, (cutoff − θ)/(cutoff − beam) between,
// nothing beyond cutoff_angle.
TEST(SpotLight, SampledIntensityFollowsTheLinearFalloff) {
  TempDir dir;
  Scene s = loadText(dir, sceneXml("<emitter type=\"spot\">" + kDownSpot + "<rgb name=\"intensity\" value=\"5\"/>"
                                   "<float name=\"cutoff_angle\" value=\"30\"/><float name=\"beam_width\" value=\"20\"/></emitter>"));
  const LightSampler lights(s);
  for (const float thetaDeg : {0.0f, 10.0f, 19.0f, 21.0f, 25.0f, 29.0f, 31.0f, 60.0f}) {
    const float theta = thetaDeg * kDeg;
    const Vec3 p(2.0f * std::tan(theta), 0.0f, 0.0f);
    const float d2 = 4.0f + p.x * p.x;
    const float expected = thetaDeg <= 20.0f ? 1.0f : thetaDeg >= 30.0f ? 0.0f : (30.0f - thetaDeg) / 10.0f;
    const auto ls = lights.sample(p, Vec2(0.5f), 0.5f);
    if (expected == 0.0f) {
      EXPECT_FALSE(ls.has_value()) << thetaDeg;
      continue;
    }
    ASSERT_TRUE(ls.has_value()) << thetaDeg;
    EXPECT_TRUE(ls->delta);
    EXPECT_NEAR(ls->radiance.g * d2 / 5.0f, expected, 1e-4f) << thetaDeg;
    EXPECT_NEAR(glm::length(ls->lightPoint - Vec3(0, 0, 2)), 0.0f, 1e-6f);
  }
}

// A scaled to_world: Mitsuba maps the world direction back with the inverse and normalises, so a
// scale along x widens the cone along x.
TEST(SpotLight, ScaledFrameWidensTheCone) {
  Emitter em;
  em.type = EmitterType::Spot;
  em.spotCutoffRad = 30.0f * kDeg;
  em.spotBeamRad = 20.0f * kDeg;
  em.spotCosCutoff = std::cos(em.spotCutoffRad);
  em.spotCosBeam = std::cos(em.spotBeamRad);
  em.spotWorldToLocal = glm::inverse(Mat3(Vec3(2, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)));
  // World 40° from the axis in x is atan(tan 40° / 2) ≈ 22.8° locally: in the transition.
  const float local = std::atan(std::tan(40.0f * kDeg) / 2.0f);
  EXPECT_NEAR(spotFalloff(em, Vec3(std::sin(40.0f * kDeg), 0, std::cos(40.0f * kDeg))), (30.0f * kDeg - local) / (10.0f * kDeg), 1e-4f);
  EXPECT_EQ(spotFalloff(em, Vec3(0, std::sin(40.0f * kDeg), std::cos(40.0f * kDeg))), 0.0f);  // y unscaled: dark
  EXPECT_EQ(spotFalloff(em, Vec3(0, 0, -1)), 0.0f);  // behind
}

}  // namespace
}  // namespace rc::test
