#pragma once
// One definition of how an Embree user-geometry callback (spheres, cylinders) records a hit of
// lane i: the ray's tfar, the geometric normal Embree hands back, no barycentrics, and the ids.
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

}  // namespace rc
