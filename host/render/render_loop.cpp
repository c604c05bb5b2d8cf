#include "render/render_loop.h"

#include <algorithm>
#include <atomic>
#include <memory>
#include <mutex>

#include "core/parallel.h"

namespace rc {

namespace {

struct TileRect {
  int x0, y0, x1, y1;
};

std::vector<TileRect> makeTiles(int width, int height, int size) {
  std::vector<TileRect> tiles;
  for (int y = 0; y < height; y += size)
    for (int x = 0; x < width; x += size) tiles.push_back({x, y, std::min(width, x + size), std::min(height, y + size)});
  return tiles;
}

// Per-tile work: the callback renders the whole tile itself, splatting into `tile`.
using TileFn = std::function<void(TileFilm& tile)>;

RenderLoopResult renderTiles(const RenderContext& ctx, Film& film, const RenderLoopSettings& settings,
                             const TileFn& fn) {
  const int size = std::max(1, settings.tileSize);
  const std::vector<TileRect> rects = makeTiles(film.width(), film.height(), size);
  // Tiles are kept until all are done and merged in index order: float sums then do not depend on
  // the order in which threads finished.
  std::vector<std::unique_ptr<TileFilm>> done(rects.size());
  std::mutex progressMutex;
  size_t finished = 0;
  std::atomic<bool> interrupted{false};
  if (ctx.progress) ctx.progress(settings.phase, 0.0, static_cast<double>(rects.size()));

  parallelFor(rects.size(), 1, [&](size_t begin, size_t end) {
    for (size_t t = begin; t < end; ++t) {
      if (ctx.cancel && ctx.cancel->load(std::memory_order_relaxed)) {
        interrupted = true;
        continue;
      }
      const TileRect& r = rects[t];
      auto tile = std::make_unique<TileFilm>(film.makeTile(r.x0, r.y0, r.x1, r.y1));
      fn(*tile);
      done[t] = std::move(tile);
      if (ctx.progress) {
        std::lock_guard<std::mutex> lock(progressMutex);
        ++finished;
        ctx.progress(settings.phase, static_cast<double>(finished), static_cast<double>(rects.size()));
      }
    }
  });

  for (const auto& tile : done)
    if (tile) film.merge(*tile);
  RenderLoopResult result;
  result.interrupted = interrupted.load();
  return result;
}

}  // namespace

bool usesLowDiscrepancy(const RenderContext& ctx) {
  const std::string& name = ctx.options.sampler.empty() ? ctx.scene.sampler.type : ctx.options.sampler;
  return name == "ldsampler";
}

namespace {

// Samples per shading chunk of a tile row: large enough for a coherent ray stream, small enough
// that cancellation, checked between chunks, stops the render promptly.
constexpr size_t kChunkSamples = 4096;

// The first pixel after `px` in row `row` such that [px, end) holds at least kChunkSamples samples
// or the tile row ends; `n` receives their number.
int chunkEnd(const std::vector<SampleRange>& ranges, size_t row, int px, int x1, size_t& n) {
  n = 0;
  for (; px < x1 && n < kChunkSamples; ++px)
    n += static_cast<size_t>(std::max(0, ranges[row + px].end - ranges[row + px].first));
  return px;
}

// Fills the RNG streams and film positions of pixels [x0, x1) of row `py` in place (the arrays
// hold at least their samples): a sample's Rng and input are written once, where they stay.
// Streams are keyed by the sensor pixel and jittered on the sensor, then moved into the crop
// window: exact, so the camera, which moves it back, sees the bits a full render sees. With the
// low-discrepancy sampler each pixel's dimension seeds go to `dimensionSeeds` (one per pixel of the
// chunk), which the chunk's Rngs read until the next chunk refills it.
void fillChunk(const Film& film, const RenderLoopSettings& settings, const std::vector<SampleRange>& ranges,
               size_t row, int py, int x0, int x1, std::vector<Rng>& rngs, std::vector<SampleInput>& inputs,
               std::vector<ld::PixelDimensionSeeds>& dimensionSeeds) {
  const Vec2 cropOrigin(static_cast<float>(film.cropX()), static_cast<float>(film.cropY()));
  if (settings.lowDiscrepancy && dimensionSeeds.size() < static_cast<size_t>(x1 - x0)) dimensionSeeds.resize(x1 - x0);
  size_t k = 0;
  for (int x = x0; x < x1; ++x) {
    const int sx = film.cropX() + x, sy = film.cropY() + py;
    const PixelRngSeed pixelSeed = pixelRngSeed(settings.seed, film.sensorWidth(), sx, sy, settings.lowDiscrepancy);
    const ld::PixelDimensionSeeds* seeds = nullptr;
    if (settings.lowDiscrepancy && ranges[row + x].end > ranges[row + x].first) {
      dimensionSeeds[x - x0] = ld::PixelDimensionSeeds(pixelSeed.lowDiscrepancySeed);
      seeds = &dimensionSeeds[x - x0];
    }
    const Vec2 onSensorPixel(static_cast<float>(sx), static_cast<float>(sy));
    for (int s = ranges[row + x].first; s < ranges[row + x].end; ++s, ++k) {
      seedPixelRng(rngs[k], pixelSeed, s, seeds);
      SampleInput& in = inputs[k];
      in.px = x;
      in.py = py;
      in.sampleIndex = s;
      in.filmPos = (onSensorPixel + rngs[k].next2D()) - cropOrigin;
      in.cameraRay = nullptr;
      in.cameraHit = nullptr;
    }
  }
}

// Traces the chunk's n camera rays as one stream and points each input at its ray and hit.
void traceCameraRays(const RenderContext& ctx, const RenderLoopSettings& settings, SampleInput* inputs, size_t n,
                     std::vector<Ray>& rays, std::vector<Hit>& hits) {
  rays.resize(n);
  hits.resize(n);
  for (size_t i = 0; i < n; ++i) rays[i] = settings.cameraRay(inputs[i].filmPos);
  ctx.accel.intersect(rays.data(), hits.data(), n, true);
  for (size_t i = 0; i < n; ++i) {
    inputs[i].cameraRay = &rays[i];
    inputs[i].cameraHit = &hits[i];
  }
}

// The sample loop shared by renderSamples and renderSampleBatches: per tile row (in chunks of whole
// pixels when the row holds many samples), the samples' RNG streams, film positions, camera rays
// and their hits traced as one coherent stream, then `shadeRow(inputs, rngs, n, radiance)`, then
// the splats in sample order.
template <class ShadeRow>
RenderLoopResult sampleLoop(const RenderContext& ctx, Film& film, const RenderLoopSettings& settings,
                            const ShadeRow& shadeRow) {
  std::atomic<uint64_t> samples{0}, nans{0};
  const int width = film.width();
  const int spp = std::max(1, settings.spp);
  // Round 0: every pixel's spp samples; then (adaptive sampling) rounds for the pixels that need
  // more, over the tiles that hold any. A tile's pixels are written by its thread alone.
  AdaptivePixels adaptive(width, film.height(), spp, settings.adaptive, settings.firstSample);
  const TileFn tileFn = [&](TileFilm& tile) {
    uint64_t tileSamples = 0, tileNans = 0;
    const bool batch = static_cast<bool>(settings.cameraRay);
    const std::vector<SampleRange>& ranges = adaptive.ranges();
    std::vector<Rng> rngs;
    std::vector<ld::PixelDimensionSeeds> dimensionSeeds;  // read by rngs' low-discrepancy draws
    std::vector<SampleInput> inputs;
    std::vector<Ray> rays;
    std::vector<Hit> hits;
    std::vector<Color> radiance;
    // Cancellation is checked per chunk of whole pixels, not only per tile: at high spp one tile is
    // minutes of work, and SIGINT/SIGTERM must stop the render promptly (the partial tile is kept).
    auto cancelled = [&] { return ctx.cancel && ctx.cancel->load(std::memory_order_relaxed); };
    for (int py = tile.y0(); py < tile.y1() && !cancelled(); ++py) {
      const size_t row = static_cast<size_t>(py) * width;
      for (int px = tile.x0(); px < tile.x1() && !cancelled();) {
        const int chunkBegin = px;
        size_t n = 0;
        px = chunkEnd(ranges, row, px, tile.x1(), n);
        if (n == 0) continue;
        if (rngs.size() < n) rngs.resize(n), inputs.resize(n);
        fillChunk(film, settings, ranges, row, py, chunkBegin, px, rngs, inputs, dimensionSeeds);
        if (batch) traceCameraRays(ctx, settings, inputs.data(), n, rays, hits);
        radiance.resize(n);
        shadeRow(inputs.data(), rngs.data(), n, radiance.data(), tile);
        for (size_t k = 0; k < n; ++k) {
          const Color& L = radiance[k];
          if (!isFinite(L)) {
            ++tileNans;  // dropped, never splatted
            continue;
          }
          tile.splat(inputs[k].filmPos, L);
          adaptive.add(row + inputs[k].px, inputs[k].sampleIndex, L);
          ++tileSamples;
        }
      }
    }
    samples += tileSamples;
    nans += tileNans;
  };
  RenderLoopResult result = renderTiles(ctx, film, settings, tileFn);
  for (int round = 1; !result.interrupted && adaptive.nextRound(); ++round) {
    RenderLoopSettings more = settings;
    more.phase = settings.phase + " (adaptive " + std::to_string(round) + ")";
    result.interrupted = renderTiles(ctx, film, more, tileFn).interrupted;
  }
  result.samples = samples.load();
  result.nanSamples = nans.load();
  result.adaptivePixels = adaptive.pixelsAboveSpp();
  result.maxPixelSamples = adaptive.maxSamples();
  return result;
}

}  // namespace

RenderLoopResult renderSamples(const RenderContext& ctx, Film& film, const RenderLoopSettings& settings,
                               const SampleFn& fn) {
  return sampleLoop(ctx, film, settings,
                    [&](const SampleInput* in, Rng* rngs, size_t n, Color* out, TileFilm& tile) {
                      for (size_t k = 0; k < n; ++k) out[k] = fn(in[k], rngs[k], tile);
                    });
}

RenderLoopResult renderSampleBatches(const RenderContext& ctx, Film& film, const RenderLoopSettings& settings,
                                     const BatchFn& fn) {
  return sampleLoop(ctx, film, settings,
                    [&](const SampleInput* in, Rng* rngs, size_t n, Color* out, TileFilm&) { fn(in, rngs, n, out); });
}

}  // namespace rc
