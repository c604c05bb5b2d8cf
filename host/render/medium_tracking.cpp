// Free flights and transmittance in one medium (render/medium_tracking.h).
#include "render/medium_tracking.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rc {

namespace {

float mean(const Color& c) { return (c.r + c.g + c.b) / 3.0f; }

// exp(−σt·d) per channel; a channel without extinction passes whole, also over an infinite distance.
Color beerLambert(const Color& sigmaT, float distance) {
  Color tr;
  for (int c = 0; c < 3; ++c) tr[c] = sigmaT[c] > 0.0f ? std::exp(-sigmaT[c] * distance) : 1.0f;
  return tr;
}

// The part [enter, exit] of the ray's [tMin, tEnd] inside the box; enter ≥ exit where it misses.
struct Span {
  float enter, exit;
};

Span clipToBox(const Bounds3& box, const Ray& ray, float tEnd) {
  Span s{ray.tMin, tEnd};
  for (int a = 0; a < 3; ++a) {
    if (ray.d[a] == 0.0f) {
      // Parallel to the slab: inside it for the whole ray or never.
      if (!(ray.o[a] >= box.lo[a] && ray.o[a] <= box.hi[a])) return {0.0f, 0.0f};
      continue;
    }
    const float inv = 1.0f / ray.d[a];
    const float t0 = (box.lo[a] - ray.o[a]) * inv, t1 = (box.hi[a] - ray.o[a]) * inv;
    s.enter = std::max(s.enter, std::min(t0, t1));
    s.exit = std::min(s.exit, std::max(t0, t1));
  }
  if (!(s.enter < s.exit)) return {0.0f, 0.0f};
  return s;
}

// The tentative collisions of a heterogeneous medium along its part of the ray, at exponential
// steps of mean 1/majorant, handed to `visit(p, σt, σn)` until it returns false. Distances count from
// the box entry in double, so that steps far smaller than the ray's distance to the box still
// advance. Returns whether the segment ended (false: `visit` stopped it, or the collision cap).
template <typename Visit>
bool trackCollisions(const Medium& m, const Ray& ray, float tEnd, Rng& rng, Visit&& visit) {
  if (!(m.majorant > 0.0f)) return true;
  const Span span = clipToBox(m.density->bounds(), ray, tEnd);
  if (!(span.enter < span.exit)) return true;
  const Vec3 entry = ray.o + span.enter * ray.d;
  const double length = double(span.exit) - double(span.enter);
  double s = 0.0;
  for (long n = 0; n < kMaxCollisionsPerSegment; ++n) {
    s -= std::log1p(-double(rng.nextFloat())) / double(m.majorant);
    if (!(s < length)) return true;
    const Vec3 p = entry + static_cast<float>(s) * ray.d;
    // σn = majorant − σt ≥ 0 but for the rounding of an interpolated σt at the grid's maximum.
    const Color sigmaT = m.extinctionAt(p);
    if (!visit(p, sigmaT, glm::max(Color(m.majorant) - sigmaT, Color(0.0f)))) return false;
  }
  return false;
}

FreeFlight homogeneousFlight(const Medium& m, const Ray& ray, float tEnd, Rng& rng) {
  // One channel's density per flight, weighted by the mean over the channels (render/volpath.h).
  const float uChannel = rng.nextFloat(), uDistance = rng.nextFloat();
  const float sigma = m.sigmaT[std::min(static_cast<int>(uChannel * 3.0f), 2)];
  const float t = sigma > 0.0f ? -std::log1p(-uDistance) / sigma : std::numeric_limits<float>::infinity();
  FreeFlight f;
  if (t < tEnd) {
    f.scattered = true;
    f.p = ray.o + t * ray.d;
    const Color tr = beerLambert(m.sigmaT, t);
    f.weight = m.sigmaT * m.albedo->eval(f.p) * tr / mean(m.sigmaT * tr);
    return f;
  }
  // The flight passed the surface (or left for good through a channel without extinction).
  const Color tr = beerLambert(m.sigmaT, tEnd);
  const float pass = mean(tr);
  f.weight = pass > 0.0f ? tr / pass : Color(0.0f);
  return f;
}

FreeFlight heterogeneousFlight(const Medium& m, const Ray& ray, float tEnd, Rng& rng) {
  FreeFlight f;
  const bool ended = trackCollisions(m, ray, tEnd, rng, [&](const Vec3& p, const Color& sigmaT, const Color& sigmaN) {
    const float pNull = mean(sigmaN) / m.majorant;
    if (rng.nextFloat() < pNull) {
      f.weight *= sigmaN / (m.majorant * pNull);
      return true;
    }
    // pNull < 1 here, so mean(σt) > 0.
    f.scattered = true;
    f.p = p;
    f.weight *= sigmaT * m.albedo->eval(p) / mean(sigmaT);
    return false;
  });
  if (!ended && !f.scattered) f.weight = Color(0.0f);  // the collision cap
  return f;
}

}  // namespace

FreeFlight sampleFreeFlight(const Medium& medium, const Ray& ray, float tEnd, Rng& rng) {
  return medium.homogeneous ? homogeneousFlight(medium, ray, tEnd, rng) : heterogeneousFlight(medium, ray, tEnd, rng);
}

Color mediumTransmittance(const Medium& medium, const Ray& ray, float tEnd, Rng& rng) {
  if (medium.homogeneous) return beerLambert(medium.sigmaT, tEnd - ray.tMin);
  Color tr(1.0f);
  const bool ended = trackCollisions(medium, ray, tEnd, rng, [&](const Vec3&, const Color&, const Color& sigmaN) {
    tr *= sigmaN / medium.majorant;
    return maxComponent(tr) > 0.0f;  // all channels blocked: nothing more to estimate
  });
  return ended ? tr : Color(0.0f);
}

}  // namespace rc
