// <spectrum> in RGB mode as Mitsuba 3's RGB variants convert it (scene/spectrum_rgb.h).
#include "scene/spectrum_rgb.h"
#include "scene_test_util.h"

namespace rc::test {
namespace {

void expectColor(const Color& got, const Color& want, float tol) {
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], tol) << "channel " << c;
}

TEST(Spectra, DefinitionalValues) {
  // D65 is sRGB's white: a flat reflectance under it is grey, with luminance = its value.
  expectColor(spectrumToRgb({360, 830}, {0.5, 0.5}, true, true), Color(0.5f), 0.01f);
  // Without D65 the CIE curves are normalised to equal area, so a flat emitter spectrum has XYZ
  // (1, 1, 1)·value — the colour Mitsuba also gives a constant emitter spectrum.
  expectColor(spectrumToRgb({360, 830}, {2.0, 2.0}, false, false), uniformEmitterSpectrumRgb(2.0), 0.02f);
  expectColor(uniformEmitterSpectrumRgb(1.0), Color(1.204794f, 0.948291f, 0.908916f), 1e-5f);  // xyz_to_srgb(1)
  // Values mi.spectrum_list_to_srgb (Mitsuba 3.9.1) returns for these lists.
  expectColor(spectrumToRgb({400, 500, 600, 700}, {0.1, 0.8, 0.3, 0.6}, true, true), Color(0.221375f, 0.618594f, 0.469112f), 2e-4f);
  expectColor(spectrumToRgb({400, 500, 600, 700}, {5, 1, 2, 9}, false, false), Color(4.46978f, 1.05468f, 2.76624f), 2e-3f);
  // Reflectances are clamped to [0, 1].
  expectColor(spectrumToRgb({360, 830}, {3.0, 3.0}, true, true), Color(1.0f), 1e-6f);
}

TEST(Spectra, SceneValuesDependOnTheOwner) {
  TempDir dir;
  const Scene s = loadText(dir, sceneXml(
      "<shape type=\"rectangle\"><bsdf type=\"diffuse\"><spectrum name=\"reflectance\" value=\"400:0.1, 500:0.8, 600:0.3, 700:0.6\"/></bsdf>"
      "<emitter type=\"area\"><spectrum name=\"radiance\" value=\"3\"/></emitter></shape>"
      "<emitter type=\"point\"><spectrum name=\"intensity\" value=\"400:5 500:1 600:2 700:9\"/></emitter>"));
  ASSERT_EQ(s.emitters.size(), 2u);
  expectColor(s.emitters[0].radiance, uniformEmitterSpectrumRgb(3.0), 1e-6f);
  expectColor(s.emitters[1].intensity, Color(4.46978f, 1.05468f, 2.76624f), 2e-3f);
}

}  // namespace
}  // namespace rc::test
