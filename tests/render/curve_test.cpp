// Mitsuba's `linearcurve` and `bsplinecurve` through Embree's round curves: hits on straight tubes
// against their closed forms (a capsule; a B-spline of evenly spaced collinear points is a straight
// tube between its second and third point), a cone and a bent B-spline against Mitsuba 3.9.1's
// values (bench/mitsuba_curve_values.py), the inside culled, and rays spawned from curve hits
// never finding the curve again.
#include <gtest/gtest.h>

#include <cmath>

#include "core/rng.h"
#include "geometry/accel.h"
#include "render/ray_probe.h"
#include "scene/scene_test_util.h"

namespace rc::test {
namespace {

constexpr float kPiF = 3.14159265358979f;
constexpr float kR = 0.2f;

Scene curveScene(TempDir& dir, const std::string& type, const std::string& points) {
  dir.write("c.txt", points);
  return loadText(dir, sceneXml("<shape type=\"" + type + "\"><string name=\"filename\" value=\"c.txt\"/></shape>"));
}

// Along x from 0 to 1, radius 0.2: a capsule (linear) / an open tube (B-spline).
const std::string kLinear = "0 0 0 0.2\n1 0 0 0.2\n";
const std::string kBSpline = "-1 0 0 0.2\n0 0 0 0.2\n1 0 0 0.2\n2 0 0 0.2\n";

void expectNear(const Vec3& a, const Vec3& b, float tol, const char* what) {
  EXPECT_NEAR(glm::length(a - b), 0.0f, tol) << what << " (" << a.x << ", " << a.y << ", " << a.z << ")";
}

void expectStraightTubeSide(const Accel& accel, bool bspline) {
  // From −y at x = 0.25: t = 5 − r, normal −y. Mitsuba's frame around the axis x: rot = z,
  // rad = rot × x = y, so −y is u = ½; v = 0.25 along the one segment.
  const Hit h = cast(accel, {0.25f, -5, 0}, {0, 1, 0});
  ASSERT_TRUE(h.valid());
  EXPECT_NEAR(h.t, 5.0f - kR, 1e-4f);
  EXPECT_NEAR(glm::length(h.p - Vec3(0.25f, -kR, 0)), 0.0f, 1e-4f);
  EXPECT_NEAR(glm::length(h.ng - Vec3(0, -1, 0)), 0.0f, 1e-4f);
  EXPECT_EQ(h.ns, h.ng);
  EXPECT_NEAR(h.uv.x, 0.5f, 1e-4f);
  EXPECT_NEAR(h.uv.y, 0.25f, 1e-3f);
  EXPECT_EQ(h.curve, 0);
  EXPECT_EQ(h.prim, 0);
  // B-spline: dp/du = 2π r around the axis, dp/dv = the axis (one segment of length 1); Mitsuba
  // 3.9.1's linearcurve leaves both zero.
  expectNear(h.dpdu, bspline ? Vec3(0, 0, -2.0f * kPiF * kR) : Vec3(0.0f), 1e-3f, "dpdu");
  expectNear(h.dpdv, bspline ? Vec3(1, 0, 0) : Vec3(0.0f), 1e-3f, "dpdv");
  // From +z: the top, u = ¼.
  const Hit top = cast(accel, {0.5f, 0, 5}, {0, 0, -1});
  ASSERT_TRUE(top.valid());
  EXPECT_NEAR(top.t, 5.0f - kR, 1e-4f);
  EXPECT_NEAR(glm::length(top.ng - Vec3(0, 0, 1)), 0.0f, 1e-4f);
  EXPECT_NEAR(top.uv.x, 0.25f, 1e-4f);
  // Oblique: the nearest root of (o + t d)_yz² = r².
  const Vec3 o(0.3f, -2, 0.05f), d = glm::normalize(Vec3(0.1f, 1, 0.03f));
  const float a = d.y * d.y + d.z * d.z, b = 2 * (o.y * d.y + o.z * d.z), c = o.y * o.y + o.z * o.z - kR * kR;
  const float t = (-b - std::sqrt(b * b - 4 * a * c)) / (2 * a);
  const Hit ob = cast(accel, o, d);
  ASSERT_TRUE(ob.valid());
  EXPECT_NEAR(ob.t, t, 1e-4f);
  EXPECT_NEAR(std::hypot(ob.p.y, ob.p.z), kR, 1e-4f);
  EXPECT_NEAR(glm::length(ob.ng - glm::normalize(Vec3(0, ob.p.y, ob.p.z))), 0.0f, 1e-3f);
  EXPECT_NEAR(ob.uv.x, 0.412134f, 1e-4f);  // Mitsuba's
  EXPECT_NEAR(ob.uv.y, 0.482971f, 1e-4f);
  // Beside the tube; from inside (Mitsuba culls the inside; Embree alone would report the exit).
  EXPECT_FALSE(cast(accel, {0.5f, -5, kR * 1.05f}, {0, 1, 0}).valid());
  EXPECT_FALSE(cast(accel, {0.5f, 0, 0}, {0, 1, 0}).valid());
  expectBlockedBetween(accel, {0.5f, -5, 0}, {0, 1, 0}, 4.7f, 4.9f);
}

TEST(Curve, LinearCurveIsACapsule) {
  TempDir dir;
  const Scene s = curveScene(dir, "linearcurve", kLinear);
  const Accel accel(s);
  expectStraightTubeSide(accel, false);
  // The spherical end cap, at x = 1.1: t = 5 − √(r² − 0.1²), the normal from the end point, v = 1.
  const Hit cap = cast(accel, {1.1f, -5, 0}, {0, 1, 0});
  ASSERT_TRUE(cap.valid());
  EXPECT_NEAR(cap.t, 5.0f - std::sqrt(kR * kR - 0.01f), 1e-4f);
  expectNear(cap.ng, glm::normalize(Vec3(0.1f, -std::sqrt(kR * kR - 0.01f), 0)), 1e-3f, "cap normal");
  EXPECT_NEAR(cap.uv.y, 1.0f, 1e-4f);
  // Along the axis Embree's test finds nothing, in Mitsuba as here; past the cap's reach.
  EXPECT_FALSE(cast(accel, {5, 0, 0}, {-1, 0, 0}).valid());
  EXPECT_FALSE(cast(accel, {1.0f + kR * 1.05f, -5, 0}, {0, 1, 0}).valid());
}

TEST(Curve, StraightBSplineIsAnOpenTube) {
  TempDir dir;
  const Scene s = curveScene(dir, "bsplinecurve", kBSpline);
  const Accel accel(s);
  expectStraightTubeSide(accel, true);
  // No end cap (Mitsuba: "open-ended"): along the axis the ray enters the open end and the inside is culled.
  EXPECT_FALSE(cast(accel, {5, 0, 0}, {-1, 0, 0}).valid());
  // The tube ends with the segment, at x = 1.
  EXPECT_FALSE(cast(accel, {1.02f, -5, 0}, {0, 1, 0}).valid());
}

struct MitsubaHit {
  Vec3 o, d;
  float t;
  Vec3 n;
  Vec2 uv;
  Vec3 dpdu, dpdv;
};

void expectMitsubaHits(const Scene& s, std::initializer_list<MitsubaHit> cases) {
  const Accel accel(s);
  for (const MitsubaHit& m : cases) {
    const Hit h = cast(accel, m.o, m.d);
    ASSERT_TRUE(h.valid());
    EXPECT_NEAR(h.t, m.t, 1e-4f);
    expectNear(h.ng, m.n, 1e-4f, "n");
    EXPECT_NEAR(h.uv.x, m.uv.x, 1e-4f);
    EXPECT_NEAR(h.uv.y, m.uv.y, 1e-4f);
    expectNear(h.dpdu, m.dpdu, 1e-4f * (1.0f + glm::length(m.dpdu)), "dpdu");
    expectNear(h.dpdv, m.dpdv, 1e-4f * (1.0f + glm::length(m.dpdv)), "dpdv");
  }
}

TEST(Curve, ConeAndBentBSplineMatchMitsuba) {
  TempDir dir;
  // Radius 0.1 to 0.3 along x: Embree's v and the normal tilt with the radius.
  expectMitsubaHits(curveScene(dir, "linearcurve", "0 0 0 0.1\n1 0 0 0.3\n"),
                    {{{0.5f, -5, 0}, {0, 1, 0}, 4.795876f, {-0.2f, -0.9797959f, 0}, {0.5f, 0.5416667f}, {}, {}},
                     {{0.2f, 0.1f, 5}, {0, 0, -1}, 4.897938f, {-0.2f, 0.6857138f, 0.6998547f}, {0.1266243f, 0.2291667f}, {}, {}}});
  // A bend in the xy plane with varying radius: the curvature correction of the normal, the
  // partials from the Frenet frame.
  TempDir dir2;
  expectMitsubaHits(curveScene(dir2, "bsplinecurve", "0 0 0 0.05\n1 0 0 0.1\n2 1 0 0.2\n2 2 0 0.1\n"),
                    {{{1.2f, 0.3f, 5}, {0, 0, -1}, 4.875873f, {-0.1067952f, 0.0352414f, 0.9936563f}, {0.2355949f, 0.2079689f},
                      {0.4479004f, -0.6384768f, 0.0707834f}, {0.9682970f, 0.6881057f, 0.0796646f}},
                     {{1.5f, 0.5f, 5}, {0, 0, -1}, 4.856111f, {0.1029309f, -0.1803320f, 0.9782053f}, {0.2821442f, 0.5f},
                      {0.6392846f, -0.6392846f, -0.1851203f}, {0.8966566f, 0.8771530f, 0.0673526f}}});
}

// Rays leaving curve hits into the outer hemisphere never hit the same tube again: the straight
// tubes are convex, so any such hit is self-intersection error.
void expectNoSelfHits(const Scene& s) {
  const Accel accel(s);
  Rng rng(7);
  int selfHits = 0, surfaces = 0;
  for (int i = 0; i < 4000; ++i) {
    const Vec3 o(0.5f + 0.4f * (rng.nextFloat() - 0.5f), -3, 0.4f * (rng.nextFloat() - 0.5f));
    const Hit h = cast(accel, o, {0, 1, 0});
    if (!h.valid()) continue;
    ++surfaces;
    Vec3 d;
    do d = Vec3(rng.nextFloat(), rng.nextFloat(), rng.nextFloat()) * 2.0f - 1.0f;
    while (glm::dot(d, d) > 1.0f || glm::dot(d, d) < 1e-4f);
    d = glm::normalize(d);
    if (glm::dot(d, h.ng) < 0.0f) d = -d;
    if (accel.intersect(Accel::spawnRay(h, d)).valid()) ++selfHits;
  }
  EXPECT_GT(surfaces, 3000);
  EXPECT_EQ(selfHits, 0);
}

TEST(Curve, SpawnedRaysDoNotFindTheirOwnTube) {
  TempDir dir;
  expectNoSelfHits(curveScene(dir, "linearcurve", kLinear));
  TempDir dir2;
  expectNoSelfHits(curveScene(dir2, "bsplinecurve", kBSpline));
}

TEST(Curve, BatchedQueriesAgreeWithSingleRays) {
  TempDir dir;
  const Scene s = curveScene(dir, "linearcurve", kLinear);
  const Accel accel(s);
  std::vector<Ray> rays(64);
  for (size_t i = 0; i < rays.size(); ++i) {
    rays[i].o = Vec3(-0.5f + 0.035f * i, -3, 0.01f * (float(i % 7) - 3));
    rays[i].d = Vec3(0, 1, 0);
  }
  for (BatchQuery q : {BatchQuery::Stream, BatchQuery::Packet16}) {
    std::vector<Hit> hits(rays.size());
    accel.intersectBatch(rays.data(), hits.data(), rays.size(), q);
    for (size_t i = 0; i < rays.size(); ++i) {
      const Hit one = accel.intersect(rays[i]);
      ASSERT_EQ(one.valid(), hits[i].valid()) << i;
      if (one.valid()) EXPECT_NEAR(one.t, hits[i].t, 1e-5f) << i;
    }
  }
}

}  // namespace
}  // namespace rc::test
