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

// Whether a path of `segments` segments is within max_depth (-1: always): the one test of the
// limit (a shade point at depth d gets direct light over d+1 segments, indirect over d+2).
inline bool withinMaxDepth(int maxDepth, int segments) { return maxDepth < 0 || segments <= maxDepth; }

}  // namespace rc
