#pragma once
// One definition of how an Embree user-geometry callback (spheres, cylinders, sdfgrids) records a
// hit of lane i: the ray's tfar, the geometric normal Embree hands back, no barycentrics, and the
// ids; and the lane loops of the callbacks whose Hit is rebuilt later from the point alone.
#include <embree3/rtcore.h>

#include "core/math.h"

namespace rc {

inline void recordUserHit(const RTCIntersectFunctionNArguments* args, RTCRayN* ray, RTCHitN* hit, unsigned i, float t,
                          const Vec3& ng) {
  const unsigned N = args->N;
  RTCRayN_tfar(ray, N, i) = t;
  RTCHitN_Ng_x(hit, N, i) = ng.x;
  RTCHitN_Ng_y(hit, N, i) = ng.y;
  RTCHitN_Ng_z(hit, N, i) = ng.z;
  RTCHitN_u(hit, N, i) = 0.0f;
  RTCHitN_v(hit, N, i) = 0.0f;
  RTCHitN_primID(hit, N, i) = args->primID;
  RTCHitN_geomID(hit, N, i) = args->geomID;
  RTCHitN_instID(hit, N, i, 0) = args->context->instID[0];
}

// The intersect callback's loop: lane i (if valid) is hit where laneHit(ray, N, i, t) finds t in
// the ray's [tnear, tfar]; the normal handed to Embree is a placeholder (Accel rebuilds the Hit).
template <class LaneHit>
void intersectLanes(const RTCIntersectFunctionNArguments* args, const LaneHit& laneHit) {
  const unsigned N = args->N;
  RTCRayN* ray = RTCRayHitN_RayN(args->rayhit, N);
  RTCHitN* hit = RTCRayHitN_HitN(args->rayhit, N);
  for (unsigned i = 0; i < N; ++i) {
    if (args->valid[i] != -1) continue;
    float t;
    if (laneHit(ray, N, i, t)) recordUserHit(args, ray, hit, i, t, Vec3(0.0f, 0.0f, 1.0f));
  }
}

// The occluded callback's loop: Embree marks a blocked lane by tfar = −∞.
template <class LaneHit>
void occludeLanes(const RTCOccludedFunctionNArguments* args, const LaneHit& laneHit) {
  const unsigned N = args->N;
  for (unsigned i = 0; i < N; ++i) {
    if (args->valid[i] != -1) continue;
    float t;
    if (laneHit(args->ray, N, i, t)) RTCRayN_tfar(args->ray, N, i) = -INFINITY;
  }
}

}  // namespace rc
