#pragma once
// Mitsuba 3's `cylinder` shape as Embree user geometry: ray tests in the unit cylinder's space (so
// any affine to_world is exact), the shading data of a hit, and world bounds.
#include <embree3/rtcore.h>

#include <vector>

#include "core/math.h"
#include "scene/scene.h"

namespace rc {

// Nearest t in [tMin, tMax] where the ray o + t·d meets the side of the cylinder (either the
// outside or, through an open end, the inside), false if none.
bool intersectCylinder(const Cylinder& c, const Vec3& o, const Vec3& d, float tMin, float tMax, float& t);

struct CylinderHitGeometry {
  Vec3 p{0.0f};     // on the surface (re-projected onto the unit cylinder)
  Vec3 n{0, 0, 1};  // unit, outward unless flipNormals
  Vec3 dpdu{0.0f};  // Mitsuba's: u = φ/2π around the axis, v = height in [0, 1]
  Vec3 dpdv{0.0f};
  Vec2 uv{0.0f};
};
CylinderHitGeometry cylinderHitGeometry(const Cylinder& c, const Vec3& worldPoint);

// World-space bounding box of the cylinder (its object box's eight corners, transformed).
void cylinderBounds(const Cylinder& c, Vec3& lo, Vec3& hi);

// One user geometry holding every cylinder of `cylinders` (which must outlive the scene), attached
// to `scene`; returns its geomID.
unsigned attachCylinders(RTCDevice device, RTCScene scene, const std::vector<Cylinder>& cylinders);

}  // namespace rc
