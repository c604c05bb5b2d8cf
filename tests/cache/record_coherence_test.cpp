// The share pilot's coherence test (cache/record_coherence.h): a diffuse washboard under a sky —
// ridges of alternating facets tilted ±60° (neighbouring facets' normals 120° apart, so a record
// on one never serves the other) — is path traced where its facets are narrower than a pixel,
// and cached where the same mesh's facets span several pixels (seen through a narrower field of
// view, as a 16× finer film would see them, at a test's cost). Every pilot point is served
// (diffuse), so only the coherence test can tell the two apart.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "cache/record_coherence.h"
#include "test_scene.h"

namespace rc {
namespace {

using test::statText;

// Ridges along y over x ∈ [−1.6, 1.6] (wider than the view), each facet `facetWidth` wide in x
// and tilted 60° from the z = 0 plane, seen head-on from z = 3 through a square film of res² pixels
// and a field of view of fovDegrees.
Scene washboardScene(float facetWidth, int res, float fovDegrees) {
  Scene s;
  s.bsdfs.push_back(test::diffuse(0.6f, 0.55f, 0.5f));
  Mesh m;
  m.name = "washboard";
  m.bsdf = 0;
  const float h = facetWidth * std::tan(kPi / 3.0f), x0 = -1.6f, y0 = -1.6f, y1 = 1.6f;
  const int facets = static_cast<int>(std::ceil(3.2f / facetWidth));
  for (int k = 0; k < facets; ++k) {  // own vertices per facet: flat normals
    const float xa = x0 + k * facetWidth, xb = xa + facetWidth;
    const float za = (k % 2) ? h : 0.0f, zb = (k % 2) ? 0.0f : h;
    const uint32_t v = static_cast<uint32_t>(m.positions.size());
    m.positions.insert(m.positions.end(), {{xa, y0, za}, {xb, y0, zb}, {xb, y1, zb}, {xa, y1, za}});
    m.triangles.push_back(glm::uvec3(v, v + 1, v + 2));
    m.triangles.push_back(glm::uvec3(v, v + 2, v + 3));
  }
  s.meshes.push_back(m);
  s.emitters.push_back(test::skyEmitter(0.0f));
  test::setTestCamera(s, Vec3(0, 0, 3), Vec3(0, 0, 0), res, res);
  s.camera.fovDegrees = fovDegrees;
  return s;
}

// A pixel at the washboard is 2·3·tan(fov/2)/res wide: 0.078 at 32² and 45°, 0.003 at 32² and 1.83°.
constexpr float kFacetWidth = 0.012f;

TEST(RecordCoherence, SubPixelFacetsArePathTraced) {
  // A facet is 0.15 px wide: a neighbour half a pixel away lies on another facet, of the other
  // orientation (never served) or a parallel one two or more facets over (served where it is not
  // in front of the record: a third of the neighbours).
  const Scene s = washboardScene(kFacetWidth, 32, 45.0f);
  const auto path = test::renderScene(s, test::pathSettings(s), 2, 5);
  const auto r = test::renderScene(s, test::rcacheSettings(s), 2, 5);
  const std::string why = statText(r.stats, "fallback");
  std::printf("%s\n", why.c_str());
  EXPECT_EQ(why.rfind("path traced: a floor record", 0), 0u) << why;
  EXPECT_DOUBLE_EQ(r.stats.get("pilot_served_share"), 1.0);  // the share alone would cache it
  EXPECT_EQ(r.stats.get("pilot_coherence_points"), 1024.0);
  EXPECT_LT(r.stats.get("pilot_neighbour_served_bound"), minNeighbourServed());
  EXPECT_EQ(r.stats.get("records", 0.0), 0.0);
  // Path traced by the path integrator: its image, bit for bit.
  ASSERT_EQ(r.image.pixels.size(), path.image.pixels.size());
  for (size_t i = 0; i < path.image.pixels.size(); ++i) ASSERT_EQ(r.image.pixels[i], path.image.pixels[i]) << i;
}

TEST(RecordCoherence, FacetsSpanningPixelsAreCached) {
  // The same facets 4 px wide: records serve their neighbours within a facet.
  const Scene s = washboardScene(kFacetWidth, 32, 2.0f * std::atan(0.048f / 3.0f) * 180.0f / kPi);
  const auto r = test::renderScene(s, test::rcacheSettings(s), 1, 5);
  const std::string why = statText(r.stats, "fallback");
  std::printf("%s\n", why.c_str());
  EXPECT_EQ(why.rfind("cached", 0), 0u) << why;
  EXPECT_GT(r.stats.get("pilot_neighbour_served_bound"), minNeighbourServed());
  EXPECT_GT(r.stats.get("records", 0.0), 0.0);
}

// A small image does not flip on noise: 4 neighbours served of 16 points (a 4² image) leave the
// bound above the threshold; the same share over 160 points does not.
TEST(RecordCoherence, FewPilotPointsDoNotDecide) {
  EXPECT_NEAR(minNeighbourServed(), 0.505, 0.001);
  RecordCoherence c;
  c.points = 16;
  c.served = 4;
  EXPECT_GT(c.upperBound(), minNeighbourServed());
  c.points = 160;
  c.served = 40;
  EXPECT_LT(c.upperBound(), minNeighbourServed());
  c.points = 0;
  EXPECT_FALSE(c.tooIncoherent());
}

}  // namespace
}  // namespace rc
