#include "geometry/sdf_grid_geometry.h"

#include "geometry/embree_attach.h"
#include "geometry/sdf_grid_math.h"
#include "geometry/user_geometry_hit.h"

namespace rc {

namespace {

// The world box of the object-space box [lo, hi] (its eight corners).
void worldBox(const Mat4& toWorld, const Vec3& objLo, const Vec3& objHi, Vec3& lo, Vec3& hi) {
  lo = Vec3(INFINITY);
  hi = Vec3(-INFINITY);
  for (int k = 0; k < 8; ++k) {
    const Vec3 corner(k & 1 ? objHi.x : objLo.x, k & 2 ? objHi.y : objLo.y, k & 4 ? objHi.z : objLo.z);
    const Vec3 p = Vec3(toWorld * Vec4(corner, 1.0f));
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
}

const SdfGrid& gridOf(void* user) { return *static_cast<const SdfGrid*>(user); }

void boundsCallback(const RTCBoundsFunctionArguments* args) {
  const SdfGrid& grid = gridOf(args->geometryUserPtr);
  const glm::ivec3 v = sdfVoxelCoords(grid, (*grid.voxels)[args->primID]);
  const Vec3 size(1.0f / (grid.res[0] - 1), 1.0f / (grid.res[1] - 1), 1.0f / (grid.res[2] - 1));
  Vec3 lo, hi;
  worldBox(grid.toWorld, Vec3(v) * size, Vec3(v + 1) * size, lo, hi);
  // Pad by a relative margin so that the float box holds the exact voxel (rays at its faces).
  const Vec3 pad = 1e-5f * (glm::abs(lo) + glm::abs(hi) + (hi - lo));
  RTCBounds* b = args->bounds_o;
  b->lower_x = lo.x - pad.x; b->lower_y = lo.y - pad.y; b->lower_z = lo.z - pad.z;
  b->upper_x = hi.x + pad.x; b->upper_y = hi.y + pad.y; b->upper_z = hi.z + pad.z;
}

bool hitOfLane(const SdfGrid& grid, unsigned prim, RTCRayN* ray, unsigned N, unsigned i, float& t) {
  // In object space t is unchanged (the direction is transformed, not normalised).
  const glm::dmat4 m(grid.toObject);
  const glm::dvec3 o(RTCRayN_org_x(ray, N, i), RTCRayN_org_y(ray, N, i), RTCRayN_org_z(ray, N, i));
  const glm::dvec3 d(RTCRayN_dir_x(ray, N, i), RTCRayN_dir_y(ray, N, i), RTCRayN_dir_z(ray, N, i));
  double tHit;
  if (!intersectSdfVoxel(grid, sdfVoxelCoords(grid, (*grid.voxels)[prim]), glm::dvec3(m * glm::dvec4(o, 1.0)),
                         glm::dvec3(m * glm::dvec4(d, 0.0)), RTCRayN_tnear(ray, N, i), RTCRayN_tfar(ray, N, i), tHit))
    return false;
  t = static_cast<float>(tHit);
  // Rounding to float must not leave the ray's interval.
  return t >= RTCRayN_tnear(ray, N, i) && t <= RTCRayN_tfar(ray, N, i);
}

// The Hit is rebuilt from the point (sdfHitGeometry).
void intersectCallback(const RTCIntersectFunctionNArguments* args) {
  const SdfGrid& grid = gridOf(args->geometryUserPtr);
  intersectLanes(args, [&](RTCRayN* ray, unsigned N, unsigned i, float& t) { return hitOfLane(grid, args->primID, ray, N, i, t); });
}

void occludedCallback(const RTCOccludedFunctionNArguments* args) {
  const SdfGrid& grid = gridOf(args->geometryUserPtr);
  occludeLanes(args, [&](RTCRayN* ray, unsigned N, unsigned i, float& t) { return hitOfLane(grid, args->primID, ray, N, i, t); });
}

}  // namespace

void sdfGridBounds(const SdfGrid& grid, Vec3& lo, Vec3& hi) { worldBox(grid.toWorld, Vec3(0.0f), Vec3(1.0f), lo, hi); }

unsigned attachSdfGrid(RTCDevice device, RTCScene scene, const SdfGrid& grid) {
  RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
  rtcSetGeometryUserPrimitiveCount(g, static_cast<unsigned>(grid.voxels->size()));
  rtcSetGeometryUserData(g, const_cast<SdfGrid*>(&grid));
  rtcSetGeometryBoundsFunction(g, &boundsCallback, nullptr);
  rtcSetGeometryIntersectFunction(g, &intersectCallback);
  rtcSetGeometryOccludedFunction(g, &occludedCallback);
  return commitAndAttach(scene, g);
}

}  // namespace rc
