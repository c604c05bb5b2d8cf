#include "cache/cost_pilot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "cache/cache_engine.h"
#include "cache/cache_fill.h"
#include "cache/final_pass.h"
#include "cache/primary_hits.h"
#include "cache/rcache_options.h"
#include "cache/rcache_run.h"
#include "core/rng.h"
#include "core/json_writer.h"
#include "core/timing.h"
#include "render/adaptive_sampling.h"
#include "render/camera.h"
#include "render/film.h"
#include "render/path_integrator.h"

namespace rc {

namespace {

// The pilot images' size: about 1/64 of the image's pixels, so that its renders (two path-traced,
// three final passes and two fills per rcache candidate) stay a few percent of the render.
constexpr double kPilotPixelShare = 1.0 / 64.0;
constexpr double kMinPilotPixels = 24.0 * 24.0, kMaxPilotPixels = 48.0 * 48.0;
// Enough samples per pixel that a render's fixed overhead (threads, buffers) does not dominate
// its per-sample time at the pilot's size.
constexpr int kMaxPilotSpp = 16, kMinPilotSpp = 2;
// Salts of the pilot renders' seeds (distinct from the image's).
constexpr uint64_t kSaltCostPilot = 0xC057;
constexpr double kFirstCandidateCost = 4.0;
constexpr const char* kNoCandidateFits =
    "no candidate's pilot fits cost_pilot_share of the path-traced render: the fill's predicted payoff decides";

// The image's scene without its geometry (the pilot renders go through the image's Accel; only
// bounds, which the caller passes, read geometry from the scene), at the pilot's film.
Scene pilotScene(const Scene& scene, int width, int height) {
  Scene s;
  s.sourceFile = scene.sourceFile;
  s.bsdfs = scene.bsdfs;
  s.emitters = scene.emitters;
  s.camera = scene.camera;
  s.film = scene.film;
  s.film.width = width;
  s.film.height = height;
  s.film.cropX = s.film.cropY = s.film.cropWidth = s.film.cropHeight = 0;
  s.sampler.sampleCount = scene.sampler.sampleCount;
  s.sampler.seed = scene.sampler.seed;
  s.sampler.type = scene.sampler.type;
  s.integrator = scene.integrator;
  return s;
}

// mean over pixels and channels of (a − b)² / (r² + 0.01): core/image_metrics.h's relMSE with the
// difference of two estimates in place of an estimate's error, r the pooled mean of the pilot's
// images (a reference the candidates share).
double pairRelMse(const Image& a, const Image& b, const std::vector<Color>& ref) {
  double sum = 0.0;
  size_t n = 0;
  for (size_t i = 0; i < ref.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double d = double(a.pixels[i][c]) - double(b.pixels[i][c]);
      if (!std::isfinite(d)) continue;
      sum += d * d / (double(ref[i][c]) * double(ref[i][c]) + 0.01);
      ++n;
    }
  return n ? sum / double(n) : 0.0;
}

struct PilotRender {
  Image image;
  double seconds = 0.0;
};

struct RcachePilot {
  CandidateKind kind;
  PilotRender fillA, passA1, passA2, passB;  // fill times in fillA/.. seconds; images of the passes
  double recordGrowth = 1.0;  // records at the image's film per record of the pilot's
  double fillImageS = 0.0;    // the image's fill, predicted
  double seconds = 0.0;       // the candidate's pilot, all of it
};

size_t recordCount(CacheEngine& engine) {
  size_t n = 0;
  for (auto& [key, cache] : engine.caches()) n += cache->size();
  return n;
}

class Pilot {
 public:
  Pilot(const CostPilotInputs& in, int width, int height, int spp)
      : in_(in), scene_(pilotScene(in.ctx.scene, width, height)), width_(width), height_(height), spp_(spp) {
    options_ = in.ctx.options;
    options_.spp = spp;
    options_.aovs.clear();
    options_.adaptive = AdaptiveSettings{};
  }

  bool cancelled() const { return in_.ctx.cancel && in_.ctx.cancel->load(std::memory_order_relaxed); }

  PilotRender pathTraced(uint64_t seed) {
    RenderContext ctx{scene_, in_.ctx.accel, in_.ctx.lights, options_, in_.ctx.cancel, nullptr};
    ctx.options.seed = seed;
    RenderStats stats;
    const auto start = SteadyClock::now();
    PilotRender r;
    r.image = makePathIntegrator(in_.settings)->render(ctx, stats);
    r.seconds = secondsSince(start);
    return r;
  }

  // Two final passes (seeds a1, a2) over one cache filled with seed a1, and one over a cache
  // filled with seed b.
  // `coarser`: the same pilot at a quarter of the pixels, whose fill's record count gives the
  // growth of the records with the pixels.
  RcachePilot rcache(CandidateKind kind, uint64_t a1, uint64_t a2, uint64_t b, Pilot& coarser, double toImage) {
    const auto start = SteadyClock::now();
    RcachePilot p{kind, {}, {}, {}, {}};
    const Cache cacheA(*this, kind, a1);
    p.fillA.seconds = cacheA.fillSeconds;
    const double records = double(recordCount(cacheA.engine));
    const Cache coarseCache(coarser, kind, a1);
    const double coarse = double(recordCount(coarseCache.engine));
    const double exponent = records > 0.0 && coarse > 0.0 ? std::clamp(std::log(records / coarse) / std::log(4.0), 0.0, 1.0) : 1.0;
    p.recordGrowth = std::pow(toImage, exponent);
    // The fill's seconds as a fixed part plus a part per record, from the two fills (the fixed
    // part — passes, batches, kernels — does not grow with the records).
    const double perRecord = records > coarse && cacheA.fillSeconds > coarseCache.fillSeconds
                                 ? (cacheA.fillSeconds - coarseCache.fillSeconds) / (records - coarse)
                                 : records > 0.0 ? cacheA.fillSeconds / records : 0.0;
    const double fixed = std::max(0.0, cacheA.fillSeconds - perRecord * records);
    p.fillImageS = fixed + perRecord * records * p.recordGrowth;
    p.passA1 = cacheA.finalPass(a1);
    p.passA2 = cacheA.finalPass(a2);
    const Cache cacheB(*this, kind, b);
    p.passB = cacheB.finalPass(b);
    p.seconds = secondsSince(start);
    return p;
  }

 private:
  // One filled cache at the pilot's film.
  struct Cache {
    Cache(Pilot& pilot, CandidateKind kind, uint64_t seed)
        : p(pilot), ctx{p.scene_, p.in_.ctx.accel, p.in_.ctx.lights, p.options_, p.in_.ctx.cancel, nullptr},
          camera(p.scene_.camera, p.scene_.film),
          engine(ctx, p.in_.backend, p.in_.params, p.in_.tables, camera, p.in_.settings.maxDepth,
                 p.in_.settings.rrDepth, p.in_.sceneLo, p.in_.sceneHi),
          primaries(ctx, engine, camera, p.in_.settings.maxDepth, p.in_.settings.hideEmitters) {
      engine.setLobeSplit(kind == CandidateKind::RcacheLobeSplit);
      const RcacheRun run = runWith(seed);
      const auto start = SteadyClock::now();
      fillCache(run);
      fillSeconds = secondsSince(start);
    }
    RcacheRun runWith(uint64_t seed) const {
      return RcacheRun{ctx, p.in_.backend, files, p.in_.params, p.in_.tables, camera, engine,
                       primaries, p.width_, p.height_, p.spp_, seed, p.in_.lowDiscrepancy};
    }
    PilotRender finalPass(uint64_t seed) const {
      const RcacheRun run = runWith(seed);
      Film film(p.scene_.film);
      AdaptivePixels adaptive(p.width_, p.height_, p.spp_, AdaptiveSettings{});
      const auto start = SteadyClock::now();
      FinalPass pass(run, RcacheAovs{}, film, adaptive);
      bool interrupted = false;
      pass.shadeBands(interrupted);
      pass.mergeBands();
      PilotRender r;
      r.seconds = secondsSince(start);
      r.image = film.develop();
      return r;
    }
    Pilot& p;
    RenderContext ctx;
    CameraModel camera;
    mutable CacheEngine engine;  // the final passes add records where the fill left gaps
    PrimaryHits primaries;
    CacheFiles files;
    double fillSeconds = 0.0;
  };

  const CostPilotInputs& in_;
  Scene scene_;
  RenderOptions options_;
  int width_, height_, spp_;
};

}  // namespace

const char* candidateName(CandidateKind k) {
  switch (k) {
    case CandidateKind::PathTracer: return "path tracer";
    case CandidateKind::Rcache: return "rcache";
    case CandidateKind::RcacheLobeSplit: return "rcache + lobe split";
  }
  return "?";
}

CostChoice chooseByCost(std::vector<TechniqueEstimate> candidates, int spp) {
  CostChoice c;
  c.candidates = std::move(candidates);
  if (c.candidates.empty() || c.candidates[0].kind != CandidateKind::PathTracer || spp <= 0) return c;
  const TechniqueEstimate& path = c.candidates[0];
  c.targetError = path.variance / double(spp);
  for (size_t i = 0; i < c.candidates.size(); ++i) {
    TechniqueEstimate& e = c.candidates[i];
    if (i == 0) {
      e.sppToTarget = double(spp);
    } else if (c.targetError > e.floor) {
      e.sppToTarget = e.variance / (c.targetError - e.floor);
    } else {
      e.sppToTarget = INFINITY;
    }
    e.secondsToTarget = std::isfinite(e.sppToTarget) ? e.fixedS + e.perSppS * e.sppToTarget : INFINITY;
    if (c.chosen < 0 || e.secondsToTarget < c.candidates[size_t(c.chosen)].secondsToTarget) c.chosen = int(i);
  }
  return c;
}

std::string CostPilotReport::json() const {
  JsonWriter w;
  w.beginArray();
  for (const TechniqueEstimate& e : choice.candidates)
    w.beginObject()
        .field("technique", candidateName(e.kind))
        .field("variance_per_spp", e.variance)
        .field("floor", e.floor)
        .field("fixed_s", e.fixedS)
        .field("per_spp_s", e.perSppS)
        .field("spp_to_target", e.sppToTarget)
        .field("seconds_to_target", e.secondsToTarget)
        .endObject();
  for (CandidateKind k : skipped) w.beginObject().field("technique", candidateName(k)).field("tried", false).endObject();
  w.endArray();
  return w.str();
}

void reportCostPilot(const CostPilotReport& report, RenderStats& stats) {
  if (report.reason.empty()) return;
  stats.setText("cost_pilot", report.reason);
  if (!report.ran && report.skipped.empty()) return;
  stats.setJson("cost_pilot_candidates", report.json());
  if (!report.ran) return;
  stats.set("cost_pilot_target_relmse", report.choice.targetError);
  stats.set("cost_pilot_s", report.seconds);
  stats.setText("cost_pilot_film", std::to_string(report.pilotWidth) + "x" + std::to_string(report.pilotHeight) + ", " +
                                       std::to_string(report.pilotSpp) + " spp");
}

CostPilotReport runCostPilot(const CostPilotInputs& in) {
  CostPilotReport report;
  const auto start = SteadyClock::now();
  const FilmSettings& film = in.ctx.scene.film;
  const double pixels = double(film.width) * double(film.height);
  if (pixels < 16.0 * kMinPilotPixels) {
    report.reason = "image too small for a cost pilot";
    return report;
  }
  // Its choice follows timings: the tiles of one image (crop windows, the Dask driver) could
  // choose differently, so they keep the share pilot's verdict, which they make alike.
  if (film.cropX != 0 || film.cropY != 0 || film.imageWidth() != film.width || film.imageHeight() != film.height) {
    report.reason = "not run for a crop window";
    return report;
  }
  const double pilotPixels = std::clamp(pixels * kPilotPixelShare, kMinPilotPixels, kMaxPilotPixels);
  const double scale = std::sqrt(pilotPixels / pixels);
  const int w = std::max(8, int(std::lround(film.width * scale))), h = std::max(8, int(std::lround(film.height * scale)));
  const int spp = std::clamp(in.spp, kMinPilotSpp, kMaxPilotSpp);
  report.pilotWidth = w;
  report.pilotHeight = h;
  report.pilotSpp = spp;
  const double toImage = pixels / (double(w) * double(h));  // seconds scale with pixels
  // The first candidate is expected to cost kFirstCandidateCost × the path tracer's two pilot
  // images, and the budget is cost_pilot_share of the path-traced render, those images' seconds
  // × toImage·spp / (2·pilot spp) (below): their seconds cancel, so where no candidate could be
  // tried that is known before anything is rendered, and the pilot stops here.
  if (kFirstCandidateCost > in.params.costPilotShare * toImage * in.spp / (2.0 * spp)) {
    report.skipped = in.rcacheCandidates;
    report.reason = kNoCandidateFits;
    report.seconds = secondsSince(start);
    return report;
  }

  Pilot pilot(in, w, h, spp), coarser(in, std::max(4, w / 2), std::max(4, h / 2), spp);
  auto seed = [&](uint64_t k) { return hashMix(in.seed, kSaltCostPilot, k); };
  const PilotRender pathA = pilot.pathTraced(seed(1)), pathB = pilot.pathTraced(seed(2));
  // The pilot may cost at most cost_pilot_share of the path tracer's render (issue 17: where caching
  // cannot pay, rcache costs at most 10 % more than the path tracer): a candidate is tried
  // only while the time spent plus what it is expected to cost (the last candidate's pilot; before
  // the first, kFirstCandidateCost × the path tracer's pilot — two fills and three final passes
  // against two renders) stays within that. A candidate not tried is not chosen.
  const double pathPilotS = pathA.seconds + pathB.seconds;
  const double pathRenderS = 0.5 * pathPilotS / spp * toImage * in.spp;
  double expected = kFirstCandidateCost * pathPilotS;
  std::vector<RcachePilot> rc;
  for (CandidateKind k : in.rcacheCandidates) {
    if (pilot.cancelled()) break;
    if (secondsSince(start) + expected > in.params.costPilotShare * pathRenderS) {
      report.skipped.push_back(k);
      continue;
    }
    rc.push_back(pilot.rcache(k, seed(3), seed(4), seed(5), coarser, toImage));
    expected = rc.back().seconds;
  }
  if (pilot.cancelled()) {
    report.reason = "cost pilot interrupted";
    return report;
  }
  // The pooled mean of every pilot image: the relMSE's denominator for all candidates.
  std::vector<Color> ref(size_t(w) * size_t(h), Color(0.0f));
  int images = 0;
  auto pool = [&](const Image& img) {
    for (size_t i = 0; i < ref.size(); ++i) ref[i] += img.pixels[i];
    ++images;
  };
  pool(pathA.image);
  pool(pathB.image);
  for (const RcachePilot& p : rc) pool(p.passA1.image), pool(p.passA2.image), pool(p.passB.image);
  for (Color& c : ref) c /= float(images);

  std::vector<TechniqueEstimate> est;
  TechniqueEstimate path;
  path.kind = CandidateKind::PathTracer;
  // Two independent renders differ by twice each one's error.
  path.variance = 0.5 * pairRelMse(pathA.image, pathB.image, ref) * spp;
  path.perSppS = 0.5 * (pathA.seconds + pathB.seconds) / spp * toImage;
  est.push_back(path);
  for (const RcachePilot& p : rc) {
    TechniqueEstimate e;
    e.kind = p.kind;
    const double passes = 0.5 * pairRelMse(p.passA1.image, p.passA2.image, ref);  // V/spp: one cache
    const double whole = 0.5 * pairRelMse(p.passA1.image, p.passB.image, ref);    // V/spp + B: two caches
    e.variance = passes * spp;
    e.floor = std::max(0.0, whole - passes);
    e.fixedS = p.fillImageS;
    e.perSppS = (p.passA1.seconds + p.passA2.seconds + p.passB.seconds) / (3.0 * spp) * toImage;
    est.push_back(e);
  }
  report.choice = chooseByCost(std::move(est), in.spp);
  report.ran = report.choice.chosen >= 0;
  if (rc.empty()) {
    report.reason = kNoCandidateFits;
    report.seconds = secondsSince(start);
    return report;
  }
  report.seconds = secondsSince(start);
  if (report.ran) {
    const TechniqueEstimate& best = report.choice.candidates[size_t(report.choice.chosen)];
    char buf[200];
    std::snprintf(buf, sizeof(buf), "%s: fastest to the path tracer's relMSE %.3g at %d spp (%.3g s predicted; %dx%d pilot)",
                  candidateName(best.kind), report.choice.targetError, in.spp, best.secondsToTarget, w, h);
    report.reason = buf;
  } else {
    report.reason = "cost pilot: no decision";
  }
  if (!report.skipped.empty()) {
    report.reason += "; not tried (its pilot would not fit cost_pilot_share of the path-traced render):";
    for (CandidateKind k : report.skipped) report.reason += std::string(" ") + candidateName(k);
  }
  return report;
}

}  // namespace rc
