// Mitsuba's `cylinder` shape: its placement from p0/p1/radius/to_world, exact ray hits on the open
// tube (outside, inside through an open end, misses along the axis) and the hit's shading data.
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/accel.h"
#include "render/ray_probe.h"
#include "scene/scene_test_util.h"

namespace rc::test {
namespace {

constexpr float kPiF = 3.14159265358979f;

// Radius 0.5 from (1, 0, 0) to (1, 0, 2): the axis along world z.
const std::string kTube = "<shape type=\"cylinder\"><point name=\"p0\" value=\"1, 0, 0\"/><point name=\"p1\" value=\"1, 0, 2\"/>"
                          "<float name=\"radius\" value=\"0.5\"/><bsdf type=\"diffuse\"/></shape>";

TEST(Cylinder, HitsTheSideWithMitsubasNormalAndUv) {
  TempDir dir;
  const Scene s = loadText(dir, sceneXml(kTube));
  ASSERT_EQ(s.cylinders.size(), 1u);
  ASSERT_TRUE(s.meshes.empty());
  const Accel accel(s);
  // From −y toward the axis at height 0.5: hits at y = −0.5, normal −y, φ = 3π/2, v = 0.25.
  const Hit h = cast(accel, {1, -5, 0.5f}, {0, 1, 0});
  ASSERT_TRUE(h.valid());
  EXPECT_NEAR(h.t, 4.5f, 1e-5f);
  EXPECT_NEAR(glm::length(h.p - Vec3(1, -0.5f, 0.5f)), 0.0f, 1e-5f);
  EXPECT_NEAR(glm::length(h.ng - Vec3(0, -1, 0)), 0.0f, 1e-5f);
  EXPECT_NEAR(h.uv.x, 0.75f, 1e-5f);
  EXPECT_NEAR(h.uv.y, 0.25f, 1e-5f);
  // dp/du = 2π r (−sin φ, cos φ, 0) in the cylinder's frame: |dp/du| = 2π·0.5, tangent to the side.
  EXPECT_NEAR(glm::length(h.dpdu), 2.0f * kPiF * 0.5f, 1e-4f);
  EXPECT_NEAR(glm::dot(h.dpdu, h.ng), 0.0f, 1e-4f);
  EXPECT_EQ(h.bsdf, 0);
  // Oblique ray: t from the 2-D quadratic in the xy plane.
  const Vec3 d = glm::normalize(Vec3(0.3f, 1.0f, 0.2f));
  const Hit o = cast(accel, {0.2f, -3, 0.4f}, d);
  ASSERT_TRUE(o.valid());
  const Vec3 p = o.p;
  EXPECT_NEAR(std::hypot(p.x - 1.0f, p.y), 0.5f, 1e-5f);
  EXPECT_NEAR(glm::length(Vec3(0.2f, -3, 0.4f) + o.t * d - p), 0.0f, 1e-4f);
}

TEST(Cylinder, OpenEndsShowTheInsideAndAxisRaysMiss) {
  TempDir dir;
  const Scene s = loadText(dir, sceneXml(kTube));
  const Accel accel(s);
  // Straight down the axis: never crosses the side.
  EXPECT_FALSE(cast(accel, {1, 0, 5}, {0, 0, -1}).valid());
  // Down into the open top at 45°: the near wall's crossing (y = −0.5) is at z = 2.5, above the
  // tube, so the ray hits the far wall's inside at y = 0.5, z = 1.5; the normal stays the shape's
  // (outward), facing away from the ray.
  const Hit in = cast(accel, {1, -2, 4}, {0, 1, -1});
  ASSERT_TRUE(in.valid());
  EXPECT_NEAR(glm::length(in.p - Vec3(1, 0.5f, 1.5f)), 0.0f, 1e-5f);
  EXPECT_NEAR(glm::length(in.ng - Vec3(0, 1, 0)), 0.0f, 1e-5f);
  // Passing beside the tube, and past its end.
  EXPECT_FALSE(cast(accel, {1.6f, -5, 1}, {0, 1, 0}).valid());
  EXPECT_FALSE(cast(accel, {1, -5, 2.1f}, {0, 1, 0}).valid());
  expectBlockedBetween(accel, {1, -5, 1}, {0, 1, 0}, 4.4f, 4.6f);
}

TEST(Cylinder, FlipNormalsAndToWorld) {
  TempDir dir;
  const Scene s = loadText(dir, sceneXml("<shape type=\"cylinder\"><boolean name=\"flip_normals\" value=\"true\"/></shape>\n"
                                         "<shape type=\"cylinder\"><transform name=\"to_world\"><scale value=\"2\"/>"
                                         "<rotate x=\"1\" angle=\"90\"/><translate z=\"10\"/></transform></shape>"));
  ASSERT_EQ(s.cylinders.size(), 2u);
  const Accel accel(s);
  const Hit flipped = cast(accel, {-5, 0, 0.5f}, {1, 0, 0});
  ASSERT_TRUE(flipped.valid());
  EXPECT_NEAR(glm::length(flipped.ng - Vec3(1, 0, 0)), 0.0f, 1e-5f);  // toward the axis
  // Radius 2, axis rotated onto −y (z ↦ −y... then y from 0 to −2), at z = 10: from +z the top at z = 12.
  const Hit placed = cast(accel, {0, -1, 20}, {0, 0, -1});
  ASSERT_TRUE(placed.valid());
  EXPECT_NEAR(placed.p.z, 12.0f, 1e-4f);
  EXPECT_NEAR(glm::length(placed.ng - Vec3(0, 0, 1)), 0.0f, 1e-5f);
}

TEST(Cylinder, MalformedParametersNameTheirLine) {
  TempDir dir;
  expectError([&] { loadText(dir, sceneXml("<shape type=\"cylinder\">\n<float name=\"radius\" value=\"0\"/></shape>")); },
              {"scene.xml:4:", "radius must be positive"});
  expectError([&] { loadText(dir, sceneXml("<shape type=\"cylinder\">\n<point name=\"p1\" value=\"0, 0, 0\"/></shape>")); },
              {"scene.xml:4:", "'p0' and 'p1' coincide"});
  expectError([&] { loadText(dir, sceneXml("<shape type=\"cylinder\">\n<emitter type=\"area\"/></shape>")); },
              {"scene.xml:4:", "area emitter on a cylinder is not supported"});
  expectError([&] { loadText(dir, sceneXml("<shape type=\"cylinder\">\n<float name=\"height\" value=\"2\"/></shape>")); },
              {"scene.xml:4:", "unsupported parameter 'height'"});
}

}  // namespace
}  // namespace rc::test
