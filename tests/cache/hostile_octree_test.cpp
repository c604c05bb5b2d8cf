// Hostile positions and radii (issue 19, finding 2/3): the record octree must not multiply its
// nodes on non-finite bounds, overflowing positions or radii below float resolution, and
// records kept high in the tree must still be found.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "cache/radius_floor.h"
#include "cache/record_octree.h"
#include "geometry/scene_bounds.h"

namespace rc {
namespace {

std::vector<uint32_t> candidates(const RecordOctree& tree, const Vec3& p) {
  std::vector<uint32_t> ids;
  tree.query(p, [&](uint32_t id) { ids.push_back(id); });
  return ids;
}

TEST(HostileOctree, InfiniteBoundsDoNotMultiplyNodes) {
  RecordOctree tree(Vec3(0.0f), Vec3(INFINITY, 1.0f, 1.0f));
  for (uint32_t i = 0; i < 100; ++i) tree.insert(i, Vec3(0.01f * i, 0.5f, 0.5f), 0.01f);
  EXPECT_EQ(tree.size(), 100u);
  // Each record lives in at most 27 cells of one depth, plus the path to them.
  EXPECT_LT(tree.nodeCount(), 100u * 27u * 40u);
  const auto ids = candidates(tree, Vec3(0.5f, 0.5f, 0.5f));
  EXPECT_NE(std::find(ids.begin(), ids.end(), 50u), ids.end());
}

TEST(HostileOctree, NanBoundsStartFromAFiniteRoot) {
  RecordOctree tree(Vec3(NAN), Vec3(NAN));
  tree.insert(0, Vec3(0.25f), 0.1f);
  EXPECT_LT(tree.nodeCount(), 27u * 40u);
  const auto ids = candidates(tree, Vec3(0.25f));
  EXPECT_NE(std::find(ids.begin(), ids.end(), 0u), ids.end());
}

TEST(HostileOctree, OverflowingPositionStaysInTheRoot) {
  RecordOctree tree(Vec3(-1.0f), Vec3(1.0f));
  tree.insert(0, Vec3(3e38f, 0, 0), 1.0f);       // the root cannot double to hold it
  tree.insert(1, Vec3(INFINITY, 0, 0), 1.0f);    // not stored at all
  tree.insert(2, Vec3(0.5f), 0.1f);
  EXPECT_EQ(tree.size(), 2u);
  EXPECT_LT(tree.nodeCount(), 2u * 27u * 130u);
  const auto ids = candidates(tree, Vec3(0.5f));
  EXPECT_NE(std::find(ids.begin(), ids.end(), 2u), ids.end());
}

TEST(HostileOctree, RadiusBelowFloatResolutionDoesNotDescendForever) {
  RecordOctree tree(Vec3(0.0f), Vec3(2.0f));
  // A point on cell boundaries with a radius far below the ulp of its coordinates: below the
  // resolution every child would overlap it.
  tree.insert(0, Vec3(1.0f), 1e-30f);
  tree.insert(1, Vec3(1.0f + 1e-7f, 1.0f, 1.0f), 0.0f);
  EXPECT_LT(tree.nodeCount(), 2u * 8u * 41u);
  const auto ids = candidates(tree, Vec3(1.0f));
  EXPECT_NE(std::find(ids.begin(), ids.end(), 0u), ids.end());
}

TEST(HostileBounds, OnlyFiniteReferencedGeometry) {
  Scene scene;
  Mesh m;
  m.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(INFINITY, 0, 0), Vec3(-50, 0, 0)};
  m.triangles = {glm::uvec3(0, 1, 2)};  // vertices 3 and 4 are unreferenced
  scene.meshes.push_back(m);
  Sphere s;
  s.center = Vec3(3e38f, 0, 0);
  s.radius = 1e38f;  // centre + radius overflows
  scene.spheres.push_back(s);
  Vec3 lo, hi;
  finiteSceneBounds(scene, lo, hi);
  EXPECT_EQ(lo, Vec3(0.0f));
  EXPECT_EQ(hi, Vec3(1, 1, 0));
}

TEST(HostileBounds, NoFiniteGeometryGivesAUnitCube) {
  Scene scene;
  Vec3 lo, hi;
  finiteSceneBounds(scene, lo, hi);
  EXPECT_EQ(lo, Vec3(-1.0f));
  EXPECT_EQ(hi, Vec3(1.0f));
}

TEST(RadiusFloor, ReachSquaredIsAPositiveFloatEverywhere) {
  for (const Vec3 p : {Vec3(0.0f), Vec3(1e-30f), Vec3(1.0f), Vec3(-1e6f, 2, 3), Vec3(1e12f)}) {
    const float r = minimumReach(p, 0.0f);
    EXPECT_GT(r * r, 0.0f);
    EXPECT_TRUE(std::isfinite(r * r));
    // Resolvable at p: a point displaced by the reach differs from p.
    EXPECT_NE(p.x + r, p.x);
  }
}

}  // namespace
}  // namespace rc
