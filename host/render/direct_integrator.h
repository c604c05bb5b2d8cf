#pragma once
// Mitsuba 3's `direct` integrator (src/integrators/direct.cpp): the emission seen by the camera
// ray, then at its first hit `emitter_samples` light samples and `bsdf_samples` BSDF samples, each
// technique's samples averaged and the two combined by the multi-sample power heuristic (weights
// from n_e·pdf_light against n_b·pdf_bsdf); no indirect light. Either count may be 0 (not both):
// the other technique then carries weight 1 — with bsdf_samples 0 a mirror shows nothing, with
// emitter_samples 0 a point light lights nothing. With one of each it is the path tracer cut at
// two segments, sample for sample.
//
//   shading_samples  1  sets both counts (not together with either of them)
//   emitter_samples  1  light samples per pixel sample (≥ 0)
//   bsdf_samples     1  BSDF samples per pixel sample (≥ 0)
//   hide_emitters false camera rays pass area emitters to what lies behind, an escaping camera ray
//                       sees no environment (render/hidden_emitters.h)
//
// One difference from Mitsuba 3.9.1, kept on purpose: Mitsuba weights a sample of a delta light
// (point, spot, directional) 1 instead of 1/emitter_samples, so its direct image of such a light
// is emitter_samples times too bright (bench/RESULTS.md, hello.xml); here every technique's
// samples are averaged.
#include <memory>

#include "core/rng.h"
#include "render/integrator.h"
#include "scene/param_reader.h"

namespace rc {

// Reads the parameters above into settings (emitterSamples, bsdfSamples, hideEmitters; maxDepth 2).
void readDirectParams(ParamReader& in, IntegratorSettings& settings);
std::unique_ptr<Integrator> makeDirectIntegrator(const IntegratorSettings& settings);

// Radiance along one camera ray: the estimator above (consumes 3·(emitterSamples + bsdfSamples)
// numbers after the camera ray's).
Color directRadiance(const RenderContext& ctx, const IntegratorSettings& settings, const Ray& ray, Rng& rng,
                     const Hit* cameraHit = nullptr);

}  // namespace rc
