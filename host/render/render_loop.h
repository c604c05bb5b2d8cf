#pragma once
// Tile scheduling over the image with rc::parallelFor. Each sample of pixel (x, y) gets its own RNG
// stream seeded by (seed, pixel index, sample index), and tiles are merged into the film in tile
// order, so an image depends only on the seed — not on the thread count or the scheduling.
// Honours ctx.cancel (tiles not yet started stay black) and reports progress through ctx.progress.
#include <cstdint>
#include <functional>
#include <string>

#include "core/rng.h"
#include "render/adaptive_sampling.h"
#include "render/film.h"
#include "render/integrator.h"

namespace rc {

struct RenderLoopSettings {
  int spp = 1;
  uint64_t seed = 0;
  bool lowDiscrepancy = false;  // pixel samples start with their padded Sobol dimensions
  std::function<Ray(const Vec2&)> cameraRay;  // set: trace camera rays in batches (SampleInput)
  AdaptiveSettings adaptive;  // off by default: every pixel takes spp samples
  int firstSample = 0;        // sample indices [firstSample, firstSample + spp) (progressive passes)
  int tileSize = 32;
  std::string phase = "render";  // progress label
};

struct RenderLoopResult {
  bool interrupted = false;
  uint64_t samples = 0;     // samples splatted
  uint64_t nanSamples = 0;  // non-finite samples dropped
  uint64_t adaptivePixels = 0;  // pixels that took more than spp samples
  int maxPixelSamples = 0;      // most samples any pixel took
};

// Per-sample work: radiance along the camera sample at filmPos (pixels, top-left origin) of pixel
// (px, py). `tile` lets the callback add AOVs for the pixel. Non-finite results are dropped
// (counted) by the loop, never splatted.
struct SampleInput {
  Vec2 filmPos;
  int px, py, sampleIndex;
  // With RenderLoopSettings::cameraRay: the sample's camera ray and its first hit, already traced
  // (a tile row's camera rays go to the BVH as one coherent stream). Null otherwise. The n inputs
  // one BatchFn call gets have theirs in consecutive elements: in[k].cameraRay == in[0].cameraRay + k.
  const Ray* cameraRay = nullptr;
  const Hit* cameraHit = nullptr;
};
using SampleFn = std::function<Color(const SampleInput& in, Rng& rng, TileFilm& tile)>;

RenderLoopResult renderSamples(const RenderContext& ctx, Film& film, const RenderLoopSettings& settings,
                               const SampleFn& fn);
// Per-row batched work (the path tracer's wavefront core): the radiance of n samples at once,
// out[k] for in[k] drawing from rngs[k]. With RenderLoopSettings::cameraRay set, every input
// carries its camera ray and hit. Same loop, seeds, splat order and NaN handling as renderSamples.
using BatchFn = std::function<void(const SampleInput* in, Rng* rngs, size_t n, Color* out)>;
RenderLoopResult renderSampleBatches(const RenderContext& ctx, Film& film, const RenderLoopSettings& settings,
                                     const BatchFn& fn);

// What the RNGs of one pixel's samples share: the pixel's index and low-discrepancy seed, hashed
// once per pixel rather than once per sample.
struct PixelRngSeed {
  uint64_t seed = 0, pixel = 0;
  uint32_t lowDiscrepancySeed = 0;
  bool lowDiscrepancy = false;
};
inline PixelRngSeed pixelRngSeed(uint64_t seed, int width, int px, int py, bool lowDiscrepancy = false) {
  PixelRngSeed p;
  p.seed = seed;
  p.pixel = static_cast<uint64_t>(py) * static_cast<uint64_t>(width) + static_cast<uint64_t>(px);
  p.lowDiscrepancy = lowDiscrepancy;
  if (lowDiscrepancy) p.lowDiscrepancySeed = static_cast<uint32_t>(hashMix(seed, p.pixel, 0x1D5A3B1E5ULL));
  return p;
}
// Sets `rng` (in place: no temporary to copy) to the stream of sample `sampleIndex` of the pixel.
// `dimensionSeeds` (optional): the pixel's ld::PixelDimensionSeeds(p.lowDiscrepancySeed), kept
// alive while the Rng draws its prefix, so that its draws read their seeds instead of hashing them.
inline void seedPixelRng(Rng& rng, const PixelRngSeed& p, int sampleIndex,
                         const ld::PixelDimensionSeeds* dimensionSeeds = nullptr) {
  // Everything hashed into the state: PCG streams that differ only in the increment are correlated.
  rng.seedWith(hashMix(p.seed, p.pixel, static_cast<uint64_t>(sampleIndex)), p.pixel);
  if (!p.lowDiscrepancy) return;
  if (dimensionSeeds) rng.useLowDiscrepancy(*dimensionSeeds, static_cast<uint32_t>(sampleIndex));
  else rng.useLowDiscrepancy(p.lowDiscrepancySeed, static_cast<uint32_t>(sampleIndex), Rng::kPixelLowDiscrepancyDims);
}

// The RNG of sample `sampleIndex` of pixel (px, py) of an image `width` wide; with lowDiscrepancy
// its first Rng::kPixelLowDiscrepancyDims draws are the pixel's padded Sobol points.
inline Rng pixelRng(uint64_t seed, int width, int px, int py, int sampleIndex, bool lowDiscrepancy = false) {
  Rng rng;
  seedPixelRng(rng, pixelRngSeed(seed, width, px, py, lowDiscrepancy), sampleIndex);
  return rng;
}

// Whether pixel samples use the low-discrepancy sampler: --sampler if given, else the scene's.
bool usesLowDiscrepancy(const RenderContext& ctx);

}  // namespace rc
