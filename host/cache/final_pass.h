#pragma once
// Phase 3 of an rcache render (docs/ARCHITECTURE.md §Pipeline): spp jittered samples per pixel, in
// bands of rows. Each band is shaded after the engine made the caches cover its points; a band that
// created records may have changed what earlier bands would see, so bands up to the last one that
// created records are shaded again at the end. The image is then a function of the final cache
// alone — the same cache --cache-save writes — and rendering with --cache-load of that file
// reproduces it exactly. Adaptive rounds (adaptive_rounds.h) reuse shadeSamples.
#include <atomic>
#include <memory>
#include <string>
#include <vector>

#include "cache/rcache_run.h"
#include "render/adaptive_sampling.h"
#include "render/film.h"

namespace rc {

// The AOVs the rcache integrator writes (RenderOptions::aovs).
struct RcacheAovs {
  bool records = false;       // per pixel: records whose primary hit lies there
  bool radius = false;        // per sample: mean a_i and mean radius (px) of the contributing records
  bool technique = false;     // red: BSDF sampling, green: irradiance cache, blue: radiance cache, magenta: lobe split
  bool contributors = false;  // per sample: records contributing to its lookup
};
// Throws rc::Error naming the unknown AOV and the known ones.
RcacheAovs parseRcacheAovs(const std::vector<std::string>& names);

class FinalPass {
 public:
  FinalPass(const RcacheRun& run, const RcacheAovs& aovs, Film& film, AdaptivePixels& adaptive);

  // Every band's first spp samples per pixel, and again for bands shaded before the caches were
  // final. Sets `interrupted` when cancelled.
  void shadeBands(bool& interrupted);
  // One band's first spp samples per pixel (replaces the band's earlier tile).
  void shadeBand(int band);
  // Shades the samples ranges[q] of the pixels q of rows [y0, y0 + pixels / W) into `tile`.
  void shadeSamples(int y0, const SampleRange* ranges, size_t pixels, TileFilm& tile);
  // The same in slices of each pixel's samples when they exceed the batch bound
  // (final_pass_memory.h), so memory does not grow with spp.
  void shadeSlices(int y0, const SampleRange* ranges, size_t pixels, TileFilm& tile);
  // Merges the bands' tiles into the film.
  void mergeBands();

  int bands() const { return bands_; }
  void countReshaded(int bands) { reshaded_ += bands; }

  uint64_t cameraRays() const { return cameraRays_; }
  uint64_t nanSamples() const { return nanSamples_; }
  uint64_t directLightOnly() const { return directLightOnly_.load(); }
  uint64_t lobeSplitSamples() const { return lobeSplitSamples_; }
  int bandsReshaded() const { return reshaded_; }

 private:
  // A sample's primary hit, direct light, and the representative whose lookup it uses.
  struct Samples {
    ParallelArray<Primary> prim;
    std::vector<Color> direct;
    std::vector<int> sampleIndex;
    std::vector<uint32_t> rep;
    std::vector<char> lobeSplit;  // technique LobeSplit: the coat's continuation is added per sample
  };
  void traceAndLight(int y0, const SampleRange* ranges, const std::vector<size_t>& offset,
                     const std::vector<uint32_t>& active, Samples& s);
  void splat(const Samples& s, const std::vector<Color>& repIndirect, const std::vector<LookupAov>& repAov,
             const std::vector<size_t>& slot, TileFilm& tile);

  const RcacheRun& run_;
  RcacheAovs aovs_;
  Film& film_;
  AdaptivePixels& adaptive_;
  int rowsPerBand_ = 1, bands_ = 0;
  std::vector<std::unique_ptr<TileFilm>> bandFilms_;
  uint64_t cameraRays_ = 0, nanSamples_ = 0, lobeSplitSamples_ = 0;
  std::atomic<uint64_t> directLightOnly_{0};  // samples whose direct light skipped the BSDF ray
  int reshaded_ = 0;
};

}  // namespace rc
