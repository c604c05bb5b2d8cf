// Mitsuba's `spot` emitter: its parameters as the loader reads them, and the intensity the light
// sampler returns in each part of its profile (full beam, linear transition, dark); its projected
// texture and the `projector` against Mitsuba 3.9.1's sample_direction values.
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
              {"scene.xml:4:", "missing parameter 'filename'"});
  expectError([&] { loadText(dir, sceneXml("<emitter type=\"spot\">\n<texture type=\"checkerboard\" name=\"intensity\"/></emitter>")); },
              {"scene.xml:4:", "unexpected <texture>"});
  expectError([&] { loadText(dir, sceneXml("<shape type=\"cube\"><emitter type=\"spot\"/></shape>")); },
              {"only an area emitter can be nested inside a <shape>"});
  LoadOptions lenient;
  lenient.lenient = true;
  std::vector<std::string> warnings;
  const Scene s = loadText(dir, sceneXml("<emitter type=\"spot\"><texture type=\"noise\" name=\"texture\"/></emitter>"), lenient, &warnings);
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

// Mitsuba 3.9.1 scalar_rgb, Emitter.sample_direction(it.p = point) of the same emitters (the weight,
// radiance·solid angle of the delta light): a projector with a constant irradiance (the corpus'
// emitter_projector_constant), one with a checkerboard, fov_axis y and scale, and a spot with a
// checkerboard texture. Printed by bench/mitsuba_emitter_values.py.
const char* const kChecker =
    "<rgb name=\"color0\" value=\"0.9, 0.5, 0.1\"/><rgb name=\"color1\" value=\"0.1, 0.2, 0.7\"/>"
    "<transform name=\"to_uv\"><scale x=\"4\" y=\"4\"/></transform>";
const char* const kAboveLookingDown =
    "<transform name=\"to_world\"><lookat origin=\"0, 0, 3\" target=\"0.2, 0.1, 0\" up=\"0, 1, 0\"/></transform>";

struct MitsubaEmission {
  float p[3];
  float value[3];
};

void expectEmission(const std::string& emitterXml, const std::vector<MitsubaEmission>& expected) {
  TempDir dir;
  const Scene s = loadText(dir, sceneXml(emitterXml));
  ASSERT_EQ(s.emitters.size(), 1u);
  const LightSampler lights(s);
  for (const MitsubaEmission& m : expected) {
    const Vec3 p(m.p[0], m.p[1], m.p[2]);
    const auto ls = lights.sample(p, Vec2(0.5f), 0.5f);
    if (m.value[0] == 0.0f && m.value[1] == 0.0f && m.value[2] == 0.0f) {
      EXPECT_FALSE(ls.has_value()) << p.x << " " << p.y << " " << p.z;
      continue;
    }
    ASSERT_TRUE(ls.has_value()) << p.x << " " << p.y << " " << p.z;
    EXPECT_TRUE(ls->delta);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(ls->radiance[c], m.value[c], 2e-4f * m.value[c]) << p.x << " " << p.y << " " << p.z;
  }
}

TEST(ProjectorLight, ConstantIrradianceMatchesMitsuba) {
  expectEmission("<emitter type=\"projector\"><float name=\"fov\" value=\"32\"/>"
                 "<transform name=\"to_world\"><lookat origin=\"4.0, 0.0, 5.5\" target=\"0.0, 0.0, 1.0\" up=\"-1, 0, 0\"/></transform>"
                 "<rgb name=\"irradiance\" value=\"25.5 38.0 20.1\"/></emitter>",
                 {{{0.3f, 0.2f, 1.0f}, {2.36700869f, 3.52730703f, 1.86575985f}},
                  {{-0.5f, 0.4f, 0.0f}, {1.59285533f, 2.37366676f, 1.25554478f}},
                  {{0.1f, -0.6f, 0.5f}, {2.01362991f, 3.00070333f, 1.58721423f}},
                  {{0.9f, 0.9f, 0.0f}, {2.17476726f, 3.24082971f, 1.71422839f}},
                  {{1.2f, -0.3f, 1.1f}, {3.06597662f, 4.56890631f, 2.41671109f}}});
}

TEST(ProjectorLight, TexturedImageMatchesMitsuba) {
  expectEmission(std::string("<emitter type=\"projector\"><float name=\"fov\" value=\"40\"/><string name=\"fov_axis\" value=\"y\"/>"
                             "<float name=\"scale\" value=\"2.5\"/><texture type=\"checkerboard\" name=\"irradiance\">") +
                     kChecker + "</texture>" + kAboveLookingDown + "</emitter>",
                 {{{0.3f, 0.2f, 1.0f}, {0.193342373f, 0.386684746f, 1.35339665f}},
                  {{-0.5f, 0.4f, 0.0f}, {0.0918005034f, 0.183601007f, 0.642603517f}},
                  {{0.1f, -0.6f, 0.5f}, {1.19266319f, 0.662590683f, 0.132518142f}},
                  {{0.9f, 0.9f, 0.0f}, {0.0874753818f, 0.174950764f, 0.612327635f}},
                  {{1.2f, -0.3f, 1.1f}, {0.0f, 0.0f, 0.0f}}});  // outside the image
}

TEST(SpotLight, ProjectedTextureMatchesMitsuba) {
  expectEmission(std::string("<emitter type=\"spot\"><float name=\"cutoff_angle\" value=\"30\"/>"
                             "<rgb name=\"intensity\" value=\"50, 40, 30\"/><texture type=\"checkerboard\" name=\"texture\">") +
                     kChecker + "</texture>" + kAboveLookingDown + "</emitter>",
                 {{{0.3f, 0.2f, 1.0f}, {1.21065378f, 1.93704605f, 5.08474588f}},
                  {{-0.5f, 0.4f, 0.0f}, {0.531349599f, 0.850159347f, 2.23166823f}},
                  {{0.1f, -0.6f, 0.5f}, {6.79758263f, 3.02114773f, 0.453172177f}},
                  {{0.9f, 0.9f, 0.0f}, {0.470809907f, 0.753295839f, 1.97740161f}},
                  {{1.2f, -0.3f, 1.1f}, {0.0670288652f, 0.0297906063f, 0.00446859095f}}});
}

TEST(ProjectorLight, ParametersAreChecked) {
  TempDir dir;
  expectError([&] { loadText(dir, sceneXml("<emitter type=\"projector\">\n<float name=\"fov\" value=\"200\"/></emitter>")); },
              {"scene.xml:4:", "'fov' must be in (0, 180)"});
  expectError([&] { loadText(dir, sceneXml("<emitter type=\"projector\">\n<float name=\"scale\" value=\"-1\"/></emitter>")); },
              {"scene.xml:4:", "'scale' must be finite and non-negative"});
  expectError([&] { loadText(dir, sceneXml("<bsdf type=\"diffuse\" id=\"d\"/><emitter type=\"projector\">\n<ref name=\"irradiance\" id=\"d\"/></emitter>")); },
              {"scene.xml:4:", "is not a texture"});
  // The default: Mitsuba's 50 mm lens on the (square) image's diagonal.
  const Scene s = loadText(dir, sceneXml("<emitter type=\"projector\"/>"));
  const float fovX = 2.0f * std::atan(std::sqrt(36.0f * 36.0f + 24.0f * 24.0f) / 100.0f / std::sqrt(2.0f));
  EXPECT_NEAR(s.emitters.at(0).projectorCot, 1.0f / std::tan(0.5f * fovX), 1e-4f);
}

}  // namespace
}  // namespace rc::test
