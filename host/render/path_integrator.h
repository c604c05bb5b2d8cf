#pragma once
// Unidirectional path tracer with Mitsuba 3 `path` semantics: max_depth (−1 unbounded, 1 = directly
// visible emission only), Russian roulette after rr_depth on the throughput, hide_emitters, BSDF and
// light sampling combined by MIS. The ground truth every cached render must converge to.
#include <memory>
#include <string>

#include "core/rng.h"
#include "render/integrator.h"

namespace rc {

// The per-sample core that renders: the batched wavefront core (render/path_wavefront.h), or the
// scalar pathRadiance it is tested against; `query` is how the wavefront core's rays go to Embree.
enum class PathCore { Wavefront, Scalar };
std::unique_ptr<Integrator> makePathIntegrator(const IntegratorSettings& settings, PathCore core = PathCore::Wavefront,
                                               BatchQuery query = BatchQuery::Packet16);

// Radiance along one camera ray from one sample's random numbers (pathRadiance's signature).
using SampleEstimator = Color (*)(const RenderContext& ctx, const IntegratorSettings& settings, const Ray& ray,
                                  Rng& rng, const Hit* cameraHit);
// An integrator named `name` that renders `estimator` per sample through the path tracer's passes
// (its sample loop, seeds and statistics): Mitsuba's `direct` (render/direct_integrator.h).
std::unique_ptr<Integrator> makeEstimatorIntegrator(const std::string& name, const IntegratorSettings& settings,
                                                    SampleEstimator estimator);

}  // namespace rc

namespace rc {
// Radiance along one camera ray (one path sample); the integrator's per-sample work, exposed for
// integrators that fall back to path tracing (e.g. behind delta lobes) and for tests.
// cameraHit (optional): the camera ray's hit, already traced (batched camera rays).
Color pathRadiance(const RenderContext& ctx, const IntegratorSettings& settings, const Ray& ray, Rng& rng,
                   const Hit* cameraHit = nullptr);
}  // namespace rc
