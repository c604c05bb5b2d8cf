// Camera conventions pinned against Mitsuba 3's perspective sensor.
#include <gtest/gtest.h>

#include "core/error.h"
#include "render/camera.h"
#include "render_test_scenes.h"

namespace rc {
namespace {

constexpr float kDeg = kPi / 180.0f;

float angleBetween(const Vec3& a, const Vec3& b) { return std::acos(glm::clamp(glm::dot(a, b), -1.0f, 1.0f)); }

TEST(Camera, CentreRayIsForward) {
  Camera cam;
  cam.toWorld = test::lookAt({1, 2, 3}, {4, -1, 0}, {0, 1, 0});
  const CameraModel model(cam, 64, 48);
  const Ray r = model.generate(Vec2(32, 24));
  const Vec3 forward = glm::normalize(Vec3(4, -1, 0) - Vec3(1, 2, 3));
  EXPECT_NEAR(glm::dot(r.d, forward), 1.0f, 1e-6f);
  EXPECT_NEAR(glm::length(r.o - Vec3(1, 2, 3)), 0.0f, 1e-6f);
}

TEST(Camera, FovEdgesAlongX) {
  Camera cam;  // identity: looks down +z, up +y
  cam.fovDegrees = 60.0f;
  cam.fovAxis = "x";
  const CameraModel model(cam, 200, 100);
  const Ray left = model.generate(Vec2(0, 50));
  const Ray right = model.generate(Vec2(200, 50));
  EXPECT_NEAR(angleBetween(left.d, {0, 0, 1}), 30.0f * kDeg, 1e-5f);
  EXPECT_NEAR(angleBetween(right.d, {0, 0, 1}), 30.0f * kDeg, 1e-5f);
  // Mitsuba: image left is camera-local +x (its look_at puts `left` in the first column).
  EXPECT_GT(left.d.x, 0.5f);
  EXPECT_LT(right.d.x, -0.5f);
  // Image top is local +y.
  EXPECT_GT(model.generate(Vec2(100, 0)).d.y, 0.0f);
  EXPECT_LT(model.generate(Vec2(100, 100)).d.y, 0.0f);
  // Vertical half-angle follows from the aspect ratio: tan(v/2) = tan(30°)/2.
  EXPECT_NEAR(angleBetween(model.generate(Vec2(100, 0)).d, {0, 0, 1}), std::atan(std::tan(30.0f * kDeg) / 2.0f), 1e-5f);
}

TEST(Camera, FovAxisYAndDiagonal) {
  Camera cam;
  cam.fovDegrees = 50.0f;
  cam.fovAxis = "y";
  const CameraModel my(cam, 300, 100);
  EXPECT_NEAR(angleBetween(my.generate(Vec2(150, 0)).d, {0, 0, 1}), 25.0f * kDeg, 1e-5f);
  cam.fovAxis = "diagonal";
  const CameraModel md(cam, 300, 100);
  EXPECT_NEAR(angleBetween(md.generate(Vec2(0, 0)).d, {0, 0, 1}), 25.0f * kDeg, 1e-5f);
  cam.fovAxis = "smaller";  // aspect > 1 → y
  EXPECT_NEAR(CameraModel(cam, 300, 100).fovXDegrees(), my.fovXDegrees(), 1e-4f);
  cam.fovAxis = "larger";  // aspect > 1 → x
  EXPECT_NEAR(CameraModel(cam, 300, 100).fovXDegrees(), 50.0f, 1e-5f);
  cam.fovAxis = "z";
  EXPECT_THROW(CameraModel(cam, 300, 100), Error);
}

TEST(Camera, LookAtImageIsNotMirrored) {
  // Looking down −z with +y up, world +x must appear on the image's right (as in Mitsuba).
  Camera cam;
  cam.toWorld = test::lookAt({0, 0, 5}, {0, 0, 0}, {0, 1, 0});
  const CameraModel model(cam, 64, 64);
  EXPECT_GT(model.generate(Vec2(64, 32)).d.x, 0.1f);
  EXPECT_LT(model.generate(Vec2(0, 32)).d.x, -0.1f);
  EXPECT_GT(model.generate(Vec2(32, 0)).d.y, 0.1f);
}

TEST(Camera, PixelFootprintMatchesNeighbourRays) {
  Camera cam;
  cam.fovDegrees = 45.0f;
  const CameraModel model(cam, 128, 96);
  const float d = 7.0f;
  const Ray a = model.generate(Vec2(64, 48)), b = model.generate(Vec2(65, 48));
  const float spacing = glm::length(a.d * (d / a.d.z) - b.d * (d / b.d.z));
  EXPECT_NEAR(model.pixelFootprint(d), spacing, 1e-4f * d);
}

TEST(Camera, SquareFilmFootprintFollowsThePixelCountNotTheAspect) {
  Camera cam;
  cam.fovDegrees = 45.0f;  // along x
  const float d = 3.0f;
  const CameraModel square(cam, 128, 128), strip(cam, 16384, 1), twoRows(cam, 8192, 2), tall(cam, 1, 16384);
  EXPECT_FLOAT_EQ(square.squareFilmPixelFootprint(d), square.pixelFootprint(d));
  // A strip's pixels are 128× smaller; the square film of its pixel count is the 128×128 one.
  EXPECT_NEAR(strip.pixelFootprint(d) * 128.0f, square.pixelFootprint(d), 1e-6f);
  EXPECT_NEAR(strip.squareFilmPixelFootprint(d), square.pixelFootprint(d), 1e-6f);
  EXPECT_NEAR(twoRows.squareFilmPixelFootprint(d), square.pixelFootprint(d), 1e-6f);
  // Never below the real pixel: a tall film's pixels (45° wide) are already the larger.
  EXPECT_FLOAT_EQ(tall.squareFilmPixelFootprint(d), tall.pixelFootprint(d));
}

TEST(Camera, NearClipIsADepth) {
  Camera cam;
  cam.fovDegrees = 90.0f;
  cam.nearClip = 0.5f;
  const CameraModel model(cam, 100, 100);
  const Ray corner = model.generate(Vec2(0, 50));  // 45° off axis
  EXPECT_NEAR(corner.tMin * corner.d.z, 0.5f, 1e-5f);
}

}  // namespace
}  // namespace rc
