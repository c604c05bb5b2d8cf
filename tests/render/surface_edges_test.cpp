// Surface edges: the pixels where the radiance cache's last fill pass looks up sub-pixel points.
#include <gtest/gtest.h>

#include "render/camera.h"
#include "render/surface_edges.h"
#include "render_test_scenes.h"

namespace rc {
namespace {

Hit hitOn(int mesh, int bsdf, float t, const Vec3& n) {
  Hit h;
  h.t = t;
  h.mesh = mesh;
  h.bsdf = bsdf;
  h.ns = h.ng = n;
  return h;
}

TEST(SurfaceEdges, WhatCountsAsADifferentSurface) {
  const Hit a = hitOn(0, 0, 2.0f, {0, 0, 1});
  EXPECT_FALSE(surfacesDiffer(a, hitOn(0, 0, 2.1f, glm::normalize(Vec3(0.1f, 0, 1)))));  // same smooth surface
  EXPECT_TRUE(surfacesDiffer(a, hitOn(1, 0, 2.0f, {0, 0, 1})));                          // another mesh
  EXPECT_TRUE(surfacesDiffer(a, hitOn(0, 1, 2.0f, {0, 0, 1})));                          // another material
  EXPECT_TRUE(surfacesDiffer(a, hitOn(0, 0, 2.0f, glm::normalize(Vec3(1, 0, 1)))));      // a 45° crease
  EXPECT_TRUE(surfacesDiffer(a, hitOn(0, 0, 2.5f, {0, 0, 1})));                          // a depth jump
  EXPECT_TRUE(surfacesDiffer(a, Hit{}));                                                 // sky beside it
  EXPECT_FALSE(surfacesDiffer(Hit{}, Hit{}));
  Hit sphere = a;
  sphere.mesh = -1;
  sphere.sphere = 0;
  EXPECT_TRUE(surfacesDiffer(a, sphere));
}

// Every pixel whose footprint shows another surface than its centre (found with 4×4 sub-pixel
// rays) is flagged, while most pixels of the box's broad walls are not.
TEST(SurfaceEdges, FlagsEveryPixelThatShowsTwoSurfaces) {
  const int W = 64, H = 64;
  test::World world(test::cornellLike(W, H));
  const CameraModel camera(world.scene.camera, W, H);
  const std::vector<uint8_t> edges = surfaceEdgePixels(*world.accel, camera, W, H);
  ASSERT_EQ(edges.size(), size_t(W) * H);
  int flagged = 0, mixed = 0, missed = 0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const Hit centre = world.accel->intersect(camera.generate(Vec2(x + 0.5f, y + 0.5f)));
      bool differs = false;
      for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) {
          const Hit h = world.accel->intersect(camera.generate(Vec2(x + (i + 0.5f) / 4, y + (j + 0.5f) / 4)));
          differs |= h.valid() != centre.valid() || h.mesh != centre.mesh || h.sphere != centre.sphere;
        }
      const bool flag = edges[size_t(y) * W + x] != 0;
      flagged += flag;
      mixed += differs;
      if (differs && !flag) ++missed;
    }
  EXPECT_GT(mixed, 0);
  EXPECT_EQ(missed, 0) << "pixels showing two surfaces that were not flagged";
  EXPECT_LT(flagged, W * H * 35 / 100) << "edges should be a minority of the pixels";
}

}  // namespace
}  // namespace rc
