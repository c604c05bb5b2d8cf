#pragma once
// The radiance-caching integrator (`--integrator rcache`, DESIGN §1–§3): direct light exact (the
// path tracer's NEE with MIS), indirect light on diffuse/glossy surfaces interpolated from a cache
// of incoming-radiance records (SH coefficients + translational gradients), filled coarse-to-fine
// over the image in batches; sharp/delta materials importance-sampled into the caches.
// Parameters (IntegratorSettings::params, also settable with -D name=value) are listed in
// cache/cache_params.h.
#include <memory>

#include "render/integrator.h"
#include "scene/scene.h"

namespace rc {

// Throws rc::Error naming the parameter when a parameter value is invalid.
std::unique_ptr<Integrator> makeRcacheIntegrator(const IntegratorSettings& settings);

}  // namespace rc
