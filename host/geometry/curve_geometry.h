#pragma once
// Mitsuba 3's `linearcurve` and `bsplinecurve` as Embree 3 round curves
// (RTC_GEOMETRY_TYPE_ROUND_LINEAR_CURVE / ROUND_BSPLINE_CURVE, the geometry Mitsuba's scalar
// variants build): the BVH geometry and the shading data of a hit, as Mitsuba computes them from
// Embree's segment and curve parameter (src/shapes/linearcurve.cpp, bsplinecurve.cpp).
#include <embree3/rtcore.h>

#include "core/math.h"
#include "scene/scene.h"

namespace rc {

struct CurveHitGeometry {
  Vec3 n{0, 0, 1};   // unit, away from the axis
  Vec3 dpdu{0.0f};   // B-spline only (zero on a linear curve, as in Mitsuba 3.9.1)
  Vec3 dpdv{0.0f};
  Vec2 uv{0.0f};     // u: angle around the axis / 2π from Mitsuba's guide frame (world z up);
                     // v: along all segments of the shape, (segment + local v) / segment count
};
// The hit at world point p on `segment` of c, at Embree's curve parameter vLocal (its hit.u).
CurveHitGeometry curveHitGeometry(const Curve& c, unsigned segment, float vLocal, const Vec3& p);

// World-space bounds of c: its control points padded by their radii (a B-spline lies in the
// convex hull of its control points, so this holds the tube).
void curveBounds(const Curve& c, Vec3& lo, Vec3& hi);

// One Embree geometry holding every segment of c, attached to `scene`; returns its geomID.
unsigned attachCurve(RTCDevice device, RTCScene scene, const Curve& c);

}  // namespace rc
