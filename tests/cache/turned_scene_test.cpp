// Scenes turned as a whole (issue 17): shipped scenes (the glossy Cornell box, the envmap product
// shot) with one more <rotate> at the end of every to_world (shapes, emitters, camera), so the
// picture is the same and only the scene's orientation in world space changes. The path tracer must see the same
// image, and rcache at its defaults the same error: nothing in the cache (axis-aligned octree,
// world-frame SH and their rotation, gradients, the six axis-aligned hemispheres of the light
// split, record radii) may depend on how the scene sits in the world.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <pugixml.hpp>
#include <sstream>

#include "core/image_metrics.h"
#include "scene/scene_loader.h"
#include "scene/scene_test_util.h"
#include "test_scene.h"

namespace rc {
namespace {

constexpr int kRes = 48, kBlock = 16;

// A shipped scene turned about the world origin by `rotate` (a <rotate .../> element; empty: the
// original). Mitsuba 3 composes a <transform>'s children left to right, each applied after the
// ones before, so a last <rotate> in every top-level shape's, sensor's and emitter's to_world
// (one added where there is none: a sphere's center and radius and an envmap's directions go
// through it) turns the whole scene, camera included. Relative file names are made absolute so
// the copy loads from a temporary folder. Returns the number of elements turned in `turned`.
Scene loadTurned(const test::TempDir& dir, const std::string& scene, const std::string& rotate, int* turned) {
  const std::string scenes = std::string(RC_SOURCE_DIR) + "/scenes/";
  pugi::xml_document doc;
  EXPECT_TRUE(doc.load_file((scenes + scene).c_str()));
  pugi::xml_document rot;
  rot.load_string(rotate.c_str());
  *turned = 0;
  for (const pugi::xpath_node& f : doc.select_nodes("//string[@name='filename']")) {
    pugi::xml_attribute v = f.node().attribute("value");
    if (v.value()[0] != '/') v.set_value((scenes + v.value()).c_str());
  }
  for (pugi::xml_node el : doc.child("scene").children()) {
    const std::string tag = el.name();
    if (rotate.empty() || (tag != "shape" && tag != "sensor" && tag != "emitter")) continue;
    // point/directional emitters placed by position/direction cannot take a to_world as well
    EXPECT_FALSE(el.find_child_by_attribute("name", "position") || el.find_child_by_attribute("name", "direction"));
    pugi::xml_node tr = el.find_child_by_attribute("transform", "name", "to_world");
    if (!tr) {
      tr = el.append_child("transform");
      tr.append_attribute("name") = "to_world";
    }
    tr.append_copy(rot.first_child());
    ++*turned;
  }
  std::ostringstream xml;
  doc.save(xml);
  LoadOptions opt;
  opt.defines = {{"res", std::to_string(kRes)}};
  return loadScene(dir.write("turned_" + scene, xml.str()), opt);
}

// Worst block/channel |a − b| over the tolerance 4 % of the reference's block mean + 0.01: the
// light split's per-block tolerance (light_split_test.cpp gives its measured reason: half the
// 512-spp reference's own noise, half record noise correlated over a block). The turned and the
// original reference (same seed) use only a small part of it (bench/RESULTS.md "Turned scenes").
double worstBlockRatio(const Image& a, const Image& ref) {
  const std::vector<double> x = test::blockMeans(a, kBlock).mean, r = test::blockMeans(ref, kBlock).mean;
  double worst = 0.0;
  for (size_t i = 0; i < r.size(); ++i) worst = std::max(worst, std::fabs(x[i] - r[i]) / (0.04 * r[i] + 0.01));
  return worst;
}

using test::statText;

struct Turn {
  const char* name;
  const char* rotate;
};

// A quarter turn about x (a floor becomes a wall: z-up or y-up assumptions show) and 37° about an
// oblique axis (nothing lines up with the octree's, the light split's or the envmap's axes).
const Turn kTurns[] = {{"x90", "<rotate x=\"1\" angle=\"90\"/>"},
                       {"oblique37", "<rotate x=\"0.267261\" y=\"0.534522\" z=\"0.801784\" angle=\"37\"/>"}};

// Renders `scene` and its turned copies: a 512-spp path-traced reference of each and rcache at
// `spp` with `params` (the defaults when empty), and checks
//  - the same picture: the turned scene's reference agrees with the original's per block;
//  - rcache's expectation on the turned scene is its path tracer's, block by block;
//  - turned, rcache makes its own image again (same seed) and the light split the same choices;
//  - the same error: the turned render's relMSE within a factor `factor` of the original's.
void expectSameErrorWhenTurned(const std::string& scene, int elements, const std::map<std::string, std::string>& params,
                               int spp, double factor) {
  const test::TempDir dir;
  int turned = 0;
  const Scene original = loadTurned(dir, scene, "", &turned);
  const auto refOriginal = test::renderScene(original, test::pathSettings(original), 512, 11);
  const auto rcOriginal = test::renderScene(original, test::rcacheSettings(original, params), spp, 3);
  const double errOriginal = compareImages(rcOriginal.image.pixels, refOriginal.image.pixels).relmse;
  ASSERT_GT(rcOriginal.stats.get("records"), 0.0) << statText(rcOriginal.stats, "fallback");
  std::printf("%s original: rcache relMSE %.5f, %g records\n", scene.c_str(), errOriginal, rcOriginal.stats.get("records"));
  for (const Turn& t : kTurns) {
    SCOPED_TRACE(t.name);
    const Scene s = loadTurned(dir, scene, t.rotate, &turned);
    EXPECT_EQ(turned, elements);
    const auto ref = test::renderScene(s, test::pathSettings(s), 512, 11);
    const auto rc = test::renderScene(s, test::rcacheSettings(s, params), spp, 3);
    const double err = compareImages(rc.image.pixels, ref.image.pixels).relmse;
    const double pictureRatio = worstBlockRatio(ref.image, refOriginal.image);
    const double rcacheRatio = worstBlockRatio(rc.image, ref.image);
    const double sameRcache = worstBlockRatio(rc.image, rcOriginal.image);
    std::printf("%s %s: rcache relMSE %.5f (%.3f× the original's), %g records; worst block / tolerance: "
                "turned reference vs original %.3f, turned rcache vs turned reference %.3f (original %.3f), "
                "turned rcache vs original rcache %.3f\n",
                scene.c_str(), t.name, err, err / errOriginal, rc.stats.get("records"), pictureRatio, rcacheRatio,
                worstBlockRatio(rcOriginal.image, refOriginal.image), sameRcache);
    EXPECT_LT(pictureRatio, 1.0);
    EXPECT_LT(rcacheRatio, 1.0);
    // Same seed, same sample streams (they follow pixels and record ids, not world positions):
    // turned, rcache makes its own image again, up to float rounding.
    EXPECT_LT(sameRcache, 1.0);
    // The light split's choices (τ from hemispheres of the envmap, the cached share of its power)
    // are the original's exactly: the map's texels and solid angles do not change when turned.
    EXPECT_EQ(statText(rc.stats, "env_cache"), statText(rcOriginal.stats, "env_cache"));
    EXPECT_EQ(rc.stats.get("env_threshold", -1.0), rcOriginal.stats.get("env_threshold", -1.0));
    EXPECT_EQ(rc.stats.get("env_cached_fraction", -1.0), rcOriginal.stats.get("env_cached_fraction", -1.0));
    EXPECT_LT(err, factor * errOriginal);
    EXPECT_GT(err, errOriginal / factor);
  }
}

// The factor 1.5: turning changes every ray's float rounding, so a turned render is another noise
// realisation of the same estimator at worst; over seeds 3–9 the original's error spreads by 1.31×
// (bench/RESULTS.md "Turned scenes"), the turned renders (same seed) stay within 3 %. Record radii
// made 1 + 3|n_z| times larger (a z-aligned choice, tried on purpose) give 1.71× on x90.
TEST(TurnedScene, GlossyCornellTurnedAsAWholeHasTheSameErrorAndPicture) {
  expectSameErrorWhenTurned("cornell_glossy.xml", 9, {}, 16, 1.5);  // sensor, five walls, cube, cone, light
}

// The envmap product shot: the envmap's to_world, the light split of the sky and records carrying
// its cached part. fallback=false: at this size the pilot would path trace the scene. The factor
// 2: the sun's rare paths spread the error over seeds 3–9 by 1.76× at 64 spp (the turned renders:
// within 1.2 %); what catches an orientation-dependent split here is the exact comparison of its
// statistics (world-axis hemispheres: τ 0.74 instead of 2.07 on oblique37, 68 % cached instead
// of 72 %) and the same-seed per-block comparison with the original's image.
TEST(TurnedScene, EnvmapProductTurnedAsAWholeHasTheSameErrorAndPicture) {
  expectSameErrorWhenTurned("envmap_product.xml", 7, {{"fallback", "false"}}, 64, 2.0);  // sensor, envmap, floor, 3 spheres, knot
}

}  // namespace
}  // namespace rc
