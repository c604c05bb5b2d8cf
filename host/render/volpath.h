#pragma once
// Volumetric path tracing with Mitsuba 3 `volpath` semantics (src/integrators/volpath.cpp), for
// scenes whose shapes or sensor hold participating media (scene/medium.h). The path integrator
// renders such scenes with this scalar estimator instead of its wavefront core where the
// integrator follows media (followsMedia; its statistics say so: `path_core`); scenes without
// media never reach it.
//
// Per path, as Mitsuba: Russian roulette at the top of every vertex once depth > rr_depth
// (q = min(max β · η², 0.95)); depth counts medium scattering and non-null surface scattering,
// and the path stops at depth = max_depth (−1 unbounded). In a medium a free-flight distance is
// drawn against the nearest surface: scattering there is weighted by the albedo and continues by
// the phase function, with next-event estimation only where the medium's `sample_emitters` is set
// (emission found afterwards then counts whole, as after a delta lobe); passing it, the path meets
// the surface. A surface with interior/exterior media switches the path's medium by the side the
// ray leaves through (the geometric normal: exterior on its side). Shadow rays carry
// transmittance through each medium they cross and a null surface's pass-through share
// (Bsdf::nullTransmission); any other surface blocks them. Free flights and transmittance in one
// medium, homogeneous (closed form) or heterogeneous (delta and ratio tracking against the
// majorant): render/medium_tracking.h.
#include <string>

#include "core/rng.h"
#include "geometry/accel.h"
#include "render/integrator.h"

namespace rc {

// True when a shape or the sensor refers to a medium (unreferenced <medium>s change nothing).
bool sceneUsesMedia(const Scene& scene);

// Whether a render with `integrator` follows the scene's media: Mitsuba's volpath and volpathmis
// do; its path and direct render surfaces only (a medium's null boundary is then just invisible).
// rcache renders what the file's integrator would (Scene::integrator.type).
bool followsMedia(const Scene& scene, const std::string& integrator);

// Radiance along one camera ray (one path sample).
Color volPathRadiance(const RenderContext& ctx, const IntegratorSettings& settings, const Ray& cameraRay, Rng& rng);

// Transmittance from ray.o to ray.tMax (∞: until nothing more is hit) through the media and null
// surfaces on the way, starting in `medium` (−1: none); heterogeneous media estimate it with
// numbers from `rng`.
Color shadowTransmittance(const RenderContext& ctx, Ray ray, int medium, Rng& rng);

}  // namespace rc
