// Textures (checkerboard, bitmap) after Mitsuba 3's definitions, and textured BSDF parameters: a
// texture on a parameter that scales the whole BSDF becomes its per-point factor (Bsdf::tint).
#include <OpenImageIO/imageio.h>

#include <cmath>

#include "scene_test_util.h"
#include "bsdf/rough_textures.h"
#include "texture/texture.h"

namespace rc::test {
namespace {

TEST(Textures, CheckerboardFollowsMitsuba) {
  const Color c0(1, 0, 0), c1(0, 0, 1);
  const TexturePtr t = makeCheckerboard(c0, c1, UvTransform{});
  EXPECT_EQ(t->eval(TexturePoint(Vec2(0.25f, 0.25f))), c0);  // both fractional parts ≤ ½
  EXPECT_EQ(t->eval(TexturePoint(Vec2(0.75f, 0.75f))), c0);  // both > ½
  EXPECT_EQ(t->eval(TexturePoint(Vec2(0.75f, 0.25f))), c1);
  EXPECT_EQ(t->eval(TexturePoint(Vec2(-0.25f, 0.25f))), c1);  // frac(−0.25) = 0.75
  UvTransform twice;
  twice.m = Mat3(2.0f);
  twice.m[2][2] = 1.0f;
  EXPECT_EQ(makeCheckerboard(c0, c1, twice)->eval(TexturePoint(Vec2(0.3f, 0.1f))), c1);  // (0.6, 0.2)
  EXPECT_EQ(t->mean(), 0.5f * (c0 + c1));
}

// Mitsuba 3's checkerboard on a scalar parameter (eval_1, e.g. a roughness): color0 where exactly one
// of frac(u) > ½, frac(v) > ½ holds — the squares of its RGB eval swapped (src/textures/checkerboard.cpp).
TEST(Textures, CheckerboardOnAScalarParameterSwapsItsSquares) {
  const TexturePtr alpha = makeCheckerboard(Color(0.0f), Color(0.4f), UvTransform{});  // bsdf_roughdielectric_textured
  EXPECT_FLOAT_EQ(textureValue1(*alpha, TexturePoint(Vec2(0.25f, 0.25f))), 0.4f);  // eval gives color0 = 0 here
  EXPECT_FLOAT_EQ(textureValue1(*alpha, TexturePoint(Vec2(0.75f, 0.75f))), 0.4f);
  EXPECT_FLOAT_EQ(textureValue1(*alpha, TexturePoint(Vec2(0.75f, 0.25f))), 0.0f);
  EXPECT_FLOAT_EQ(textureValue1(*alpha, TexturePoint(Vec2(0.25f, 0.75f))), 0.0f);
  // Colours reduce to their luminance (Mitsuba's RGB eval_1), as for any texture.
  const TexturePtr rgb = makeCheckerboard(Color(1, 0, 0), Color(0, 0, 1), UvTransform{});
  EXPECT_FLOAT_EQ(textureValue1(*rgb, TexturePoint(Vec2(0.75f, 0.25f))), 0.2126f);
  const TexturePtr bitmap = makeBitmapTexture(1, 1, {Color(0, 1, 0)}, TextureFilter::Nearest, TextureWrap::Repeat, UvTransform{});
  EXPECT_FLOAT_EQ(textureValue1(*bitmap, TexturePoint(Vec2(0.5f, 0.5f))), 0.7152f);
}

TEST(Textures, BitmapBilinearAndWrapModes) {
  const Color a(1, 0, 0), b(0, 1, 0);
  auto tex = [&](TextureFilter f, TextureWrap w) { return makeBitmapTexture(2, 1, {a, b}, f, w, UvTransform{}); };
  const TexturePtr repeat = tex(TextureFilter::Bilinear, TextureWrap::Repeat);
  // Texel centres at u = 0.25 and 0.75.
  EXPECT_EQ(repeat->eval(TexturePoint(Vec2(0.25f, 0.5f))), a);
  EXPECT_EQ(repeat->eval(TexturePoint(Vec2(0.75f, 0.5f))), b);
  EXPECT_NEAR(glm::length(repeat->eval(TexturePoint(Vec2(0.5f, 0.5f))) - 0.5f * (a + b)), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::length(repeat->eval(TexturePoint(Vec2(0.0f, 0.5f))) - 0.5f * (a + b)), 0.0f, 1e-6f);  // wraps to the last texel
  EXPECT_NEAR(glm::length(repeat->eval(TexturePoint(Vec2(1.25f, 0.5f))) - a), 0.0f, 1e-6f);
  EXPECT_EQ(tex(TextureFilter::Bilinear, TextureWrap::Clamp)->eval(TexturePoint(Vec2(0.0f, 0.5f))), a);
  EXPECT_EQ(tex(TextureFilter::Bilinear, TextureWrap::Mirror)->eval(TexturePoint(Vec2(0.0f, 0.5f))), a);  // texel −1 mirrors to 0
  EXPECT_EQ(tex(TextureFilter::Nearest, TextureWrap::Repeat)->eval(TexturePoint(Vec2(0.49f, 0.5f))), a);
  EXPECT_EQ(tex(TextureFilter::Nearest, TextureWrap::Repeat)->eval(TexturePoint(Vec2(0.51f, 0.5f))), b);
}

void writePng(const std::string& path, unsigned char value) {
  const unsigned char px[4 * 3] = {value, value, value, value, value, value, value, value, value, value, value, value};
  auto out = OIIO::ImageOutput::create(path);
  ASSERT_TRUE(out);
  ASSERT_TRUE(out->open(path, OIIO::ImageSpec(2, 2, 3, OIIO::TypeDesc::UINT8)));
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, px));
  out->close();
}

TEST(Textures, BitmapFilesAreLinearisedUnlessRaw) {
  TempDir dir;
  writePng(dir.path("grey.png"), 128);
  const Scene s = loadText(dir, sceneXml(
      "<shape type=\"rectangle\"><bsdf type=\"diffuse\"><texture type=\"bitmap\" name=\"reflectance\">"
      "<string name=\"filename\" value=\"grey.png\"/></texture></bsdf></shape>"
      "<shape type=\"rectangle\"><bsdf type=\"diffuse\"><texture type=\"bitmap\" name=\"reflectance\">"
      "<string name=\"filename\" value=\"grey.png\"/><boolean name=\"raw\" value=\"true\"/>"
      "<string name=\"wrap_mode\" value=\"clamp\"/><string name=\"filter_type\" value=\"nearest\"/></texture></bsdf></shape>"));
  ASSERT_EQ(s.bsdfs.size(), 2u);
  const float srgb = 128.0f / 255.0f, linear = std::pow((srgb + 0.055f) / 1.055f, 2.4f);  // the sRGB curve
  ASSERT_TRUE(s.bsdfs[0]->tinted());
  EXPECT_NEAR(s.bsdfs[0]->tint(TexturePoint(Vec2(0.3f, 0.6f)), {0, 0, 1}).g, linear, 1e-5f);
  EXPECT_NEAR(s.bsdfs[1]->tint(TexturePoint(Vec2(0.3f, 0.6f)), {0, 0, 1}).g, srgb, 1e-5f);
}

// Mitsuba's BMP and TGA readers mark 8-bit files sRGB (Bitmap::read_bmp / read_tga), as PNG and JPEG.
TEST(Textures, BmpAndTgaFilesAreLinearisedToo) {
  TempDir dir;
  const float srgb = 200.0f / 255.0f, linear = std::pow((srgb + 0.055f) / 1.055f, 2.4f);
  for (const char* name : {"grey.bmp", "grey.tga"}) {
    writePng(dir.path(name), 200);
    const Scene s = loadText(dir, sceneXml(std::string("<shape type=\"rectangle\"><bsdf type=\"diffuse\"><texture type=\"bitmap\" "
                                                       "name=\"reflectance\"><string name=\"filename\" value=\"") +
                                           name + "\"/></texture></bsdf></shape>"));
    ASSERT_TRUE(s.bsdfs.at(0)->tinted()) << name;
    EXPECT_NEAR(s.bsdfs[0]->tint(TexturePoint(Vec2(0.3f, 0.6f)), {0, 0, 1}).g, linear, 1e-5f) << name;
  }
}

TEST(Textures, TexturedReflectanceScalesAUnitBsdf) {
  TempDir dir;
  const Scene s = loadText(dir, sceneXml(
      "<texture type=\"checkerboard\" id=\"check\"><rgb name=\"color0\" value=\"0.8, 0.1, 0.1\"/>"
      "<rgb name=\"color1\" value=\"0.1\"/><transform name=\"to_uv\"><scale x=\"4\" y=\"4\"/></transform></texture>"
      "<bsdf type=\"twosided\" id=\"floor\"><bsdf type=\"diffuse\"><ref name=\"reflectance\" id=\"check\"/></bsdf></bsdf>"
      "<shape type=\"rectangle\"><ref id=\"floor\"/></shape>"
      "<shape type=\"sphere\"><bsdf type=\"roughconductor\"><string name=\"material\" value=\"none\"/>"
      "<ref name=\"specular_reflectance\" id=\"check\"/></bsdf></shape>"));
  ASSERT_EQ(s.bsdfs.size(), 2u);
  const Bsdf& floor = *s.bsdfs[0];
  ASSERT_TRUE(floor.tinted());
  const Vec3 up(0, 0, 1), wi = glm::normalize(Vec3(0.3f, 0.2f, 1.0f));
  EXPECT_NEAR(floor.eval(up, wi).r, wi.z / kPi, 1e-6f);                              // reflectance 1 ...
  EXPECT_NEAR(glm::length(floor.tint(TexturePoint(Vec2(0.05f, 0.05f)), up) - Color(0.8f, 0.1f, 0.1f)), 0.0f, 1e-6f);  // ... times the texture
  EXPECT_NEAR(glm::length(floor.tint(TexturePoint(Vec2(0.2f, 0.05f)), up) - Color(0.1f)), 0.0f, 1e-6f);               // u' = 0.8
  EXPECT_NEAR(glm::length(floor.tint(TexturePoint(Vec2(0.05f, 0.05f)), -up) - Color(0.8f, 0.1f, 0.1f)), 0.0f, 1e-6f); // back side, same BSDF
  EXPECT_TRUE(s.bsdfs[1]->tinted());
}

TEST(Textures, UnsupportedTexturedParametersAreNamed) {
  TempDir dir;
  const std::string dielectric = sceneXml("<shape type=\"rectangle\"><bsdf type=\"dielectric\">\n"
                                       "<texture type=\"checkerboard\" name=\"specular_transmittance\"/></bsdf></shape>");
  expectError([&] { loadText(dir, dielectric); }, {"scene.xml:4:", "texture on parameter 'specular_transmittance'", "not supported"});
  LoadOptions lenient;
  lenient.lenient = true;
  std::vector<std::string> warnings;
  const Scene s = loadText(dir, dielectric, lenient, &warnings);
  EXPECT_EQ(warnings.size(), 1u);
  EXPECT_FALSE(s.bsdfs.at(0)->tinted());
  expectError([&] { loadText(dir, sceneXml("<texture type=\"bitmap\"><string name=\"filename\" value=\"none.png\"/></texture>")); },
              {"none.png", "not found"});
  expectError([&] { loadText(dir, sceneXml("<texture type=\"noise\"/>")); }, {"unknown plugin 'noise'", "checkerboard, bitmap"});
  expectError([&] { loadText(dir, sceneXml("<bsdf type=\"diffuse\"><texture type=\"checkerboard\"/></bsdf>")); },
              {"needs the parameter's 'name'"});
  expectError([&] { loadText(dir, sceneXml("<bsdf type=\"diffuse\"><rgb name=\"reflectance\" value=\"0.5\"/>"
                                           "<texture type=\"checkerboard\" name=\"reflectance\"/></bsdf>")); },
              {"given more than once"});
  expectError([&] { loadText(dir, sceneXml("<bsdf type=\"blendbsdf\"><bsdf type=\"diffuse\"><texture type=\"checkerboard\" "
                                           "name=\"reflectance\"/></bsdf><bsdf type=\"diffuse\"/></bsdf>")); },
              {"blendbsdf", "textured"});
}

}  // namespace
}  // namespace rc::test
