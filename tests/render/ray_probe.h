#pragma once
// Single rays against an Accel for the analytic-shape tests (cylinders, curves).
#include <gtest/gtest.h>

#include "geometry/accel.h"

namespace rc::test {

// The closest hit of the ray from o along d (normalised).
inline Hit cast(const Accel& accel, Vec3 o, Vec3 d) {
  Ray r;
  r.o = o;
  r.d = glm::normalize(d);
  return accel.intersect(r);
}

// A shadow ray from o along the unit d is clear up to tClear and blocked by tBlocked.
inline void expectBlockedBetween(const Accel& accel, Vec3 o, Vec3 d, float tClear, float tBlocked) {
  Ray shadow;
  shadow.o = o;
  shadow.d = d;
  shadow.tMax = tClear;
  EXPECT_FALSE(accel.occluded(shadow));
  shadow.tMax = tBlocked;
  EXPECT_TRUE(accel.occluded(shadow));
}

}  // namespace rc::test
