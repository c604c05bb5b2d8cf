// normalmap and bumpmap loaded from XML as Mitsuba 3 writes them (a bumpmap's texture under any name
// or none), and their errors with the file and line.
#include <gtest/gtest.h>

#include "scene_test_util.h"

namespace rc::test {
namespace {

const char* kRectangle = "<shape type=\"rectangle\"><ref id=\"m\"/></shape>";

TEST(FrameMapLoad, NormalMapAndBumpMapFromXml) {
  TempDir dir;
  const Scene n = loadText(dir, sceneXml(
      "<bsdf type=\"normalmap\" id=\"m\"><texture type=\"checkerboard\" name=\"normalmap\">"
      "<rgb name=\"color0\" value=\"0.5, 0.5, 1\"/><rgb name=\"color1\" value=\"0.7, 0.5, 0.9\"/></texture>"
      "<bsdf type=\"diffuse\"/></bsdf>" + std::string(kRectangle)));
  ASSERT_EQ(n.meshes.size(), 1u);
  const Bsdf& normal = *n.bsdfs[static_cast<size_t>(n.meshes[0].bsdf)];
  EXPECT_EQ(normal.typeName(), "normalmap");
  EXPECT_TRUE(normal.perturbsFrame());
  // color1 = (0.7, 0.5, 0.9) → n ∝ (0.4, 0, 0.8) where frac(u), frac(v) disagree about ½.
  FramePoint p;
  p.uv = Vec2(0.75f, 0.25f);
  EXPECT_NEAR(normal.perturbedFrame(p).n.x, 0.4f / std::sqrt(0.8f), 1e-5f);

  // A grey ramp 0, 85, 170, 255 as a 4×1 PGM; the bumpmap's texture without a name.
  dir.write("ramp.pgm", "P2\n4 1\n255\n0 85 170 255\n");
  const Scene b = loadText(dir, sceneXml(
      "<bsdf type=\"bumpmap\" id=\"m\"><float name=\"scale\" value=\"0.5\"/><texture type=\"bitmap\">"
      "<string name=\"filename\" value=\"ramp.pgm\"/><boolean name=\"raw\" value=\"true\"/>"
      "<string name=\"wrap_mode\" value=\"clamp\"/></texture><bsdf type=\"diffuse\"/></bsdf>" + std::string(kRectangle)));
  const Bsdf& bump = *b.bsdfs[static_cast<size_t>(b.meshes[0].bsdf)];
  EXPECT_EQ(bump.typeName(), "bumpmap");
  p.uv = Vec2(0.5f, 0.5f);
  p.dpdu = Vec3(2, 0, 0);
  p.dpdv = Vec3(0, 2, 0);
  // Steps of ⅓ per texel, 4 texels: ∂h/∂u = 4/3 in the interior, so n ∝ (−2·0.5·4/3, 0, 4).
  const Frame f = bump.perturbedFrame(p);
  EXPECT_NEAR(f.n.x / f.n.z, -1.0f / 3.0f, 1e-5f);
}

TEST(FrameMapLoad, Errors) {
  TempDir dir;
  expectError([&] {
    loadText(dir, sceneXml("<bsdf type=\"bumpmap\" id=\"m\"><texture type=\"checkerboard\"/><bsdf type=\"diffuse\"/></bsdf>" +
                           std::string(kRectangle)));
  }, {"scene.xml:3", "no gradient"});
  expectError([&] {
    loadText(dir, sceneXml("<bsdf type=\"twosided\" id=\"m\"><bsdf type=\"normalmap\"><rgb name=\"normalmap\" value=\"0.5, 0.5, 1\"/>"
                           "<bsdf type=\"diffuse\"/></bsdf></bsdf>" + std::string(kRectangle)));
  }, {"scene.xml:3", "outermost"});
  expectError([&] {
    loadText(dir, sceneXml("<bsdf type=\"bumpmap\" id=\"m\"><texture type=\"checkerboard\"/><texture type=\"checkerboard\"/>"
                           "<bsdf type=\"diffuse\"/></bsdf>" + std::string(kRectangle)));
  }, {"scene.xml:3", "more than once"});
  expectError([&] {
    loadText(dir, sceneXml("<bsdf type=\"normalmap\" id=\"m\"><bsdf type=\"diffuse\"/></bsdf>" + std::string(kRectangle)));
  }, {"scene.xml:3", "normalmap"});
}

}  // namespace
}  // namespace rc::test
