// Normal maps end to end: a constant normal map tilting a floor under a directional light renders
// Mitsuba's closed form (the cosine to the tilted normal times the shadowing term) in the scalar and
// the wavefront path tracer and in rcache; a bitmap normal map on the box scene's floor goes
// through the radiance cache (records in the geometric frame, the BRDF in the perturbed one) and
// agrees with the path tracer per 16-px block.
#include <gtest/gtest.h>

#include <cmath>

#include "block_agreement.h"
#include "material_stats.h"
#include "render/path_integrator.h"
#include "scene/scene_test_util.h"
#include "test_scene.h"
#include "texture/texture.h"

namespace rc::test {
namespace {

constexpr float kPiF = 3.14159265358979f;

Image renderWith(const Scene& s, PathCore core, int spp, uint64_t seed) {
  Accel accel(s);
  LightSampler lights(s);
  RenderOptions opt;
  opt.spp = spp;
  opt.seed = seed;
  RenderContext ctx{s, accel, lights, opt};
  RenderStats stats;
  return makePathIntegrator(pathSettings(s), core, BatchQuery::Single)->render(ctx, stats);
}

float tan2(float c) { return (1.0f - c * c) / (c * c); }

// `below`: camera and light under the rectangle, the normal map around a twosided diffuse BSDF.
std::string tiltedFloorXml(const Vec3& n, const Vec3& toLight, bool shadowing, bool below) {
  const std::string diffuse = "<bsdf type=\"diffuse\"><rgb name=\"reflectance\" value=\"0.5\"/></bsdf>";
  return "<scene version=\"3.0.0\">\n"
         "<integrator type=\"path\"><integer name=\"max_depth\" value=\"2\"/></integrator>"
         "<sensor type=\"perspective\"><float name=\"fov\" value=\"40\"/>"
         "<transform name=\"to_world\"><lookat origin=\"0, 0, " + std::string(below ? "-5" : "5") +
         "\" target=\"0, 0, 0\" up=\"0, 1, 0\"/></transform>"
         "<film type=\"hdrfilm\"><integer name=\"width\" value=\"16\"/><integer name=\"height\" value=\"16\"/>"
         "<rfilter type=\"box\"/></film></sensor>\n"
         "<shape type=\"rectangle\"><transform name=\"to_world\"><scale value=\"5\"/></transform>"
         "<bsdf type=\"normalmap\"><boolean name=\"use_shadowing_function\" value=\"" + std::string(shadowing ? "true" : "false") +
         "\"/><rgb name=\"normalmap\" value=\"" + std::to_string(0.5f * (n.x + 1.0f)) + ", 0.5, " +
         std::to_string(0.5f * (n.z + 1.0f)) + "\"/>" +
         (below ? "<bsdf type=\"twosided\">" + diffuse + "</bsdf>" : diffuse) + "</bsdf></shape>\n"
         "<emitter type=\"directional\"><vector name=\"direction\" value=\"" + std::to_string(-toLight.x) + ", " +
         std::to_string(-toLight.y) + ", " + std::to_string(-toLight.z) + "\"/><rgb name=\"irradiance\" value=\"3\"/></emitter>\n"
         "</scene>\n";
}

// From above, and from below through a twosided nested BSDF (rcache mirrors both of the point's
// frames to the viewer there): ρ/π·E·|n·l|·G(l), G on the angle of l to the unperturbed normal.
TEST(NormalMapRender, ConstantTiltUnderADirectionalLightIsTheClosedForm) {
  const float tilt = 30.0f * kPiF / 180.0f, rho = 0.5f, E = 3.0f;
  // The rectangle's frame: t = dp/du = +x, n = +z; the normal map tilts n toward t.
  const Vec3 n(std::sin(tilt), 0.0f, std::cos(tilt));
  for (const bool below : {false, true})
    for (const bool shadowing : {false, true}) {
      const Vec3 toLight = glm::normalize(Vec3(0.5f, 0.2f, below ? -1.0f : 1.0f));
      TempDir dir;
      const Scene s = loadText(dir, tiltedFloorXml(n, toLight, shadowing, below));
      const float g = shadowing ? 2.0f / (1.0f + std::sqrt(1.0f + std::fmin(0.125f * tan2(n.z), 1.0f) * tan2(toLight.z))) : 1.0f;
      const float expected = rho / kPiF * E * std::fabs(glm::dot(n, toLight)) * g;
      const Image images[3] = {renderWith(s, PathCore::Scalar, 4, 1), renderWith(s, PathCore::Wavefront, 4, 1),
                               renderScene(s, rcacheSettings(s), 4, 1).image};
      const char* names[3] = {"scalar path", "wavefront path", "rcache"};
      for (int k = 0; k < 3; ++k)
        for (const Color& c : images[k].pixels)
          // The light is a Dirac and the normal constant: every sample is the closed form up to
          // float rounding (the text of the normal map's rgb value, 6 digits).
          ASSERT_NEAR(c.g, expected, 1e-4f * expected) << names[k] << " shadowing " << shadowing << " below " << below;
    }
}

// The box scene's floor under an 8×8 bitmap of normals tilted 20°–37° toward dp/du (+x), varying
// by up to ±14° in azimuth: the floor's left half faces the light more, its right half less.
Scene normalMappedBox(int size) {
  Scene s = boxScene(0.0f, size, size);
  std::vector<Color> px;
  Rng rng(11);
  for (int i = 0; i < 64; ++i) {
    const float theta = 0.35f + 0.3f * rng.nextFloat(), phi = 0.5f * (rng.nextFloat() - 0.5f);
    const Vec3 n(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
    px.push_back(0.5f * (Color(n.x, n.y, n.z) + Color(1.0f)));
  }
  Properties props;
  props.pluginType = "normalmap";
  props.set("normalmap", rgbProp(0.5f, 0.5f, 1.0f));
  s.bsdfs[0] = createBsdf(props, {diffuse(0.6f, 0.6f, 0.6f)}, "floor",
                          {{"normalmap", makeBitmapTexture(8, 8, px, TextureFilter::Bilinear, TextureWrap::Repeat, {})}});
  s.meshes[0].uvs = {Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)};
  return s;
}

// rcache may also be 3 % off per block for the cache's interpolation bias (the walls' and ceiling's,
// present without normal maps too: tests/cache/material_plugins_render_test.cpp allows 5 % on the mean).
TEST(NormalMapRender, BothIntegratorsAgreePerBlockOnANormalMappedFloor) {
  constexpr int kSize = 48, kSeeds = 4, kSpp = 16, kRefSpp = 256;
  const Scene s = normalMappedBox(kSize);
  const Image ref = renderWith(s, PathCore::Scalar, kRefSpp, 999);
  std::vector<Image> wave, cached;
  RenderStats cacheStats;
  for (int k = 1; k <= kSeeds; ++k) {
    wave.push_back(renderWith(s, PathCore::Wavefront, kSpp, 100 + k));
    RenderResult r = renderScene(s, rcacheSettings(s, {{"fallback", "false"}}), kSpp, 200 + k);
    cached.push_back(std::move(r.image));
    cacheStats = std::move(r.stats);
  }
  expectBlocksAgree(wave, kSpp, ref, kRefSpp, kSize, kSize, 0.0, "wavefront");
  expectBlocksAgree(cached, kSpp, ref, kRefSpp, kSize, kSize, 0.03, "rcache");
  // The check can tell: the floor without its normal map, through the cache, fails it.
  Scene plain = s;
  plain.bsdfs[0] = diffuse(0.6f, 0.6f, 0.6f);
  std::vector<Image> unmapped;
  for (int k = 1; k <= kSeeds; ++k)
    unmapped.push_back(renderScene(plain, rcacheSettings(plain, {{"fallback", "false"}}), kSpp, 200 + k).image);
  EXPECT_GT(blockExcess(unmapped, kSpp, ref, kRefSpp, kSize, kSize, 0.03, "unmapped", false), 0.0);
  // The normal-mapped floor is shaded from the cache, not importance-sampled.
  const std::string entry = materialEntry(cacheStats, "floor");
  EXPECT_EQ(entry.find("importance sampling"), std::string::npos) << entry;
}

}  // namespace
}  // namespace rc::test
