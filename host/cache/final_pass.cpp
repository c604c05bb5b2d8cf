#include "cache/final_pass.h"

#include <algorithm>
#include <cmath>
#include <new>
#include <utility>

#include "cache/direct_light_batch.h"
#include "cache/final_pass_memory.h"
#include "cache/rng_salts.h"
#include "core/error.h"
#include "core/low_discrepancy.h"
#include "core/parallel.h"
#include "core/parallel_select.h"
#include "render/direct_light.h"
#include "render/render_loop.h"
#include "scene/integrator_params.h"

namespace rc {

namespace {

// Samples per band (≥): fewer engine calls (each a few kernel launches) at high spp; ~14 MB of
// primaries per band.
constexpr size_t kSamplesPerBand = 65536;
// A jittered sample that no record covers (the fill covered pixel centres) first tries the
// records covering it at twice their radius, before a record is made for it (which means shading
// earlier bands again). A sample is at most 0.71 px from its pixel's centre and records reach at
// least r_min = 1.5 px, so on flat surfaces the relaxed lookup nearly always succeeds; the
// interpolation weights are the same formula with a doubled a.
constexpr float kFinalRelaxedScale = 2.0f;
// Reshading rounds over the bands are capped: records only grow and a reshaded band finds its
// points covered, so a third round has not been seen; the cap only bounds time.
constexpr int kMaxBandRounds = 4;
// Samples of one pixel on surfaces whose normals agree this closely share one cache lookup.
constexpr float kSharedLookupMinCos = 0.995f;
// Image rows per parallel task of the splat (any value gives the same image).
constexpr int kSplatStripeRows = 8;

// The RNG streams, film positions and camera rays of the samples of active pixels [jb, je), in
// sample order; `first` is the offset of the chunk's first sample. With the low-discrepancy
// sampler, pixel j's scramble seeds are hashed once into dimensionSeeds[j − jb] (sized by the
// caller, alive while the streams draw their prefix) instead of twice per draw of each sample.
void generateCameraRays(const RcacheRun& run, const Film& film, int y0, const SampleRange* ranges,
                        const std::vector<size_t>& offset, const std::vector<uint32_t>& active, size_t jb, size_t je,
                        size_t first, std::vector<ld::PixelDimensionSeeds>& dimensionSeeds, std::vector<Rng>& rngs,
                        std::vector<Ray>& rays, std::vector<Vec2>& filmPos) {
  const int W = run.width;
  for (size_t j = jb; j < je; ++j) {
    const size_t q = active[j];
    const int x = static_cast<int>(q % W), y = y0 + static_cast<int>(q / W);
    // Streams keyed by the sensor pixel: a crop window draws what the full render draws there.
    const PixelRngSeed pixelSeed =
        pixelRngSeed(run.seed, film.sensorWidth(), film.cropX() + x, film.cropY() + y, run.lowDiscrepancy);
    const ld::PixelDimensionSeeds* seeds = nullptr;
    if (run.lowDiscrepancy) {
      dimensionSeeds[j - jb] = ld::PixelDimensionSeeds(pixelSeed.lowDiscrepancySeed);
      seeds = &dimensionSeeds[j - jb];
    }
    for (int si = ranges[q].first; si < ranges[q].end; ++si) {
      const size_t k = offset[q] + (si - ranges[q].first) - first;
      seedPixelRng(rngs.emplace_back(), pixelSeed, si, seeds);
      const Vec2 crop(static_cast<float>(film.cropX()), static_cast<float>(film.cropY()));
      filmPos[k] = Vec2(static_cast<float>(x), static_cast<float>(y)) + crop + rngs[k].next2D() - crop;
      rays[k] = run.camera.generate(filmPos[k]);
    }
  }
}

// The pixel's earlier representative whose lookup sample `sp` may share (same surface, normals
// agreeing, fewer than shareGroup users so far; its count is raised), or `self`.
uint32_t sharedRepresentative(const ParallelArray<Primary>& prim, const std::vector<uint32_t>& pixelReps,
                              std::vector<int>& repShares, int shareGroup, const ShadePoint& sp, uint32_t self) {
  for (size_t k = 0; k < pixelReps.size(); ++k) {
    const uint32_t r = pixelReps[k];
    const ShadePoint& o = prim[r].sp;
    if (repShares[k] < shareGroup && o.hit.bsdf == sp.hit.bsdf && o.hit.mesh == sp.hit.mesh &&
        o.hit.sphere == sp.hit.sphere && o.hit.curve == sp.hit.curve && glm::dot(o.frame.n, sp.frame.n) > kSharedLookupMinCos) {
      ++repShares[k];
      return r;
    }
  }
  return self;
}

}  // namespace

RcacheAovs parseRcacheAovs(const std::vector<std::string>& names) {
  RcacheAovs a;
  for (const std::string& n : names) {
    if (n == "records") a.records = true;
    else if (n == "radius") a.radius = true;
    else if (n == "technique") a.technique = true;
    else if (n == "contributors") a.contributors = true;
    else throw Error("rcache: unknown AOV '" + n + "' (known: records, radius, technique, contributors)");
  }
  return a;
}

FinalPass::FinalPass(const RcacheRun& run, const RcacheAovs& aovs, Film& film, AdaptivePixels& adaptive)
    : run_(run), aovs_(aovs), film_(film), adaptive_(adaptive) {
  const size_t rowSamples = static_cast<size_t>(std::max(1, run.width)) * static_cast<size_t>(std::max(1, run.spp));
  rowsPerBand_ = static_cast<int>(std::max<size_t>(1, std::min<size_t>(run.height, kSamplesPerBand / rowSamples)));
  bands_ = (run.height + rowsPerBand_ - 1) / rowsPerBand_;
  bandFilms_.resize(static_cast<size_t>(bands_));
}

void FinalPass::shadeBand(int band) {
  const int W = run_.width;
  const int y0 = band * rowsPerBand_, y1 = std::min(run_.height, y0 + rowsPerBand_);
  const size_t begin = static_cast<size_t>(y0) * W, end = static_cast<size_t>(y1) * W;
  auto tile = std::make_unique<TileFilm>(film_.makeTile(0, y0, W, y1));
  adaptive_.restart(begin, end);
  shadeSlices(y0, adaptive_.ranges().data() + begin, end - begin, *tile);
  bandFilms_[static_cast<size_t>(band)] = std::move(tile);
}

// A band whose samples exceed the batch bound (one long row at a huge spp) is shaded in slices
// of each pixel's samples. Sample indices, and so seeds and the image up to lookup sharing, are
// those of the whole band; a slice holds a multiple of the sharing group where it can.
void FinalPass::shadeSlices(int y0, const SampleRange* ranges, size_t pixels, TileFilm& tile) {
  size_t total = 0;
  int longest = 0;
  for (size_t q = 0; q < pixels; ++q) {
    total += static_cast<size_t>(ranges[q].count());
    longest = std::max(longest, ranges[q].count());
  }
  const size_t batch = finalPassBatchSamples(static_cast<int>(pixels), longest);
  if (total <= batch) {
    shadeSamples(y0, ranges, pixels, tile);
    return;
  }
  int perPixel = static_cast<int>(std::max<size_t>(1, batch / pixels));
  const int shareGroup = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(std::max(1, run_.spp)))));
  if (perPixel >= shareGroup) perPixel -= perPixel % shareGroup;
  std::vector<SampleRange> slice(pixels);
  for (int s0 = 0; s0 < longest && !run_.cancelled(); s0 += perPixel) {
    for (size_t q = 0; q < pixels; ++q) {
      slice[q].first = std::min(ranges[q].first + s0, ranges[q].end);
      slice[q].end = std::min(slice[q].first + perPixel, ranges[q].end);
    }
    shadeSamples(y0, slice.data(), pixels, tile);
  }
}

// A band shaded before records were created elsewhere may have missed them; it is shaded again
// until every band saw the final caches (usually one extra round over the bands up to the last
// one that created records, often none).
void FinalPass::shadeBands(bool& interrupted) {
  std::vector<size_t> shadedWith(static_cast<size_t>(bands_), 0);  // record count when last shaded
  for (int round = 0; round < kMaxBandRounds && !interrupted; ++round) {
    bool any = false;
    for (int band = 0; band < bands_ && !interrupted; ++band) {
      if (round > 0 && shadedWith[static_cast<size_t>(band)] == run_.totalRecords()) continue;
      if (run_.cancelled()) {
        interrupted = true;
        break;
      }
      shadeBand(band);
      shadedWith[static_cast<size_t>(band)] = run_.totalRecords();
      if (round > 0) ++reshaded_;
      any = true;
      if (run_.ctx.progress && round == 0) run_.ctx.progress("render", double(band + 1), double(bands_));
    }
    if (!any) break;
  }
}

void FinalPass::mergeBands() {
  for (auto& t : bandFilms_)
    if (t) film_.merge(*t);
}

void FinalPass::shadeSamples(int y0, const SampleRange* ranges, size_t pixels, TileFilm& tile) {
  std::vector<size_t> offset(pixels + 1, 0);
  // The pixels that take samples: all in a band's first round, a few in adaptive rounds (which
  // then do not walk the empty ones).
  std::vector<uint32_t> active;
  for (size_t q = 0; q < pixels; ++q) {
    offset[q + 1] = offset[q] + static_cast<size_t>(ranges[q].count());
    if (ranges[q].count() > 0) active.push_back(static_cast<uint32_t>(q));
  }
  const size_t n = offset[pixels];
  if (n == 0) return;
  Samples s;
  traceAndLight(y0, ranges, offset, active, s);
  cameraRays_ += n;
  // Representatives in sample order (the order is what makes the image independent of threads).
  const std::vector<size_t> reps = parallelSelect(n, [&](size_t i) { return s.rep[i] == i; });
  std::vector<size_t> slot(n, 0);
  const ParallelArray<ShadePoint> repPts(reps.size(), [&](size_t j) {
    slot[reps[j]] = j;
    return s.prim[reps[j]].sp;
  });
  std::vector<Color> repIndirect;
  std::vector<LookupAov> repAov;
  // Lobe-split points share the lookup of their base like any cached point; their coat's
  // continuation stays per sample, added to the sample's own (direct) term.
  run_.engine.indirect(repPts, repIndirect, &repAov, kFinalRelaxedScale, false);
  std::vector<size_t> split;
  for (size_t i = 0; i < n; ++i)
    if (s.lobeSplit[i]) split.push_back(i);
  if (!split.empty()) {
    std::vector<ShadePoint> coatPts(split.size());
    for (size_t j = 0; j < split.size(); ++j) coatPts[j] = s.prim[split[j]].sp;
    std::vector<Color> coat;
    run_.engine.coatIndirect(coatPts, coat, kFinalRelaxedScale);
    for (size_t j = 0; j < split.size(); ++j) s.direct[split[j]] += coat[j];
    lobeSplitSamples_ += split.size();
  }
  splat(s, repIndirect, repAov, slot, tile);
}

// Cached indirect light is smooth (the cache itself interpolates over ≥ r_min pixels), so the
// samples of one pixel that land on the same surface share a lookup at the first of them;
// direct light, emission and importance-sampled (sharp) materials stay per sample, so edges,
// shadows and sharp reflections keep their anti-aliasing. A lookup is shared by at most ⌈√spp⌉
// samples (see shareGroup). share_pixel=false: one lookup per sample. rep[i] = the sample whose lookup sample i uses. Everything per pixel runs in parallel
// over pixels.
void FinalPass::traceAndLight(int y0, const SampleRange* ranges, const std::vector<size_t>& offset,
                              const std::vector<uint32_t>& active, Samples& s) {
  const int W = run_.width, maxDepth = run_.engine.maxDepth();
  const RcacheParams& params = run_.params;
  // One lookup for all of a pixel's samples would make the cached term a single point sample of
  // the pixel, an error no spp removes (a floor); groups of ⌈√spp⌉ samples keep the lookups at
  // √spp of one per sample while that error falls with spp.
  const int shareGroup = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(std::max(1, run_.spp)))));
  const size_t n = offset.back();
  s.prim = ParallelArray<Primary>(n, ParallelArray<Primary>::Unconstructed{});  // every sample's is made below
  s.direct.assign(n, Color(0.0f));
  s.sampleIndex.resize(n);
  s.rep.resize(n);
  s.lobeSplit.assign(n, 0);
  parallelFor(active.size(), 16, [&](size_t jb, size_t je) {
    std::vector<uint32_t> pixelReps;
    std::vector<int> repShares;  // samples using each representative's lookup
    uint64_t lightOnlyCount = 0;
    // One stream per sample: camera, then direct light, then (importance-sampled materials) the
    // continuation's BSDF sample, all from the pixel's low-discrepancy dimensions where the
    // sampler is ldsampler. The chunk's camera rays are traced first, as one coherent stream.
    const size_t first = offset[active[jb]], count = offset[active[je - 1] + 1] - first;
    std::vector<Rng> rngs;
    rngs.reserve(count);
    std::vector<Ray> rays(count);
    std::vector<Hit> hits(count);
    std::vector<Vec2> filmPos(count);
    std::vector<ld::PixelDimensionSeeds> dimensionSeeds(run_.lowDiscrepancy ? je - jb : 0);
    generateCameraRays(run_, film_, y0, ranges, offset, active, jb, je, first, dimensionSeeds, rngs, rays, filmPos);
    run_.ctx.accel.intersect(rays.data(), hits.data(), count, true);
    // The chunk's direct light as one batch (shadow and BSDF rays as packets).
    thread_local DirectLightChunk batch;
    batch.clear();
    for (size_t j = jb; j < je; ++j) {
      const size_t q = active[j];
      const int x = static_cast<int>(q % W), y = y0 + static_cast<int>(q / W);
      for (int si = ranges[q].first; si < ranges[q].end; ++si) {
        const size_t i = offset[q] + (si - ranges[q].first), k = i - first;
        s.sampleIndex[i] = si;
        const uint64_t sensorPixel = static_cast<uint64_t>(film_.cropY() + y) * film_.sensorWidth() + film_.cropX() + x;
        const uint64_t sampleSeed = hashMix(run_.seed, sensorPixel, kSaltFinalSample + si);
        new (&s.prim[i]) Primary(run_.primaries.of(filmPos[k], y * W + x, sampleSeed, rays[k], hits[k]));
        ShadePoint& sp = s.prim[i].sp;
        if (!sp.active || !withinMaxDepth(maxDepth, 2)) continue;
        // A spatially varying BSDF made at this point (Bsdf::at) is kept alive by the batch; most
        // points make none and add nothing to it.
        BsdfPtr pointBsdf;
        const Bsdf& bsdf = bsdfAt(*run_.ctx.scene.bsdfs[sp.hit.bsdf], sp, pointBsdf);
        if (pointBsdf) batch.holders.push_back(std::move(pointBsdf));
        sp.lightSamples = params.lightSamples;
        // Importance-sampled points: the continuation's ray doubles as the BSDF sample
        // (lightStrategyMis); the others take directLightCheapest's estimator.
        const RenderContext& lights = run_.engine.directLightContext(sp);
        s.lobeSplit[i] = run_.engine.hasIndirect(sp) && run_.engine.technique(sp) == Technique::LobeSplit;
        if (s.lobeSplit[i]) {  // the base lobe's light and the coat's own: outside the batch
          s.direct[i] = run_.engine.lobeSplitDirect(sp, rngs[k], params.lightSamples);
          continue;
        }
        const bool continues = run_.engine.continuesPath(sp);
        const bool lightOnly = !continues && cheapestIsLightOnly(lights, sp.hit, bsdf, params.lightSamples);
        if (lightOnly) ++lightOnlyCount;
        batch.jobs.push_back({&lights, &sp.hit, sp.frame, sp.wo, &bsdf, rngs[k],
                        continues   ? DirectEstimator::LightStrategy
                        : lightOnly ? DirectEstimator::LightOnly
                                    : DirectEstimator::Full,
                        params.lightSamples});
        batch.owner.push_back(static_cast<uint32_t>(k));
      }
    }
    batch.run();
    for (size_t m = 0; m < batch.jobs.size(); ++m) {
      rngs[batch.owner[m]] = batch.jobs[m].rng;  // the stream goes on where the estimator left it
      s.direct[first + batch.owner[m]] = batch.L[m];
    }
    for (size_t j = jb; j < je; ++j) {
      const size_t q = active[j];
      pixelReps.clear();
      repShares.clear();
      for (int si = ranges[q].first; si < ranges[q].end; ++si) {
        const size_t i = offset[q] + (si - ranges[q].first);
        ShadePoint& sp = s.prim[i].sp;
        continueLowDiscrepancy(sp, rngs[i - first]);
        s.rep[i] = static_cast<uint32_t>(i);
        const bool cached = sp.active && isCached(run_.engine.technique(sp));
        if (params.sharePixel && cached)
          s.rep[i] = sharedRepresentative(s.prim, pixelReps, repShares, shareGroup, sp, static_cast<uint32_t>(i));
        if (s.rep[i] == i && cached) {
          pixelReps.push_back(static_cast<uint32_t>(i));
          repShares.push_back(1);
        }
      }
    }
    directLightOnly_ += lightOnlyCount;
  });
}

// The samples' radiance is splatted by stripes of the tile's rows in parallel: each stripe passes
// the samples that can reach it in sample order and adds only to its own rows, so every pixel sums
// the same terms in the same order as one serial pass (the image does not depend on threads).
// A sample's per-pixel records (adaptive sampling, the NaN count) go with the stripe holding its
// pixel; the AOVs, rarely asked for, keep one serial pass.
void FinalPass::splat(const Samples& s, const std::vector<Color>& repIndirect, const std::vector<LookupAov>& repAov,
                      const std::vector<size_t>& slot, TileFilm& tile) {
  const int W = run_.width;
  const size_t n = s.prim.size();
  // What the stripes read of each sample, compact: every stripe a sample's footprint reaches
  // reads it again.
  struct SplatSample {
    Vec2 filmPos;
    Color L;
    int pixel, sampleIndex;
  };
  const ParallelArray<SplatSample> samples(n, [&](size_t i) {
    const ShadePoint& sp = s.prim[i].sp;
    const Bsdf* bsdf = sp.active ? run_.ctx.scene.bsdfs[sp.hit.bsdf].get() : nullptr;
    const Color tint = bsdf && bsdf->tinted() ? bsdf->tint(sp.hit.uv, sp.wo) : Color(1.0f);  // Bsdf::tint
    return SplatSample{s.prim[i].filmPos, s.prim[i].Le + tint * (s.direct[i] + repIndirect[slot[s.rep[i]]]), sp.pixel,
                       s.sampleIndex[i]};
  });
  // Samples are in pixel order, so those of rows [ya, yb) are one index range.
  auto firstOfRow = [&](int y) {
    size_t lo = 0, hi = n;
    while (lo < hi) {
      const size_t mid = (lo + hi) / 2;
      if (samples[mid].pixel / W < y) lo = mid + 1;
      else hi = mid;
    }
    return lo;
  };
  // Rows a sample at most reaches from its pixel's row: a position in [py, py + 1] reaches rows
  // ceil(y − ½ − r) … floor(y − ½ + r).
  const int reach = static_cast<int>(std::ceil(film_.filter().radius() + 0.5f));
  const int rowBegin = tile.splatRowBegin(), rowEnd = tile.splatRowEnd();
  const int stripes = (rowEnd - rowBegin + kSplatStripeRows - 1) / kSplatStripeRows;
  std::atomic<uint64_t> nan{0};
  parallelFor(static_cast<size_t>(std::max(0, stripes)), 1, [&](size_t b, size_t e) {
    for (size_t stripe = b; stripe < e; ++stripe) {
      const int ya = rowBegin + static_cast<int>(stripe) * kSplatStripeRows;
      const int yb = std::min(rowEnd, ya + kSplatStripeRows);
      uint64_t stripeNan = 0;
      for (size_t i = firstOfRow(ya - reach), end = firstOfRow(yb + reach); i < end; ++i) {
        const SplatSample& smp = samples[i];
        const int py = smp.pixel / W;
        const bool own = py >= ya && py < yb;
        if (isFinite(smp.L)) {
          tile.splatRows(smp.filmPos, smp.L, ya, yb);
          if (own) adaptive_.add(static_cast<size_t>(smp.pixel), smp.sampleIndex, smp.L);
        } else if (own) {
          ++stripeNan;
        }
      }
      nan += stripeNan;
    }
  });
  nanSamples_ += nan.load();
  if (!aovs_.radius && !aovs_.contributors && !aovs_.technique) return;
  for (size_t i = 0; i < n; ++i) {
    const ShadePoint& sp = s.prim[i].sp;
    const LookupAov& la = repAov[slot[s.rep[i]]];
    const int px = sp.pixel % W, py = sp.pixel / W;
    if (aovs_.radius) tile.addAov("radius", px, py, Color(la.meanA, la.meanRadiusPx, 0.0f));
    if (aovs_.contributors) tile.addAov("contributors", px, py, Color(float(la.contributors)));
    if (aovs_.technique) {
      const Technique t = run_.engine.technique(sp);
      const Color c = t == Technique::ImportanceSampling ? Color(1, 0, 0)
                      : t == Technique::IrradianceCache  ? Color(0, 1, 0)
                      : t == Technique::RadianceCache    ? Color(0, 0, 1)
                      : t == Technique::LobeSplit        ? Color(1, 0, 1)
                                                         : Color(0.0f);
      tile.addAov("technique", px, py, c);
    }
  }
}

}  // namespace rc
