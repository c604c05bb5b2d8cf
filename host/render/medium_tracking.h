#pragma once
// Free flights and transmittance through one participating medium (scene/medium.h) along a ray,
// with the estimators of Mitsuba 3's volpath (src/integrators/volpath.cpp, src/render/medium.cpp).
//
// Homogeneous: the distance is drawn in closed form for one colour channel chosen per flight and
// weighted by the mean density over the channels; transmittance is exp(−σt·d).
//
// Heterogeneous: delta tracking against the majorant inside the density's bounds. Each tentative
// collision is null with probability mean(σn)/majorant (σn = majorant − σt), weighted σn/(majorant·P_null),
// else real, weighted σs/mean(σt) (Mitsuba's spectral MIS for RGB; grey media get weight 1 for nulls
// and the albedo for real collisions). Shadow rays use ratio tracking: the product of σn/majorant
// over the tentative collisions (Mitsuba's equivalent). Where Mitsuba rolls Russian roulette at
// every null collision, these loops do not (the same expectation, less variance); and a ray
// leaving for good passes whatever lies beyond the bounds (Mitsuba's exp(−∞·majorant) gives 0).
#include "core/math.h"
#include "geometry/accel.h"
#include "core/rng.h"
#include "scene/medium.h"

namespace rc {

// A heterogeneous flight or shadow segment stops after this many tentative collisions, its
// weight 0. The loader keeps the expected count across the medium at most kMaxCollisionsAcross
// (Poisson, so its standard deviation is at most ~320): ten times that is never reached by a
// valid medium, and bounds the work whatever the numbers.
constexpr long kMaxCollisionsPerSegment = 10 * static_cast<long>(kMaxCollisionsAcross);

struct FreeFlight {
  bool scattered = false;  // a real collision at `p` before tEnd
  Vec3 p{0.0f};
  Color weight{1.0f};  // multiplies the path throughput (the albedo included where it scattered)
};

// One free flight from ray.o along ray.d through `medium`, up to the surface at tEnd (∞: none).
FreeFlight sampleFreeFlight(const Medium& medium, const Ray& ray, float tEnd, Rng& rng);

// The transmittance of `medium` between ray.tMin and tEnd (∞: the whole ray), an unbiased estimate
// where the medium is heterogeneous.
Color mediumTransmittance(const Medium& medium, const Ray& ray, float tEnd, Rng& rng);

}  // namespace rc
