// The BSDFs for real scenes loaded from XML as Mitsuba 3 writes them: roughdielectric with named
// IORs, null, mask with a textured opacity around a textured diffuse, plastic with a textured
// diffuse_reflectance, principled with textures, textured roughness — and their errors.
#include <gtest/gtest.h>

#include "scene_test_util.h"

namespace rc::test {
namespace {

const char* kChecker =
    "<texture type=\"checkerboard\" id=\"check\"><rgb name=\"color0\" value=\"0.8, 0.1, 0.1\"/>"
    "<rgb name=\"color1\" value=\"0.1\"/></texture>"
    "<texture type=\"checkerboard\" id=\"grey\"><float name=\"color0\" value=\"1\"/>"
    "<float name=\"color1\" value=\"0\"/></texture>";

TEST(BsdfPluginsLoad, MaterialsForRealScenes) {
  TempDir dir;
  const Scene s = loadText(dir, sceneXml(std::string(kChecker) +
      "<bsdf type=\"roughdielectric\" id=\"glass\"><string name=\"distribution\" value=\"ggx\"/>"
      "<float name=\"alpha\" value=\"0.2\"/><string name=\"int_ior\" value=\"water\"/></bsdf>"
      "<bsdf type=\"null\" id=\"invisible\"/>"
      "<bsdf type=\"mask\" id=\"leaf\"><ref name=\"opacity\" id=\"grey\"/>"
      "<bsdf type=\"diffuse\"><ref name=\"reflectance\" id=\"check\"/></bsdf></bsdf>"
      "<bsdf type=\"plastic\" id=\"tiles\"><ref name=\"diffuse_reflectance\" id=\"check\"/></bsdf>"
      "<bsdf type=\"roughconductor\" id=\"brushed\"><ref name=\"alpha\" id=\"grey\"/></bsdf>"
      "<bsdf type=\"principled\" id=\"paint\"><ref name=\"base_color\" id=\"check\"/>"
      "<float name=\"metallic\" value=\"0.3\"/><float name=\"clearcoat\" value=\"0.5\"/></bsdf>"
      "<shape type=\"sphere\"><ref id=\"glass\"/></shape><shape type=\"sphere\"><ref id=\"invisible\"/></shape>"
      "<shape type=\"sphere\"><ref id=\"leaf\"/></shape><shape type=\"sphere\"><ref id=\"tiles\"/></shape>"
      "<shape type=\"sphere\"><ref id=\"brushed\"/></shape><shape type=\"sphere\"><ref id=\"paint\"/></shape>"));
  ASSERT_EQ(s.bsdfs.size(), 6u);
  std::map<std::string, BsdfPtr> byId;
  for (const BsdfPtr& b : s.bsdfs) byId[b->id] = b;
  EXPECT_EQ(byId.at("glass")->typeName(), "roughdielectric");
  EXPECT_FALSE(byId.at("glass")->spatiallyVarying());
  EXPECT_EQ(byId.at("invisible")->typeName(), "null");
  for (const char* id : {"leaf", "tiles", "brushed", "paint"}) {
    EXPECT_TRUE(byId.at(id)->spatiallyVarying()) << id;
    EXPECT_FALSE(byId.at(id)->tinted()) << id;
  }
  // The mask: solid where the grey checkerboard is 1, a hole where it is 0 — as a scalar parameter
  // (Mitsuba's eval_1) the checkerboard gives color0 where its RGB eval gives color1 (Mitsuba 3.9.1:
  // eval_1 at uv (0.25, 0.25) is color1, at (0.75, 0.25) color0), while the diffuse reflectance
  // inside is an RGB parameter (0.1 at (0.75, 0.25)).
  const Vec3 up(0, 0, 1), wi = glm::normalize(Vec3(0.2f, 0.1f, 1.0f));
  EXPECT_EQ(byId.at("leaf")->at(TexturePoint(Vec2(0.25f, 0.25f)))->eval(up, wi), Color(0.0f));
  EXPECT_NEAR(byId.at("leaf")->at(TexturePoint(Vec2(0.75f, 0.25f)))->eval(up, wi).r, 0.1f * wi.z / kPi, 1e-5f);
  // The plastic's diffuse part follows the texture.
  const Color red = byId.at("tiles")->at(TexturePoint(Vec2(0.25f, 0.25f)))->eval(up, wi);
  const Color grey = byId.at("tiles")->at(TexturePoint(Vec2(0.75f, 0.25f)))->eval(up, wi);
  EXPECT_GT(red.r, 4.0f * red.g);
  EXPECT_NEAR(grey.r, grey.g, 1e-6f);
}

TEST(BsdfPluginsLoad, ErrorsNameTheParameter) {
  TempDir dir;
  expectError([&] { loadText(dir, sceneXml("<bsdf type=\"roughdielectric\"><float name=\"int_ior\" value=\"1.3\"/>"
                                           "<float name=\"ext_ior\" value=\"1.3\"/></bsdf>")); },
              {"scene.xml:3", "must differ"});
  expectError([&] { loadText(dir, sceneXml("<bsdf type=\"mask\"/>")); }, {"mask", "1 nested BSDF"});
  expectError([&] { loadText(dir, sceneXml("<bsdf type=\"principled\"><float name=\"eta\" value=\"1.4\"/>"
                                           "<float name=\"specular\" value=\"0.4\"/></bsdf>")); },
              {"specular", "not both"});
}

}  // namespace
}  // namespace rc::test
