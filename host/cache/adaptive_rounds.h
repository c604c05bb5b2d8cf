#pragma once
// Phase 4 of an rcache render (docs/ARCHITECTURE.md §Pipeline), with --adaptive only: rounds over
// the rows that hold pixels needing more samples (render/adaptive_sampling.h chooses them). Should
// a round create records (a new sample position found no record even with the relaxed lookup),
// every band is shaded again with the final caches and the rounds start over, once.
#include <memory>

#include "cache/final_pass.h"
#include "render/film.h"

namespace rc {

// Returns the rounds' samples as one film of their own (null when adaptive sampling is off), to
// be added to the bands' film. Tiles are merged into it as they finish, so peak memory stays one
// film, not a tile per run of rows and round; it is dropped if the rounds start over.
std::unique_ptr<Film> runAdaptiveRounds(const RcacheRun& run, FinalPass& pass, AdaptivePixels& adaptive,
                                        const Film& film, bool& interrupted);

}  // namespace rc
