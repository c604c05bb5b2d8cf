#include "cache/path_fallback.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "cache/rng_salts.h"
#include "core/parallel.h"
#include "core/rng.h"

namespace rc {

namespace {

// Pilot size: a 64² grid's worth of camera rays — a share estimate with a standard error below
// 1 %, for a cost of a few thousand rays (well under a percent of one spp at 256²).
constexpr size_t kPilotPoints = 4096;

}  // namespace

FallbackDecision decideFallback(const RcacheRun& run) {
  FallbackDecision d;
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
  auto served = [&](const ShadePoint& sp) { return sp.active && engine.hasIndirect(sp) && isCached(engine.technique(sp)); };
  std::vector<char> hit(prim.size(), 0), serves(prim.size(), 0);
  parallelFor(prim.size(), 64, [&](size_t b, size_t e) {
    for (size_t i = b; i < e; ++i) {
      const ShadePoint& sp = prim[i].sp;
      if (!sp.active) continue;
      hit[i] = 1;
      if (served(sp)) {
        serves[i] = 1;
        continue;
      }
      if (!engine.continuesPath(sp)) continue;
      Rng rng(sp.seed, 0);
      const Vec2 u = rng.next2D();
      BsdfPtr pointBsdf;  // a spatially varying BSDF at this point (Bsdf::at)
      const std::optional<BsdfSample> bs =
          bsdfAt(*run.ctx.scene.bsdfs[sp.hit.bsdf], sp, pointBsdf).sample(sp.wo, rng.nextFloat(), u);
      if (!bs || !(maxComponent(bs->weight) > 0.0f)) continue;
      const Vec3 dir = sp.frame.toWorld(bs->wi);
      const Hit next = run.ctx.accel.intersect(Accel::spawnRay(sp.hit, dir));
      const bool delta = (bs->lobe & kLobeDelta) != 0;
      serves[i] = served(engine.shadePointOf(next, dir, sp.depth + 1, sp.level + (delta ? 0 : 1), sp.seed)) ? 1 : 0;
    }
  });
  size_t hits = 0, servedCount = 0;
  for (size_t i = 0; i < prim.size(); ++i) hits += hit[i], servedCount += serves[i];
  d.pilotPoints = hits;
  if (hits == 0) {
    d.reason = "nothing hit";
    return d;
  }
  d.servedShare = double(servedCount) / double(hits);
  d.pathTrace = d.servedShare < run.params.fallbackShare;
  char buf[160];
  std::snprintf(buf, sizeof(buf), "%s: the cache would serve %.1f %% of %zu pilot points (threshold %.0f %%)",
                d.pathTrace ? "path traced" : "cached", 100.0 * d.servedShare, hits, 100.0 * run.params.fallbackShare);
  d.reason = buf;
  return d;
}

}  // namespace rc
