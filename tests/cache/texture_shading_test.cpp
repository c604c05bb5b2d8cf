// Textured reflectance through both integrators: a texture factor (Bsdf::tint) multiplies at the
// shading point, after the radiance cache, so the cache's incoming radiance stays BRDF-independent.
#include <gtest/gtest.h>

#include <cmath>

#include "bsdf/textured.h"
#include "test_scene.h"
#include "texture/texture.h"

namespace rc {
namespace {

// The box scene with its floor's diffuse reflectance given as a texture over the floor's uvs.
Scene texturedFloor(const Color& c0, const Color& c1) {
  Scene s = test::boxScene(0.0f, 32, 24);
  UvTransform toUv;
  toUv.m = Mat3(4.0f);
  toUv.m[2][2] = 1.0f;
  s.bsdfs[0] = makeTexturedBsdf(test::diffuse(1, 1, 1), makeCheckerboard(c0, c1, toUv));
  s.meshes[0].uvs = {Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)};
  return s;
}

Color meanOf(const Image& img) {
  Color m(0.0f);
  for (const Color& c : img.pixels) m += c;
  return m / float(img.pixels.size());
}

// A constant texture c renders what diffuse(c) renders: the factor applied after the BSDF and the
// cache equals the reflectance inside them.
TEST(TextureShading, ConstantTextureEqualsPlainReflectance) {
  const Color c(0.6f, 0.3f, 0.2f);
  Scene plain = test::boxScene(0.0f, 32, 24);
  plain.bsdfs[0] = test::diffuse(c.r, c.g, c.b);
  const Scene textured = texturedFloor(c, c);
  for (const bool cache : {false, true}) {
    const auto settings = cache ? test::rcacheSettings(plain) : test::pathSettings(plain);
    const Image a = test::renderScene(plain, settings, 16, 3).image;
    const Image b = test::renderScene(textured, settings, 16, 3).image;
    const Color ma = meanOf(a), mb = meanOf(b);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(mb[k] / ma[k], 1.0, 2e-3) << (cache ? "rcache" : "path") << " channel " << k;
  }
}

// A checkerboard floor: rcache agrees with the path tracer, and the floor shows both colours.
TEST(TextureShading, CheckerboardThroughTheCacheMatchesThePathTracer) {
  const Scene s = texturedFloor(Color(0.8f, 0.2f, 0.1f), Color(0.1f, 0.1f, 0.6f));
  const Image path = test::renderScene(s, test::pathSettings(s), 256, 1).image;
  const Image cached = test::renderScene(s, test::rcacheSettings(s), 16, 1).image;
  const Color mp = meanOf(path), mc = meanOf(cached);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(mc[k] / mp[k], 1.0, 0.05) << "channel " << k;
  // Floor pixels (bottom rows) of both squares in both images: reddish ones, and bluish ones (the
  // red wall's bounce light keeps blue squares from being very blue).
  for (const Image* img : {&path, &cached}) {
    int red = 0, blue = 0;
    for (int y = 18; y < 24; ++y)
      for (int x = 0; x < 32; ++x) {
        const Color& p = img->pixels[size_t(y) * 32 + x];
        red += p.r > 1.5f * p.b;
        blue += p.b > p.r;
      }
    EXPECT_GT(red, 10);
    EXPECT_GT(blue, 10);
  }
}

}  // namespace
}  // namespace rc
