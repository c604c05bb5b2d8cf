#pragma once
// The Lambertian lobe of bsdf "diffuse" (bsdf/diffuse.cpp) as inline arithmetic on plain floats, the
// one definition that DiffuseBsdf and the wave's batched diffuse shading (render/diffuse_shading.h)
// share, so that both are the same estimator bit for bit.
#include "core/math.h"

namespace rc {

// cos θi / π where wo and wi both lie above the surface (one-sided, as Mitsuba 3), else 0: the
// lobe's eval is ρ times it, its pdf (the cosine-weighted hemisphere's density) is it.
// (Nested selects rather than &&: the batched pass's vector loop keeps them.)
inline float lambertCosineTerm(float woZ, float wiZ) { return woZ > 0.0f ? (wiZ > 0.0f ? kInvPi * wiZ : 0.0f) : 0.0f; }

}  // namespace rc
