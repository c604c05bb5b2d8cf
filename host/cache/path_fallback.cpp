#include "cache/path_fallback.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "cache/record_coherence.h"
#include "cache/rng_salts.h"
#include "core/parallel.h"
#include "core/rng.h"
#include "render/volpath.h"

namespace rc {

namespace {

// Pilot size: a 64² grid's worth of camera rays — a share estimate with a standard error below
// 1 %, for a cost of a few thousand rays (well under a percent of one spp at 256²).
constexpr size_t kPilotPoints = 4096;

struct ServedShare {
  float share = 0.0f;      // of the point's reflected light that records serve
  bool lobeSplit = false;  // served through a lobe split's base
};

// A cached point is served whole; a lobe-split point for its base's part of what it reflects,
// estimated from one sample of the whole BSDF as f_base/f there (E over the BSDF's sampling ≈
// the base's share of the albedo; a delta coat sample counts 0).
ServedShare servedShare(const RcacheRun& run, const ShadePoint& sp, Rng& rng) {
  ServedShare s;
  const CacheEngine& engine = run.engine;
  if (!sp.active || !engine.hasIndirect(sp)) return s;
  const Technique t = engine.technique(sp);
  if (!isCached(t)) return s;
  if (t != Technique::LobeSplit) {
    s.share = 1.0f;
    return s;
  }
  s.lobeSplit = true;
  const Bsdf& bsdf = *run.ctx.scene.bsdfs[sp.hit.bsdf];
  const Vec2 u = rng.next2D();
  const std::optional<BsdfSample> bs = bsdf.sample(sp.wo, rng.nextFloat(), u);
  if (!bs) return s;
  const float whole = luminance(bsdf.eval(sp.wo, bs->wi));
  if (whole > 0.0f && std::isfinite(whole))
    s.share = std::clamp(luminance(bsdf.baseLayer()->eval(sp.wo, bs->wi)) / whole, 0.0f, 1.0f);
  return s;
}

}  // namespace

FallbackDecision decideFallback(const RcacheRun& run) {
  FallbackDecision d;
  // Records hold surface radiance without media on the way, so a scene whose media the file's
  // integrator follows is always path traced by the volumetric estimator (render/volpath.h),
  // whatever the options ask.
  if (followsMedia(run.ctx.scene, "rcache")) {
    d.pathTrace = true;
    d.reason = "path traced: the scene has participating media, which the cache does not carry";
    return d;
  }
  if (!run.params.fallback || !run.files.load.empty() || !run.files.save.empty()) {
    d.reason = "not considered";
    return d;
  }
  // The grid covers the whole sensor, not the crop window: a tile (rcache --crop, the Dask
  // driver) then makes the decision the full image makes.
  const FilmSettings& film = run.ctx.scene.film;
  const int W = film.width, H = film.height;
  const int stride = std::max(1, static_cast<int>(std::sqrt(double(W) * H / kPilotPoints)));
  std::vector<Vec2> filmPos;
  std::vector<int> pixel;
  std::vector<uint64_t> seeds;
  for (int y = stride / 2; y < H; y += stride)
    for (int x = stride / 2; x < W; x += stride) {
      filmPos.emplace_back(float(x - film.cropX) + 0.5f, float(y - film.cropY) + 0.5f);
      pixel.push_back(-1);  // outside the image where it is cropped; the pilot makes no AOV
      seeds.push_back(hashMix(run.seed, static_cast<uint64_t>(y) * W + x, kSaltPilot));
    }
  std::vector<Primary> prim;
  run.primaries.trace(filmPos, pixel, seeds, prim);
  const CacheEngine& engine = run.engine;
  std::vector<char> hit(prim.size(), 0), ownCached(prim.size(), 0);
  std::vector<float> serves(prim.size(), 0.0f), splitServes(prim.size(), 0.0f);
  parallelFor(prim.size(), 64, [&](size_t b, size_t e) {
    for (size_t i = b; i < e; ++i) {
      const ShadePoint& sp = prim[i].sp;
      if (!sp.active) continue;
      hit[i] = 1;
      Rng rng(sp.seed, 0);
      const ServedShare own = servedShare(run, sp, rng);
      if (own.share > 0.0f) {
        ownCached[i] = 1;
        serves[i] = own.share;
        if (own.lobeSplit) splitServes[i] = own.share;
        continue;
      }
      if (!engine.continuesPath(sp)) continue;
      const Vec2 u = rng.next2D();
      BsdfPtr pointBsdf;  // a spatially varying BSDF at this point (Bsdf::at)
      const std::optional<BsdfSample> bs =
          bsdfAt(*run.ctx.scene.bsdfs[sp.hit.bsdf], sp, pointBsdf).sample(sp.wo, rng.nextFloat(), u);
      if (!bs || !(maxComponent(bs->weight) > 0.0f)) continue;
      const Vec3 dir = sp.frame.toWorld(bs->wi);
      const Hit next = run.ctx.accel.intersect(Accel::spawnRay(sp.hit, dir));
      const bool delta = (bs->lobe & kLobeDelta) != 0;
      const ServedShare below =
          servedShare(run, engine.shadePointOf(next, dir, sp.depth + 1, sp.level + (delta ? 0 : 1), sp.seed), rng);
      serves[i] = below.share;
      if (below.lobeSplit) splitServes[i] = below.share;
    }
  });
  size_t hits = 0;
  double servedSum = 0.0, splitSum = 0.0;
  for (size_t i = 0; i < prim.size(); ++i) hits += hit[i], servedSum += serves[i], splitSum += splitServes[i];
  d.gridPoints = prim.size();
  d.pilotPoints = hits;
  if (hits == 0) {
    d.reason = "nothing hit";
    return d;
  }
  d.servedShare = servedSum / double(hits);
  d.lobeSplitShare = splitSum / double(hits);
  d.pathTrace = d.servedShare < run.params.fallbackShare;
  char buf[400];
  const int n = std::snprintf(buf, sizeof(buf),
                              "%s: the cache would serve %.1f %% of %zu pilot points "
                              "(%.1f %% through lobe splits; threshold %.0f %%)",
                              d.pathTrace ? "path traced" : "cached", 100.0 * d.servedShare, hits,
                              100.0 * d.lobeSplitShare, 100.0 * run.params.fallbackShare);
  if (d.pathTrace) {
    d.reason = buf;
    return d;
  }
  // Served, but can a record serve more than its own pixel (cache/record_coherence.h)?
  const RecordCoherence coherence = measureRecordCoherence(run, filmPos, seeds, prim, ownCached);
  d.coherencePoints = coherence.points;
  d.neighbourOffsetPx = coherence.offsetPx;
  d.neighbourServedShare = coherence.share();
  d.neighbourServedBound = coherence.upperBound();
  if (coherence.tooIncoherent()) {
    d.pathTrace = true;
    std::snprintf(buf, sizeof(buf),
                  "path traced: a floor record would serve the point %.2f px away at %.1f %% of %zu pilot points "
                  "(at most %.1f %%; threshold %.1f %%) though the cache would serve %.1f %% of %zu",
                  coherence.offsetPx, 100.0 * d.neighbourServedShare, coherence.points,
                  100.0 * d.neighbourServedBound, 100.0 * minNeighbourServed(), 100.0 * d.servedShare, hits);
  } else if (coherence.points > 0 && n > 0 && size_t(n) < sizeof(buf)) {
    std::snprintf(buf + n, sizeof(buf) - size_t(n),
                  "; a floor record serves its neighbour %.2f px away at %.1f %% of %zu", coherence.offsetPx,
                  100.0 * d.neighbourServedShare, coherence.points);
  }
  d.reason = buf;
  return d;
}

void reportFallback(const FallbackDecision& d, RenderStats& stats) {
  stats.setText("fallback", d.reason);
  if (d.pilotPoints == 0) return;
  stats.set("pilot_served_share", d.servedShare);
  stats.set("pilot_lobe_split_share", d.lobeSplitShare);
  if (d.coherencePoints == 0) return;
  stats.set("pilot_neighbour_served_share", d.neighbourServedShare);
  stats.set("pilot_neighbour_served_bound", d.neighbourServedBound);
  stats.set("pilot_coherence_points", double(d.coherencePoints));
}

}  // namespace rc
