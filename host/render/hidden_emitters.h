#pragma once
// hide_emitters on camera rays, as Mitsuba 3 defines it (Integrator::skip_area_emitters, used by its
// path, direct and volpath): a camera ray that meets an area emitter passes through it, and through
// every area emitter after it, and the path starts at whatever lies behind. The emitters are hidden
// from the camera only: they still light the scene and still block shadow rays and later segments.
// (An environment is hidden by leaving out the emission of a camera ray that escapes; that is the
// integrators' own business.)
#include "geometry/accel.h"
#include "render/integrator.h"

namespace rc {

// True when `hit` lies on a shape that carries an area emitter.
bool onAreaEmitter(const Scene& scene, const Hit& hit);

// The first hit along the camera ray's direction that is not on an area emitter, starting from the
// ray's own first hit `hit` (returned unchanged when it is not on one). Its t is the distance along
// the camera ray, as if the emitters were not there.
Hit behindAreaEmitters(const RenderContext& ctx, const Ray& cameraRay, const Hit& hit);

}  // namespace rc
