// Mitsuba's `sdfgrid` (src/shapes/sdfgrid.cpp): where its samples sit (the voxel corners of the
// unit cube), exact hits on the trilinear interpolant — a plane's distance is linear, so the
// interpolant reproduces it and every hit and normal must be the plane's —, rays along voxel
// faces and edges, a sphere's distance within the trilinear interpolation error, the smooth
// normal continuous across a voxel face where the analytic one jumps, and no self-hits.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <map>

#include "common/vol_file_bytes.h"
#include "core/rng.h"
#include "geometry/accel.h"
#include "render/ray_probe.h"
#include "scene/scene_test_util.h"

namespace rc::test {
namespace {

// One sdfgrid of nx·ny·nz samples of f at object points (i/(nx−1), j/(ny−1), k/(nz−1)).
Scene gridScene(TempDir& dir, int nx, int ny, int nz, const std::function<double(const glm::dvec3&)>& f,
                const std::string& params = "") {
  dir.write("g.vol", volGrid(nx, ny, nz, [&](int i, int j, int k) {
              return static_cast<float>(f(glm::dvec3(i / (nx - 1.0), j / (ny - 1.0), k / (nz - 1.0))));
            }));
  return loadText(dir, sceneXml("<shape type=\"sdfgrid\"><string name=\"filename\" value=\"g.vol\"/>" + params +
                                "<bsdf type=\"diffuse\"/></shape>"));
}

// The angle between two unit vectors (atan2: acos of a float dot product near 1 is 3e-4 off).
double angle(const Vec3& a, const Vec3& b) {
  const glm::dvec3 da(a), db(b);
  return std::atan2(glm::length(glm::cross(da, db)), glm::dot(da, db));
}

TEST(SdfGrid, SamplesSitOnTheVoxelCorners) {
  // Mitsuba maps the unit cube onto its texture so that texel centres land on (i/(n−1)): three
  // samples −1, −1, 1 along x sit at x = 0, ½, 1 and the zero is at x = ¾ (at texel centres
  // (i+½)/n it would be at ⅔). Two samples −¼, ¾: the zero at x = ¼ (centres: ⅜).
  for (const auto& [nx, zero] : {std::pair<int, double>{3, 0.75}, {2, 0.25}}) {
    TempDir dir;
    const Scene s = gridScene(dir, nx, 2, 2, [&](const glm::dvec3& p) {
      return nx == 3 ? (p.x > 0.75 ? 1.0 : -1.0) : p.x - 0.25;
    });
    ASSERT_EQ(s.sdfGrids.size(), 1u);
    const Accel accel(s);
    const Hit fromRight = cast(accel, {5, 0.3f, 0.6f}, {-1, 0, 0});
    ASSERT_TRUE(fromRight.valid()) << nx;
    EXPECT_NEAR(fromRight.t, 5.0 - zero, 1e-6) << nx;
    EXPECT_NEAR(glm::length(fromRight.ng - Vec3(1, 0, 0)), 0.0f, 1e-6f);  // the gradient: toward positive values
    const Hit fromLeft = cast(accel, {-5, 0.7f, 0.2f}, {1, 0, 0});  // from the negative side: the same surface
    ASSERT_TRUE(fromLeft.valid());
    EXPECT_NEAR(fromLeft.t, 5.0 + zero, 1e-6);
    EXPECT_FALSE(cast(accel, {5, 1.5f, 0.5f}, {-1, 0, 0}).valid());  // beside the cube: no surface
  }
}

// The plane n·p = c through the cube, n of unit length: its distance is linear, so the trilinear
// interpolant is exact and so are the hits and both normals (all voxel gradients are n).
const glm::dvec3 kPlaneN = glm::normalize(glm::dvec3(1, 2, 3));
const double kPlaneC = glm::dot(kPlaneN, glm::dvec3(0.5));
double planeDistance(const glm::dvec3& p) { return glm::dot(kPlaneN, p) - kPlaneC; }

TEST(SdfGrid, PlaneHitsAndNormalsAreExactUnderANonUniformToWorld) {
  for (const std::string normals : {"analytic", "smooth"}) {
    TempDir dir;
    const Scene s = gridScene(dir, 6, 5, 4, planeDistance,
                              "<string name=\"normals\" value=\"" + normals + "\"/><transform name=\"to_world\">"
                              "<scale value=\"2, 0.5, 3\"/><rotate x=\"1\" y=\"1\" angle=\"40\"/>"
                              "<translate value=\"1, -2, 0.5\"/></transform>");
    const Accel accel(s);
    const Mat4 toWorld = s.sdfGrids[0].toWorld;
    const glm::dmat4 toObject = glm::inverse(glm::dmat4(toWorld));
    const Vec3 worldN = glm::normalize(glm::transpose(glm::inverse(Mat3(toWorld))) * Vec3(kPlaneN));
    Rng rng(7);
    int hits = 0;
    for (int i = 0; i < 500; ++i) {
      // A point of the plane well inside the cube (away from the far faces, where Mitsuba's
      // smooth normal uses voxels past the grid), seen from a random point.
      const double x = 0.2 + 0.6 * rng.nextFloat(), y = 0.2 + 0.6 * rng.nextFloat();
      const double z = (kPlaneC - kPlaneN.x * x - kPlaneN.y * y) / kPlaneN.z;
      if (z < 0.2 || z > 0.8) continue;
      const Vec3 target = Vec3(toWorld * Vec4(Vec3(x, y, z), 1.0f));
      const Vec3 origin = target + 6.0f * Vec3(rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f) +
                          Vec3(0, 0, 4);
      const Hit h = cast(accel, origin, target - origin);
      ASSERT_TRUE(h.valid()) << normals << " ray " << i;
      ++hits;
      const glm::dvec3 local = glm::dvec3(toObject * glm::dvec4(glm::dvec3(h.p), 1.0));
      EXPECT_NEAR(planeDistance(local), 0.0, 2e-6) << normals;
      // Along the ray the point is as exact as float o + t·d (the cosine of grazing rays aside).
      EXPECT_NEAR(glm::length(h.p - target) * std::fabs(glm::dot(glm::normalize(target - origin), worldN)), 0.0f, 2e-5f)
          << normals;
      EXPECT_LT(angle(h.ng, worldN), 1e-5) << normals;
      EXPECT_LT(angle(h.ns, worldN), 1e-5) << normals;
      EXPECT_EQ(h.dpdu, Vec3(0.0f));  // Mitsuba's sdfgrid has no parameterisation
    }
    EXPECT_GT(hits, 200);
  }
}

TEST(SdfGrid, RaysAlongVoxelFacesAndEdgesHit) {
  // 5 samples per axis: voxel faces at multiples of ¼, exact in float. Rays down −z through every
  // voxel edge (x, y on the grid lines), and rays lying in a face plane (d.x = 0, x on a face).
  TempDir dir;
  const Scene s = gridScene(dir, 5, 5, 5, planeDistance);
  const Accel accel(s);
  for (int i = 0; i <= 4; ++i)
    for (int j = 0; j <= 4; ++j) {
      const double x = 0.25 * i, y = 0.25 * j, z = (kPlaneC - kPlaneN.x * x - kPlaneN.y * y) / kPlaneN.z;
      if (z < 0.0 || z > 1.0) continue;
      const Hit h = cast(accel, Vec3(x, y, 3), {0, 0, -1});
      ASSERT_TRUE(h.valid()) << x << ", " << y;
      EXPECT_NEAR(h.p.z, z, 1e-6) << x << ", " << y;
      const Hit inFace = cast(accel, Vec3(x, -2, 0.5), glm::normalize(Vec3(0, 1, 0.01f)));
      if (!inFace.valid()) continue;  // this face column may miss the plane inside the cube
      EXPECT_NEAR(planeDistance(glm::dvec3(inFace.p)), 0.0, 1e-6);
    }
  // Every face column that crosses the plane inside the cube is hit (checked by the sample
  // values: a sign change along the line).
  int inFaceHits = 0;
  for (int i = 0; i <= 4; ++i) inFaceHits += cast(accel, Vec3(0.25f * i, -2, 0.5f), glm::normalize(Vec3(0, 1, 0.01f))).valid();
  EXPECT_EQ(inFaceHits, 5);
}

TEST(SdfGrid, SpawnedRaysDoNotFindTheirOwnSurface) {
  TempDir dir;
  const Scene s = gridScene(dir, 7, 6, 5, planeDistance,
                            "<transform name=\"to_world\"><scale value=\"40, 10, 25\"/><rotate z=\"1\" angle=\"30\"/>"
                            "<translate value=\"100, 50, -20\"/></transform>");
  const Accel accel(s);
  const Mat4 toWorld = s.sdfGrids[0].toWorld;
  Rng rng(3);
  int surfaces = 0, selfHits = 0;
  for (int i = 0; i < 3000; ++i) {
    const Vec3 target = Vec3(toWorld * Vec4(Vec3(0.5f) + 0.4f * Vec3(rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f, 0), 1.0f));
    const Vec3 origin = Vec3(toWorld * Vec4(0.5f, 0.5f, 3.0f, 1.0f));
    const Hit h = cast(accel, origin, target - origin);
    if (!h.valid()) continue;
    ++surfaces;
    // Any direction, either side: the plane cannot be met again.
    const Vec3 d = glm::normalize(Vec3(rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f));
    if (accel.intersect(Accel::spawnRay(h, d)).valid()) ++selfHits;
    if (accel.occluded(Accel::spawnRay(h, d))) ++selfHits;
  }
  EXPECT_GT(surfaces, 2000);
  EXPECT_EQ(selfHits, 0);
}

// The distance to a sphere of radius 0.3 about the cube's centre, on 33³ samples (h = 1/32).
constexpr double kR = 0.3;
double sphereDistance(const glm::dvec3& p) { return glm::length(p - glm::dvec3(0.5)) - kR; }

TEST(SdfGrid, SphereWithinTheInterpolationErrorAndNoSelfHits) {
  TempDir dir;
  const Scene s = gridScene(dir, 33, 33, 33, sphereDistance, "<string name=\"normals\" value=\"analytic\"/>");
  const Accel accel(s);
  // Trilinear interpolation errs by at most h²/8 · (|f_xx| + |f_yy| + |f_zz|) = h²/8 · 2/ρ, ρ the
  // distance from the centre (≥ r − h√3 in a voxel the surface passes); |∇f| = 1, so the zero
  // set moves by at most that: 1.1e-3.
  const double h = 1.0 / 32, bound = h * h / 8.0 * 2.0 / (kR - h * std::sqrt(3.0));
  Rng rng(11);
  int hits = 0, selfHits = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vec3 d = glm::normalize(Vec3(rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f));
    const Vec3 origin = Vec3(0.5f) - 2.0f * d + 0.2f * Vec3(rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f, 0);
    const Hit hit = cast(accel, origin, d);
    ASSERT_TRUE(hit.valid()) << i;
    ++hits;
    EXPECT_LT(std::fabs(sphereDistance(glm::dvec3(hit.p))), bound) << i;
    // The gradient errs by O(h·|f''|) = O(h/r): well under 0.15 rad.
    EXPECT_LT(angle(hit.ng, glm::normalize(hit.p - Vec3(0.5f))), 0.15) << i;
    // Leaving within 60° of the normal, a ray cannot meet this nearly convex surface again.
    Vec3 out = glm::normalize(Vec3(rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f));
    out = glm::normalize(out + 1.5f * hit.ng);
    if (glm::dot(out, hit.ng) > 0.5f && accel.intersect(Accel::spawnRay(hit, out)).valid()) ++selfHits;
  }
  EXPECT_EQ(hits, 2000);
  EXPECT_EQ(selfHits, 0);
  // From the centre (inside, f < 0) every ray meets the surface at about r.
  const Hit inside = cast(accel, Vec3(0.5f), {0.3f, -0.2f, 0.9f});
  ASSERT_TRUE(inside.valid());
  EXPECT_NEAR(inside.t, kR, bound);
}

TEST(SdfGrid, SmoothNormalIsContinuousAcrossAVoxelFaceWhereTheAnalyticJumps) {
  // Two rays 2e-5 apart on either side of the voxel face x = 12/32, down −z onto the sphere's top.
  std::map<std::string, double> jump;
  for (const std::string normals : {"analytic", "smooth"}) {
    TempDir dir;
    const Scene s = gridScene(dir, 33, 33, 33, sphereDistance, "<string name=\"normals\" value=\"" + normals + "\"/>");
    const Accel accel(s);
    const float face = 12.0f / 32.0f;
    const Hit a = cast(accel, {face - 1e-5f, 0.53f, 2}, {0, 0, -1});
    const Hit b = cast(accel, {face + 1e-5f, 0.53f, 2}, {0, 0, -1});
    ASSERT_TRUE(a.valid() && b.valid());
    jump[normals] = angle(a.ns, b.ns);
  }
  // Analytic: ∂f/∂x jumps by about h·f_xx across the face (f_xx = (1 − n_x²)/ρ ≈ 3): ≈ 0.1 rad.
  EXPECT_GT(jump["analytic"], 0.02);
  // Smooth: continuous, so 2e-5 apart the normals differ by O(2e-5 · curvature).
  EXPECT_LT(jump["smooth"], 1e-3);
}

// Mitsuba 3.9.1's hits (bench/mitsuba_sdfgrid_values.py, llvm_ad_rgb) on the distance to a sphere of
// radius 0.3 about (0.45, 0.5, 0.55) sampled on 7×5×7 points — so coarse that the analytic normal
// is far from the sphere's and the smooth one differs from it by up to 0.5 rad —, placed by a
// non-uniform to_world, and inside a shapegroup by an instance that also turns it.
struct MitsubaHit {
  const char* normals;
  const char* placement;
  Vec3 o, d;
  float t;
  Vec3 n, ns;
};
const MitsubaHit kMitsubaHits[] = {
    {"analytic", "placed", {1.94, -1.48, 5.775}, {0, 0, -1}, 4.022663, {-0.07349889, 0.4949833, 0.8657882}, {-0.07349889, 0.4949833, 0.8657882}},
    {"analytic", "placed", {3.874308, -1.891436, 4.935771}, {-0.3685771, 0.122859, -0.9214426}, 3.983805, {0.7273738, 0.6747972, 0.1248037}, {0.7273738, 0.6747972, 0.1248037}},
    {"analytic", "placed", {-2.350918, -1.897546, 0.5823622}, {0.9877296, 0.04938648, 0.1481594}, 3.986746, {-0.4745159, -0.7584003, -0.4468372}, {-0.4745159, -0.7584003, -0.4468372}},
    {"analytic", "placed", {1.382302, 2.33849, 3.164821}, {0.1794245, -0.8971226, -0.4037052}, 4.035202, {0.3160423, 0.7486563, 0.5827788}, {0.3160423, 0.7486563, 0.5827788}},
    {"analytic", "instanced", {0.2770319, 1.460167, 5.7}, {0, 0, -1}, 4.030218, {-0.5216087, 0.657022, 0.5442853}, {-0.5216087, 0.657022, 0.5442853}},
    {"analytic", "instanced", {1.06823, 1.735047, 4.950918}, {-0.1530031, -0.03130978, -0.9877296}, 3.979856, {0.2945031, 0.9544883, 0.04711777}, {0.2945031, 0.9544883, 0.04711777}},
    {"analytic", "instanced", {-2.935322, -0.7356957, -0.5839645}, {0.7800324, 0.5038999, 0.3709911}, 3.992943, {-0.03487542, -0.9822883, -0.1841013}, {-0.03487542, -0.9822883, -0.1841013}},
    {"analytic", "instanced", {-1.421129, 3.545466, 4.448003}, {0.4274856, -0.4864266, -0.7620008}, 4.024866, {-0.1195809, 0.9582559, 0.2597038}, {-0.1195809, 0.9582559, 0.2597038}},
    {"smooth", "placed", {1.94, -1.48, 5.775}, {0, 0, -1}, 4.022663, {-0.07349889, 0.4949833, 0.8657882}, {0.03765209, 0.09359281, 0.9948983}},
    {"smooth", "placed", {3.874308, -1.891436, 4.935771}, {-0.3685771, 0.122859, -0.9214426}, 3.983805, {0.7273738, 0.6747972, 0.1248037}, {0.7835125, 0.606424, -0.1354917}},
    {"smooth", "placed", {-2.350918, -1.897546, 0.5823622}, {0.9877296, 0.04938648, 0.1481594}, 3.986746, {-0.4745159, -0.7584003, -0.4468372}, {-0.3530876, -0.8796155, -0.3187564}},
    {"smooth", "placed", {1.382302, 2.33849, 3.164821}, {0.1794245, -0.8971226, -0.4037052}, 4.035202, {0.3160423, 0.7486563, 0.5827788}, {0.2303035, 0.8926651, 0.3874394}},
    {"smooth", "instanced", {0.2770319, 1.460167, 5.7}, {0, 0, -1}, 4.030218, {-0.5216087, 0.657022, 0.5442853}, {-0.03671246, 0.258431, 0.9653319}},
    {"smooth", "instanced", {1.06823, 1.735047, 4.950918}, {-0.1530031, -0.03130978, -0.9877296}, 3.979856, {0.2945031, 0.9544883, 0.04711777}, {0.3783248, 0.924255, -0.05121537}},
    {"smooth", "instanced", {-2.935322, -0.7356957, -0.5839645}, {0.7800324, 0.5038999, 0.3709911}, 3.992943, {-0.03487542, -0.9822883, -0.1841013}, {0.1402898, -0.9821728, -0.125121}},
    {"smooth", "instanced", {-1.421129, 3.545466, 4.448003}, {0.4274856, -0.4864266, -0.7620008}, 4.024866, {-0.1195809, 0.9582559, 0.2597038}, {-0.2645359, 0.9517276, 0.1556773}},
};

TEST(SdfGrid, HitsAndNormalsMatchMitsuba) {
  for (const MitsubaHit& m : kMitsubaHits) {
    TempDir dir;
    dir.write("g.vol", volGrid(7, 5, 7, [](int i, int j, int k) {
                const double x = i / 6.0 - 0.45, y = j / 4.0 - 0.5, z = k / 6.0 - 0.55;
                return static_cast<float>(std::sqrt(x * x + y * y + z * z) - 0.3);
              }));
    const std::string grid = std::string("<shape type=\"sdfgrid\"><string name=\"filename\" value=\"g.vol\"/>") +
                             "<string name=\"normals\" value=\"" + m.normals + "\"/>";
    const std::string xml =
        std::string(m.placement) == "placed"
            ? grid + "<transform name=\"to_world\"><scale value=\"2, 1, 1.5\"/><translate value=\"1, -2, 0.5\"/></transform></shape>"
            : "<shape type=\"shapegroup\" id=\"g\">" + grid + "</shape></shape><shape type=\"instance\"><ref id=\"g\"/>"
              "<transform name=\"to_world\"><scale value=\"1, 0.5, 2\"/><rotate z=\"1\" angle=\"30\"/><translate y=\"1\"/></transform></shape>";
    const Scene s = loadText(dir, sceneXml(xml));
    const Accel accel(s);
    Ray r;
    r.o = m.o;
    r.d = m.d;
    const Hit h = accel.intersect(r);
    const std::string what = std::string(m.normals) + " " + m.placement + " t " + std::to_string(m.t);
    ASSERT_TRUE(h.valid()) << what;
    // Mitsuba stops its regula falsi at 1e-5 in t and evaluates in float.
    EXPECT_NEAR(h.t, m.t, 2e-5f) << what;
    // Normals move with the point at the interpolant's curvature (≈ 1/h ≈ 6 here): 6 · 2e-5, plus
    // float gradients; 3e-4 rad.
    EXPECT_LT(angle(h.ng, m.n), 3e-4) << what;
    EXPECT_LT(angle(h.ns, m.ns), 3e-4) << what;
  }
}

TEST(SdfGrid, BatchedQueriesAgreeWithSingleRays) {
  TempDir dir;
  const Scene s = gridScene(dir, 17, 17, 17, sphereDistance);
  const Accel accel(s);
  std::vector<Ray> rays(64);
  for (size_t i = 0; i < rays.size(); ++i) {
    rays[i].o = Vec3(0.1f + 0.0125f * i, -3, 0.5f + 0.01f * (float(i % 7) - 3));
    rays[i].d = Vec3(0, 1, 0);
  }
  for (BatchQuery q : {BatchQuery::Stream, BatchQuery::Packet16}) {
    std::vector<Hit> hits(rays.size());
    accel.intersectBatch(rays.data(), hits.data(), rays.size(), q);
    std::vector<uint8_t> blocked(rays.size());
    accel.occludedBatch(rays.data(), blocked.data(), rays.size(), q);
    for (size_t i = 0; i < rays.size(); ++i) {
      const Hit one = accel.intersect(rays[i]);
      ASSERT_EQ(one.valid(), hits[i].valid()) << i;
      EXPECT_EQ(one.valid(), blocked[i] != 0) << i;
      if (one.valid()) EXPECT_EQ(one.t, hits[i].t) << i;
    }
  }
}

}  // namespace
}  // namespace rc::test
