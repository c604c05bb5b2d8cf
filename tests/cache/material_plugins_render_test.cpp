// The BSDFs added for real scenes (roughdielectric, null, mask) and parameters textured per point
// (Bsdf::at: plastic's diffuse_reflectance, a roughness, a mask's opacity) rendered by both
// integrators on the box scene's floor: rcache (forced to cache, fallback=false) agrees with the
// path tracer in the image mean, and its material plan importance-samples those floors (the
// roughconductor's α reaches 0.05, sharper than the tables over α may go at the order cap;
// tests/cache/alpha_tables_render_test.cpp has one they cover).
#include <gtest/gtest.h>

#include "test_scene.h"
#include "texture/texture.h"

namespace rc {
namespace {

using test::floatProp;
using test::rgbProp;
using test::stringProp;

BsdfPtr build(const std::string& type, std::vector<std::pair<std::string, Property>> params,
              const BsdfTextures& textures = {}, const std::vector<BsdfPtr>& nested = {}) {
  Properties props;
  props.pluginType = type;
  for (const auto& [name, p] : params) props.set(name, p);
  return createBsdf(props, nested, "floor", textures);
}

TexturePtr checker(float a, float b) {
  UvTransform toUv;
  toUv.m = Mat3(4.0f);
  toUv.m[2][2] = 1.0f;
  return makeCheckerboard(Color(a), Color(b), toUv);
}

struct FloorCase {
  const char* name;
  BsdfPtr (*floor)();
};

const FloorCase kFloors[] = {
    {"roughdielectric", [] { return build("roughdielectric", {{"distribution", stringProp("ggx")}, {"alpha", floatProp(0.2)}}); }},
    {"roughdielectric_textured_alpha",
     [] { return build("roughdielectric", {{"alpha", floatProp(0.3)}}, {{"alpha", checker(0.05f, 0.55f)}}); }},
    {"null", [] { return build("null", {}); }},
    {"mask_textured_opacity",
     [] {
       return build("mask", {{"opacity", floatProp(0.5)}}, {{"opacity", checker(1.0f, 0.0f)}},
                    {test::diffuse(0.7f, 0.6f, 0.5f)});
     }},
    {"plastic_textured_diffuse",
     [] {
       UvTransform toUv;
       toUv.m = Mat3(4.0f);
       toUv.m[2][2] = 1.0f;
       return build("plastic", {{"diffuse_reflectance", rgbProp(0.45f, 0.15f, 0.35f)}},
                    {{"diffuse_reflectance", makeCheckerboard(Color(0.8f, 0.2f, 0.1f), Color(0.1f, 0.1f, 0.6f), toUv)}});
     }},
    {"roughplastic_textured_diffuse",
     [] {
       return build("roughplastic", {{"alpha", floatProp(0.2)}, {"diffuse_reflectance", floatProp(0.45)}},
                    {{"diffuse_reflectance", checker(0.8f, 0.1f)}});
     }},
    {"roughconductor_textured_alpha",
     [] {
       return build("roughconductor", {{"alpha", floatProp(0.3)}, {"distribution", stringProp("ggx")}},
                    {{"alpha", checker(0.05f, 0.55f)}});
     }},
};

Color meanOf(const Image& img) {
  Color m(0.0f);
  for (const Color& c : img.pixels) m += c;
  return m / float(img.pixels.size());
}

class MaterialPluginsRender : public ::testing::TestWithParam<int> {};

TEST_P(MaterialPluginsRender, RcacheAgreesWithThePathTracer) {
  const FloorCase& c = kFloors[GetParam()];
  Scene s = test::boxScene(0.0f, 32, 24);
  s.bsdfs[0] = c.floor();
  s.meshes[0].uvs = {Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)};
  const auto path = test::renderScene(s, test::pathSettings(s), 256, 1);
  const auto cached = test::renderScene(s, test::rcacheSettings(s, {{"fallback", "false"}}), 32, 1);
  const Color mp = meanOf(path.image), mc = meanOf(cached.image);
  // 5 %: the cache's interpolation bias on the walls plus both estimates' noise at these spp.
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(mc[k] / mp[k], 1.0, 0.05) << c.name << " channel " << k;
  std::string materials;
  for (const auto& [key, value] : cached.stats.json)
    if (key == "materials") materials = value;
  const size_t floor = materials.find("\"name\": \"floor\"");
  ASSERT_NE(floor, std::string::npos) << materials;
  const size_t end = materials.find('}', floor);
  EXPECT_NE(materials.substr(floor, end - floor).find("importance sampling"), std::string::npos) << materials;
}

INSTANTIATE_TEST_SUITE_P(All, MaterialPluginsRender, ::testing::Range(0, int(sizeof(kFloors) / sizeof(kFloors[0]))),
                         [](const ::testing::TestParamInfo<int>& info) { return kFloors[info.param].name; });

}  // namespace
}  // namespace rc
