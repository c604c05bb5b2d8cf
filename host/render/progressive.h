#pragma once
// Progressive rendering under a wall-clock budget (`--time SECONDS`, both integrators): what an
// integrator does once (rcache: BRDF tables, pilot, cache fill — its share of the budget is
// whatever those phases take) runs first, then passes of spp samples per pixel (spp: --spp or the
// scene's sample_count) until the budget. Pass p draws the sample indices [p·spp, (p+1)·spp) of
// every pixel's streams, so the passes are disjoint samples of one render: N passes of the path
// tracer are the render of N·spp samples (equal up to the order of the film's double sums).
//
// The image is always the average of whole passes: a pass is started only if the last one's
// duration says it ends within the budget, and a pass the budget or SIGINT cuts anyway is dropped
// — except the first, which the budget never cuts (there is no image without it; with a fill or a
// first pass longer than the budget, the render takes longer than the budget) and which SIGINT
// leaves partial, as in a render without --time. The budget runs from the start of the render
// (after the scene is loaded and the BVH built).
#include "render/integrator.h"

namespace rc {

struct ProgressiveSettings {
  double seconds = 0.0;  // the budget, > 0
  int maxPasses = 0;     // stop after this many passes as well (0: only the budget; tests)
};

// Statistics added to the integrator's: time_budget_s, passes, pass_spp, spp (= passes × pass_spp),
// passes_dropped (a pass after the first cut by the budget or SIGINT, not in the image), time_passes_s (the passes alone, without the
// integrator's one-time work).
Image renderProgressive(Integrator& integrator, const RenderContext& ctx, const ProgressiveSettings& settings,
                        RenderStats& stats);

}  // namespace rc
