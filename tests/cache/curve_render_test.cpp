// Curves through both integrators: a lone convex tube (a linear curve: a capsule) under a constant
// white sky sees the sky over its whole outer hemisphere, so its radiance is its reflectance ρ
// everywhere; darker pixels would be self-shadowing from spawned rays finding the tube, brighter
// ones light counted twice. The B-spline tube (straight, open ends) likewise from the side.
#include <gtest/gtest.h>

#include "scene/scene_test_util.h"
#include "test_scene.h"

namespace rc {
namespace {

Scene tubeScene(const test::TempDir& dir, const std::string& type, const std::string& points) {
  dir.write("c.txt", points);
  return test::loadText(dir, test::sceneXml(
      "<emitter type=\"constant\"><rgb name=\"radiance\" value=\"1\"/></emitter>"
      "<shape type=\"" + type + "\"><string name=\"filename\" value=\"c.txt\"/>"
      "<bsdf type=\"diffuse\"><rgb name=\"reflectance\" value=\"0.8, 0.5, 0.2\"/></bsdf></shape>",
      "<sensor type=\"perspective\"><float name=\"fov\" value=\"20\"/><transform name=\"to_world\">"
      "<lookat origin=\"0, -4, 0\" target=\"0, 0, 0\" up=\"0, 0, 1\"/></transform>"
      "<film type=\"hdrfilm\"><integer name=\"width\" value=\"40\"/><integer name=\"height\" value=\"40\"/></film></sensor>"));
}

void expectTubeShowsItsReflectance(const Scene& s) {
  for (const bool cache : {false, true}) {
    const std::string name = cache ? "rcache" : "path";
    const Image img = test::renderScene(s, cache ? test::rcacheSettings(s) : test::pathSettings(s), 64, 3).image;
    // The tube along x through the image centre, radius 0.25 at distance 4 (20° view: ±0.7):
    // rows 17–22 are inside it, away from the silhouette; the top rows see the sky.
    Color tube(0.0f), sky(0.0f);
    for (int x = 8; x < 32; ++x) {
      for (int y = 18; y < 22; ++y) tube += img.pixels[size_t(y) * 40 + x];
      for (int y = 0; y < 4; ++y) sky += img.pixels[size_t(y) * 40 + x];
    }
    tube /= 24.0f * 4.0f;
    sky /= 24.0f * 4.0f;
    const Color rho(0.8f, 0.5f, 0.2f);
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(tube[k], rho[k], 0.01f * rho[k]) << name << " channel " << k;
      EXPECT_NEAR(sky[k], 1.0f, 1e-4f) << name << " channel " << k;
    }
  }
}

TEST(CurveRender, CapsuleUnderAWhiteSkyShowsItsReflectance) {
  test::TempDir dir;
  expectTubeShowsItsReflectance(tubeScene(dir, "linearcurve", "-1 0 0 0.25\n1 0 0 0.25\n"));
}

TEST(CurveRender, BSplineTubeUnderAWhiteSkyShowsItsReflectance) {
  test::TempDir dir;
  expectTubeShowsItsReflectance(tubeScene(dir, "bsplinecurve", "-3 0 0 0.25\n-1 0 0 0.25\n1 0 0 0.25\n3 0 0 0.25\n"));
}

}  // namespace
}  // namespace rc
