// The sdfgrid and instances through both integrators. A plane sampled into an sdfgrid (exact: its
// distance is linear) under a constant white sky sees the sky over its whole upper hemisphere, so
// it shows its reflectance ρ; darker pixels would be self-shadowing, brighter ones light counted
// twice. An instance of a mesh group renders as the same mesh placed by hand.
#include <gtest/gtest.h>

#include "cache/cache_file.h"
#include "common/vol_file_bytes.h"
#include "scene/scene_test_util.h"
#include "test_scene.h"

namespace rc {
namespace {

const std::string kSky = "<emitter type=\"constant\"><rgb name=\"radiance\" value=\"1\"/></emitter>";
std::string camera(int size) {
  return "<sensor type=\"perspective\"><float name=\"fov\" value=\"30\"/><transform name=\"to_world\">"
         "<lookat origin=\"0.3, -0.5, 6\" target=\"0, 0, 0\" up=\"0, 1, 0\"/></transform><film type=\"hdrfilm\">"
         "<integer name=\"width\" value=\"" + std::to_string(size) + "\"/><integer name=\"height\" value=\"" +
         std::to_string(size) + "\"/><rfilter type=\"box\"/></film></sensor>";
}

TEST(SdfGridRender, PlaneGridUnderAWhiteSkyShowsItsReflectance) {
  test::TempDir dir;
  // z = 0.4 in the grid's cube (tilted samples would do as well: the plane is exact either way),
  // stretched to cover the view and turned a little.
  dir.write("plane.vol", test::volGrid(4, 3, 5, [](int, int, int k) { return k / 4.0f - 0.4f; }));
  const Scene s = test::loadText(dir, test::sceneXml(
      kSky + "<shape type=\"sdfgrid\"><string name=\"filename\" value=\"plane.vol\"/><transform name=\"to_world\">"
             "<translate value=\"-0.5, -0.5, -0.4\"/><scale value=\"8, 6, 1\"/><rotate x=\"1\" angle=\"10\"/></transform>"
             "<bsdf type=\"diffuse\"><rgb name=\"reflectance\" value=\"0.8, 0.5, 0.2\"/></bsdf></shape>",
      camera(24)));
  for (const bool cache : {false, true}) {
    const std::string name = cache ? "rcache" : "path";
    const Image img = test::renderScene(s, cache ? test::rcacheSettings(s) : test::pathSettings(s), 32, 3).image;
    Color mean(0.0f);
    for (const Color& c : img.pixels) mean += c;
    mean /= static_cast<float>(img.pixels.size());
    const Color rho(0.8f, 0.5f, 0.2f);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(mean[k], rho[k], 0.01f * rho[k]) << name << " channel " << k;
  }
}

TEST(SdfGridRender, InstanceRendersAsTheMeshPlacedByHand) {
  test::TempDir dir;
  dir.write("m.obj", "v -1 -1 0\nv 1 -1 0\nv 0 1 0\nv 0 0 1\nvn 0 0 -1\nvn 0.3 0 1\nvn -0.2 0.5 1\nvn 0 0 1\n"
                     "f 1//1 2//2 4//4\nf 2//2 3//3 4//4\nf 3//3 1//1 4//4\n");
  // Dyadic entries: the placed positions are the same floats either way (normals round differently).
  const std::string group = "<shape type=\"shapegroup\" id=\"g\"><shape type=\"obj\"><string name=\"filename\" value=\"m.obj\"/>"
                            "<transform name=\"to_world\"><scale value=\"1, 2, 0.5\"/></transform>"
                            "<bsdf type=\"diffuse\"><rgb name=\"reflectance\" value=\"0.7, 0.6, 0.5\"/></bsdf></shape></shape>";
  const std::string instance = "<shape type=\"instance\"><ref id=\"g\"/><transform name=\"to_world\">"
                               "<matrix value=\"1.5 0 0 0.25  0 0.5 0 -0.5  0 0 2 0  0 0 0 1\"/></transform></shape>";
  const std::string byHand = "<shape type=\"obj\"><string name=\"filename\" value=\"m.obj\"/><transform name=\"to_world\">"
                             "<matrix value=\"1.5 0 0 0.25  0 1 0 -0.5  0 0 1 0  0 0 0 1\"/></transform>"
                             "<bsdf type=\"diffuse\"><rgb name=\"reflectance\" value=\"0.7, 0.6, 0.5\"/></bsdf></shape>";
  const std::string floor = "<shape type=\"rectangle\"><transform name=\"to_world\"><scale value=\"5\"/>"
                            "<translate z=\"-0.2\"/></transform></shape>";
  const Scene a = test::loadText(dir, test::sceneXml(kSky + floor + group + instance, camera(16)));
  const Scene b = test::loadText(dir, test::sceneXml(kSky + floor + byHand, camera(16)));
  ASSERT_EQ(a.meshes.size(), 2u);
  EXPECT_EQ(a.meshes[1].positions, b.meshes[1].positions);
  for (const bool cache : {false, true}) {
    const std::string name = cache ? "rcache" : "path";
    const Image ia = test::renderScene(a, cache ? test::rcacheSettings(a) : test::pathSettings(a), 8, 5).image;
    const Image ib = test::renderScene(b, cache ? test::rcacheSettings(b) : test::pathSettings(b), 8, 5).image;
    ASSERT_EQ(ia.pixels.size(), ib.pixels.size());
    float worst = 0.0f;
    for (size_t i = 0; i < ia.pixels.size(); ++i)
      for (int k = 0; k < 3; ++k)
        worst = std::max(worst, std::fabs(ia.pixels[i][k] - ib.pixels[i][k]) / std::max(1e-3f, ib.pixels[i][k]));
    // Within float error: the normals alone were rounded along another path (relative 1e-7).
    EXPECT_LT(worst, 1e-4f) << name;
  }
}

TEST(SdfGridRender, CacheFilesKnowTheGrid) {
  // A saved cache holds radiance of one geometry: its scene hash must change with the grid's
  // samples, normals and placement.
  test::TempDir dir;
  auto hashOf = [&](float offset, const std::string& params) {
    dir.write("g.vol", test::volGrid(3, 3, 3, [&](int i, int, int) { return i - 0.9f + offset; }));
    const Scene s = test::loadText(dir, test::sceneXml("<shape type=\"sdfgrid\"><string name=\"filename\" value=\"g.vol\"/>" +
                                                       params + "</shape>"));
    return cacheSceneHash(s, -1, false);
  };
  const uint64_t base = hashOf(0.0f, "");
  EXPECT_EQ(hashOf(0.0f, ""), base);
  EXPECT_NE(hashOf(0.1f, ""), base);
  EXPECT_NE(hashOf(0.0f, "<string name=\"normals\" value=\"analytic\"/>"), base);
  EXPECT_NE(hashOf(0.0f, "<transform name=\"to_world\"><translate x=\"1\"/></transform>"), base);
}

}  // namespace
}  // namespace rc
