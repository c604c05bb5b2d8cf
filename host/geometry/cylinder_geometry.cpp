#include "geometry/cylinder_geometry.h"

#include <algorithm>
#include <cmath>

#include "geometry/embree_attach.h"
#include "geometry/user_geometry_hit.h"

namespace rc {

bool intersectCylinder(const Cylinder& c, const Vec3& o, const Vec3& d, float tMin, float tMax, float& t) {
  // In object space t is unchanged (the direction is transformed, not normalised). Double: the
  // quadratic's cancellation near grazing rays would otherwise leave holes in the silhouette.
  const glm::dmat4 m(c.toObject);
  const glm::dvec3 lo = glm::dvec3(m * glm::dvec4(glm::dvec3(o), 1.0));
  const glm::dvec3 ld = glm::dvec3(m * glm::dvec4(glm::dvec3(d), 0.0));
  const double A = ld.x * ld.x + ld.y * ld.y;
  if (!(A > 0.0)) return false;  // parallel to the axis: the side is never crossed
  const double B = 2.0 * (lo.x * ld.x + lo.y * ld.y);
  const double C = lo.x * lo.x + lo.y * lo.y - 1.0;
  const double disc = B * B - 4.0 * A * C;
  if (!(disc >= 0.0)) return false;
  const double q = -0.5 * (B + std::copysign(std::sqrt(disc), B));
  double t0 = q / A, t1 = q != 0.0 ? C / q : t0;
  if (t0 > t1) std::swap(t0, t1);
  for (const double tc : {t0, t1}) {
    if (!(tc >= tMin && tc <= tMax)) continue;
    const double z = lo.z + tc * ld.z;
    if (z >= 0.0 && z <= 1.0) {
      t = static_cast<float>(tc);
      return true;
    }
  }
  return false;
}

CylinderHitGeometry cylinderHitGeometry(const Cylinder& c, const Vec3& worldPoint) {
  CylinderHitGeometry g;
  Vec3 local = Vec3(c.toObject * Vec4(worldPoint, 1.0f));
  const float r = std::sqrt(local.x * local.x + local.y * local.y);
  if (r > 0.0f) local.x /= r, local.y /= r;
  else local.x = 1.0f, local.y = 0.0f;
  local.z = glm::clamp(local.z, 0.0f, 1.0f);
  g.p = Vec3(c.toWorld * Vec4(local, 1.0f));
  const Mat3 linear(c.toWorld);
  g.dpdu = linear * (2.0f * kPi * Vec3(-local.y, local.x, 0.0f));
  g.dpdv = linear * Vec3(0.0f, 0.0f, 1.0f);
  // Mitsuba's normal, cross(dp/du, dp/dv): outward for a proper to_world; a mirroring one turns it
  // inward, which the loader compensates through flipNormals as Mitsuba does.
  g.n = glm::normalize(glm::cross(g.dpdu, g.dpdv));
  if (c.flipNormals) g.n = -g.n;
  float phi = std::atan2(local.y, local.x);
  if (phi < 0.0f) phi += 2.0f * kPi;
  g.uv = Vec2(phi / (2.0f * kPi), local.z);
  return g;
}

void cylinderBounds(const Cylinder& c, Vec3& lo, Vec3& hi) {
  lo = Vec3(INFINITY);
  hi = Vec3(-INFINITY);
  for (int k = 0; k < 8; ++k) {
    const Vec3 corner(k & 1 ? 1.0f : -1.0f, k & 2 ? 1.0f : -1.0f, k & 4 ? 1.0f : 0.0f);
    const Vec3 p = Vec3(c.toWorld * Vec4(corner, 1.0f));
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
}

namespace {

// Embree's user pointer is the scene's cylinder list itself.
const std::vector<Cylinder>& cylindersOf(void* user) { return *static_cast<const std::vector<Cylinder>*>(user); }

void boundsCallback(const RTCBoundsFunctionArguments* args) {
  Vec3 lo, hi;
  cylinderBounds(cylindersOf(args->geometryUserPtr)[args->primID], lo, hi);
  // Pad by a relative margin so the float surface is always inside the box.
  const Vec3 pad = 1e-5f * (glm::abs(lo) + glm::abs(hi) + (hi - lo));
  RTCBounds* b = args->bounds_o;
  b->lower_x = lo.x - pad.x; b->lower_y = lo.y - pad.y; b->lower_z = lo.z - pad.z;
  b->upper_x = hi.x + pad.x; b->upper_y = hi.y + pad.y; b->upper_z = hi.z + pad.z;
}

bool hitOfLane(const Cylinder& c, RTCRayN* ray, unsigned N, unsigned i, float& t) {
  const Vec3 o(RTCRayN_org_x(ray, N, i), RTCRayN_org_y(ray, N, i), RTCRayN_org_z(ray, N, i));
  const Vec3 d(RTCRayN_dir_x(ray, N, i), RTCRayN_dir_y(ray, N, i), RTCRayN_dir_z(ray, N, i));
  return intersectCylinder(c, o, d, RTCRayN_tnear(ray, N, i), RTCRayN_tfar(ray, N, i), t);
}

// The Hit is rebuilt from the point (cylinderHitGeometry).
void intersectCallback(const RTCIntersectFunctionNArguments* args) {
  const Cylinder& c = cylindersOf(args->geometryUserPtr)[args->primID];
  intersectLanes(args, [&](RTCRayN* ray, unsigned N, unsigned i, float& t) { return hitOfLane(c, ray, N, i, t); });
}

void occludedCallback(const RTCOccludedFunctionNArguments* args) {
  const Cylinder& c = cylindersOf(args->geometryUserPtr)[args->primID];
  occludeLanes(args, [&](RTCRayN* ray, unsigned N, unsigned i, float& t) { return hitOfLane(c, ray, N, i, t); });
}

}  // namespace

unsigned attachCylinders(RTCDevice device, RTCScene scene, const std::vector<Cylinder>& cylinders) {
  RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
  rtcSetGeometryUserPrimitiveCount(g, static_cast<unsigned>(cylinders.size()));
  rtcSetGeometryUserData(g, const_cast<std::vector<Cylinder>*>(&cylinders));
  rtcSetGeometryBoundsFunction(g, &boundsCallback, nullptr);
  rtcSetGeometryIntersectFunction(g, &intersectCallback);
  rtcSetGeometryOccludedFunction(g, &occludedCallback);
  return commitAndAttach(scene, g);
}

}  // namespace rc
