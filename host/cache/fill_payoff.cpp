#include "cache/fill_payoff.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "cache/record_coherence.h"
#include "cache/rng_salts.h"
#include "core/image_metrics.h"
#include "core/parallel.h"
#include "core/rng.h"
#include "render/direct_light.h"
#include "render/path_integrator.h"

namespace rc {

namespace {

// Points at which L and f are measured: four samples each (two of them direct light only), at
// most 1/64 of the render's samples (its cost must stay within the few percent the issue allows
// where the image is path traced), at most 1024 and at least 64.
constexpr double kPayoffSampleShare = 1.0 / 64.0;
constexpr double kMaxPayoffPoints = 1024.0, kMinPayoffPoints = 64.0;
constexpr size_t kFGroups = 8;

}  // namespace

double pixelsPerRecord(double q, double offsetPx, double rMaxPx) {
  const double cap = kPiD * rMaxPx * rMaxPx;
  if (q >= 1.0) return cap;
  const double rho = 2.0 * offsetPx / (kPiD * (1.0 - std::max(0.0, q)));
  return std::min(cap, kPiD * rho * rho);
}

FillPayoff predictFillPayoff(const FillPayoffFigures& f) {
  FillPayoff p;
  p.measured = true;
  p.figures = f;
  const double N = double(std::max(1, f.spp)), S = std::max(1.0, f.recordRays);
  p.fillRays = f.hitShare * f.recordShare * 2.0 * S / std::max(1e-9, f.pixelsPerRecord);
  p.cacheRays = p.fillRays + (1.0 + f.overhead) * N * f.raysPerSample;
  const double fs = std::clamp(f.indirectShare, 0.0, 1.0) * std::clamp(f.servedShare, 0.0, 1.0);
  p.pathEqualSpp = N / (1.0 - fs + fs * N / S);
  p.pathRays = p.pathEqualSpp * f.raysPerSample;
  p.pays = p.cacheRays <= p.pathRays;
  char buf[400];
  std::snprintf(buf, sizeof(buf),
                "%s: rcache predicted at %.3g rays per pixel (fill %.3g: %.2f px per record), the path tracer at "
                "its error %.3g (%.3g spp × %.3g rays; indirect share of its variance %.2f)",
                p.pays ? "the fill can pay" : "path traced, the fill cannot pay", p.cacheRays, p.fillRays,
                f.pixelsPerRecord, p.pathRays, p.pathEqualSpp, f.raysPerSample, f.indirectShare);
  p.reason = buf;
  return p;
}

FillPayoff measureFillPayoff(const RcacheRun& run, const IntegratorSettings& settings, const FallbackDecision& share) {
  if (run.lowDiscrepancy) {
    FillPayoff p;
    p.reason = "not predicted: under a low-discrepancy sampler the error does not fall as 1/spp";
    return p;
  }
  const int W = run.width, H = run.height;
  const double points = std::clamp(double(W) * H * std::max(1, run.spp) * kPayoffSampleShare / 4.0, kMinPayoffPoints,
                                   kMaxPayoffPoints);
  const int stride = std::max(1, int(std::sqrt(double(W) * H / points)));
  std::vector<Vec2> filmPos;
  std::vector<uint64_t> seeds;
  for (int y = stride / 2; y < H; y += stride)
    for (int x = stride / 2; x < W; x += stride) {
      filmPos.emplace_back(float(x) + 0.5f, float(y) + 0.5f);
      seeds.push_back(hashMix(run.seed, uint64_t(y) * uint64_t(W) + uint64_t(x), kSaltFillPayoff));
    }
  std::vector<Primary> prim;
  run.primaries.trace(filmPos, std::vector<int>(filmPos.size(), -1), seeds, prim);
  const CacheEngine& engine = run.engine;
  // Two path samples per point (their rays counted), and two of what the final pass leaves noisy
  // there: at a cached point the emission seen and the light-sampling half of its direct light from
  // the lights the records do not carry (engine.directLightContext); elsewhere the whole path.
  std::vector<Color> full(2 * prim.size()), kept(2 * prim.size());
  const uint64_t before = run.ctx.accel.raysTraced();
  parallelFor(full.size(), 64, [&](size_t b, size_t e) {
    for (size_t i = b; i < e; ++i) {
      Rng rng(seeds[i / 2], 1 + (i % 2));
      full[i] = pathRadiance(run.ctx, settings, run.camera.generate(filmPos[i / 2]), rng);
    }
  });
  const double pathRays = double(run.ctx.accel.raysTraced() - before);
  parallelFor(kept.size(), 64, [&](size_t b, size_t e) {
    for (size_t i = b; i < e; ++i) {
      const ShadePoint& sp = prim[i / 2].sp;
      if (!sp.active || !engine.hasIndirect(sp) || !isCached(engine.technique(sp))) {
        kept[i] = full[i];
        continue;
      }
      Rng rng(seeds[i / 2], 3 + (i % 2));
      BsdfPtr pointBsdf;  // a spatially varying BSDF at this point (Bsdf::at)
      const Bsdf& bsdf = bsdfAt(*run.ctx.scene.bsdfs[sp.hit.bsdf], sp, pointBsdf);
      kept[i] = prim[i / 2].Le + lightStrategyMis(engine.directLightContext(sp), sp.hit, sp.frame, sp.wo, bsdf, rng, 1);
    }
  });
  // Two samples per point make a pooled f hang on a few bright paths (corridor at 96²: 0.88, 0.01
  // and 0.56 at 2, 8 and 32 spp), so f is the median of kFGroups interleaved groups of points: one
  // such path moves one group. (The largest group's f swung lego at 256² to the cache.)
  double vAll[kFGroups] = {}, vKept[kFGroups] = {};
  for (size_t k = 0; k < prim.size(); ++k) {
    const double a = luminance(full[2 * k]), b = luminance(full[2 * k + 1]);
    const double c = luminance(kept[2 * k]), d = luminance(kept[2 * k + 1]);
    if (!std::isfinite(a + b + c + d)) continue;
    // Each pair's variance, weighted as relMSE weighs a pixel's error around their mean.
    const double mean = 0.5 * (a + b);
    vAll[k % kFGroups] += 0.5 * relMseTerm(a - b, mean);
    vKept[k % kFGroups] += 0.5 * relMseTerm(c - d, mean);
  }
  std::vector<double> groupF;
  for (size_t g = 0; g < kFGroups; ++g)
    groupF.push_back(vAll[g] > 0.0 ? std::clamp(1.0 - vKept[g] / vAll[g], 0.0, 1.0) : 0.0);
  std::sort(groupF.begin(), groupF.end());
  const double fMedian = 0.5 * (groupF[kFGroups / 2 - 1] + groupF[kFGroups / 2]);
  FillPayoffFigures f;
  f.spp = run.spp;
  f.hitShare = share.gridPoints ? double(share.pilotPoints) / double(share.gridPoints) : 1.0;
  f.recordShare = share.pilotPoints ? double(share.coherencePoints) / double(share.pilotPoints) : 0.0;
  f.servedShare = 1.0;  // the unserved points' noise is in what the final pass leaves (above)
  f.pixelsPerRecord = pixelsPerRecord(share.neighbourServedShare, share.neighbourOffsetPx, run.params.rMaxPx);
  f.recordRays = run.params.rays;
  f.raysPerSample = full.empty() ? 1.0 : pathRays / double(full.size());
  f.indirectShare = fMedian;
  f.overhead = kFinalPassOverhead;
  return predictFillPayoff(f);
}

void reportFillPayoff(const FillPayoff& p, RenderStats& stats) {
  if (!p.reason.empty()) stats.setText("fill_payoff", p.reason);
  if (!p.measured) return;
  stats.set("fill_payoff_rays_per_pixel", p.cacheRays);
  stats.set("fill_payoff_path_rays_per_pixel", p.pathRays);
  stats.set("fill_payoff_indirect_share", p.figures.indirectShare);
  stats.set("fill_payoff_rays_per_sample", p.figures.raysPerSample);
}

}  // namespace rc
