#pragma once
// The parameters every integrator shares with Mitsuba's path tracer, read once here:
//   max_depth      -1   longest path in segments (-1 unbounded; 1 = directly visible emission only)
//   rr_depth        5   segments before Russian roulette starts (≥ 1)
//   hide_emitters false camera rays pass area emitters to what lies behind, an escaping camera ray
//                       sees no environment (render/hidden_emitters.h)
#include "scene/param_reader.h"
#include "scene/scene.h"

namespace rc {

void readPathParams(ParamReader& in, IntegratorSettings& settings);

// Mitsuba's differentiable path tracers (`prb`, `prb_basic`, `prb_projective`, `direct_projective`,
// and `prbvolpath`, which follows media as `volpath` does) render the primal image of `path` /
// `volpath` (the same expectation; they differ in how they estimate
// derivatives, which rcache does not compute). Their base class reads max_depth with a default of 6
// (not −1), rr_depth and hide_emitters; the projective ones also take their gradient sampling
// settings (sppc, sppp, sppi, guiding, guiding_proj, guiding_rounds, project_seed), which change no
// primal pixel and are accepted and checked only. `direct_projective` is `prb_projective` at
// max_depth 2 whatever the file says (Mitsuba overrides it).
void readPrbParams(ParamReader& in, IntegratorSettings& settings);
void readProjectivePrbParams(ParamReader& in, IntegratorSettings& settings);
void readDirectProjectiveParams(ParamReader& in, IntegratorSettings& settings);

// Whether a path of `segments` segments is within max_depth (-1: always): the one test of the
// limit (a shade point at depth d gets direct light over d+1 segments, indirect over d+2).
inline bool withinMaxDepth(int maxDepth, int segments) { return maxDepth < 0 || segments <= maxDepth; }

}  // namespace rc
