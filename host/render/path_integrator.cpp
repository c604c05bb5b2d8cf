#include "render/path_integrator.h"

#include <algorithm>
#include <utility>

#include "core/error.h"
#include "core/timing.h"
#include "geometry/shading_frame.h"
#include "render/camera.h"
#include "render/direct_light.h"
#include "render/film.h"
#include "render/hidden_emitters.h"
#include "render/light_sampler.h"
#include "render/path_wavefront.h"
#include "render/render_loop.h"
#include "render/volpath.h"

namespace rc {

Color pathRadiance(const RenderContext& ctx, const IntegratorSettings& settings, const Ray& cameraRay, Rng& rng,
                   const Hit* cameraHit) {
  const Scene& scene = ctx.scene;
  const int maxDepth = settings.maxDepth;
  if (maxDepth == 0) return Color(0.0f);
  Color L(0.0f), throughput(1.0f);
  float eta = 1.0f;  // accumulated relative IOR, for Russian roulette as Mitsuba
  Ray ray = cameraRay;
  Vec3 prevP(0.0f);
  float prevPdf = 0.0f;
  bool prevDelta = true;
  for (int depth = 0;; ++depth) {
    Hit hit = depth == 0 && cameraHit ? *cameraHit : ctx.accel.intersect(ray);
    if (depth == 0 && settings.hideEmitters) hit = behindAreaEmitters(ctx, ray, hit);

    // Emission found by this segment: full weight for the camera ray, MIS against light sampling after.
    if (depth == 0) {
      if (!settings.hideEmitters)
        L += throughput * (hit.valid() ? emitted(scene, hit, -ray.d) : ctx.lights.environment(ray.d));
    } else {
      L += throughput * emitterMis(ctx, prevP, ray.d, hit, prevPdf, prevDelta);
    }
    if (!hit.valid()) break;
    // Mitsuba: a vertex may extend the path only while the path has fewer than max_depth segments.
    if (maxDepth >= 0 && depth + 1 >= maxDepth) break;
    if (hit.bsdf < 0 || hit.bsdf >= static_cast<int>(scene.bsdfs.size()) || !scene.bsdfs[hit.bsdf]) break;
    // The frame a normal/bump map turns, and the BSDF at this point (Bsdf::at, Bsdf::atFrame).
    const Frame frame = shadingFrame(*scene.bsdfs[hit.bsdf], hit, -ray.d);
    BsdfPtr pointBsdf;
    const Bsdf& bsdf = bsdfAt(*scene.bsdfs[hit.bsdf], hit, frame, hit.ns, pointBsdf);
    const Vec3 wo = frame.toLocal(-ray.d);
    // A textured factor scales everything this vertex reflects (Bsdf::tint), not its emission.
    if (bsdf.tinted()) throughput *= bsdf.tint(hit.uv, wo);

    L += throughput * lightStrategyMis(ctx, hit, frame, wo, bsdf, rng, 1);

    const Vec2 u = rng.next2D();
    const float uLobe = rng.nextFloat();
    const std::optional<BsdfSample> bs = bsdf.sample(wo, uLobe, u);
    if (!bs) break;
    throughput *= bs->weight;
    eta *= bs->eta;
    if (!(maxComponent(throughput) > 0.0f) || !isFinite(throughput)) break;
    const Vec3 dir = frame.toWorld(bs->wi);
    prevP = hit.p;
    prevPdf = bs->pdf;
    prevDelta = (bs->lobe & kLobeDelta) != 0;
    ray = Accel::spawnRay(hit, dir);

    // Russian roulette (Mitsuba 3): once depth ≥ rr_depth, continue with q = min(max(β)·η², 0.95).
    const int segments = depth + 1;
    const float uRr = rng.nextFloat();
    if (segments >= settings.rrDepth) {
      const float q = std::min(maxComponent(throughput) * eta * eta, 0.95f);
      if (!(uRr < q)) break;
      throughput /= q;
    }
  }
  return L;
}

namespace {

// The path tracer's passes (render/integrator.h): each is the render loop over the pass's sample
// indices, into the caller's film.
class PathPasses final : public PassRender {
 public:
  PathPasses(const RenderContext& ctx, const IntegratorSettings& settings, PathCore core, BatchQuery query,
             const std::string& name, SampleEstimator estimator)
      : ctx_(ctx), settings_(settings), core_(core), query_(query), media_(followsMedia(ctx.scene, settings.type)),
        name_(name), estimator_(estimator), rays0_(ctx.accel.raysTraced()), camera_(ctx.scene.camera, ctx.scene.film) {
    loop_.spp = ctx.options.spp > 0 ? ctx.options.spp : ctx.scene.sampler.sampleCount;
    if (loop_.spp <= 0) throw Error("sampler: sample_count must be positive");
    loop_.seed = ctx.scene.sampler.seed + ctx.options.seed;
    loop_.lowDiscrepancy = usesLowDiscrepancy(ctx);
    loop_.cameraRay = [this](const Vec2& filmPos) { return camera_.generate(filmPos); };
    loop_.adaptive = ctx.options.adaptive;
    loop_.phase = "path";
  }
  int passSpp() const override { return loop_.spp; }

  bool addPass(Film& film, int firstSample) override {
    loop_.firstSample = firstSample;
    const RenderLoopResult r = renderPathSamples(film);
    total_.samples += r.samples;
    total_.nanSamples += r.nanSamples;
    total_.adaptivePixels += r.adaptivePixels;
    total_.maxPixelSamples = std::max(total_.maxPixelSamples, r.maxPixelSamples);
    return !r.interrupted;
  }

  Image finish(const Film& film, int passes, bool stopped, RenderStats& stats) override {
    Image image = film.develop();
    const double seconds = secondsSince(start_);
    const double rays = static_cast<double>(ctx_.accel.raysTraced() - rays0_);
    const int spp = loop_.spp * std::max(1, passes);
    stats.setText("integrator", name_);
    if (media_) stats.setText("path_core", "volpath (scalar; the scene has participating media)");
    stats.set("time_s", seconds);
    stats.set("spp", spp);
    stats.setText("sampler", loop_.lowDiscrepancy ? "ldsampler" : "independent");
    stats.set("samples", static_cast<double>(total_.samples));
    reportAdaptiveSampling(stats, ctx_.options.adaptive, loop_.spp, total_.samples + total_.nanSamples,
                           total_.adaptivePixels, total_.maxPixelSamples, static_cast<double>(film.width()) * film.height());
    stats.set("nan_samples", static_cast<double>(total_.nanSamples));
    stats.set("rays", rays);
    stats.set("rays_per_s", seconds > 0.0 ? rays / seconds : 0.0);
    stats.set("time_per_spp_s", seconds / spp);
    if (stopped) stats.set("interrupted", 1.0);
    return image;
  }

 private:
  RenderLoopResult renderPathSamples(Film& film) const {
    // Media are followed by the scalar volumetric estimator (render/volpath.h), whatever the core.
    if (media_)
      return renderSamples(ctx_, film, loop_, [&](const SampleInput& in, Rng& rng, TileFilm&) {
        return volPathRadiance(ctx_, settings_, *in.cameraRay, rng);
      });
    if (core_ == PathCore::Scalar)
      return renderSamples(ctx_, film, loop_, [&](const SampleInput& in, Rng& rng, TileFilm&) {
        return estimator_(ctx_, settings_, *in.cameraRay, rng, in.cameraHit);
      });
    // A tile row's samples (32 pixels × spp) are cut into waves of kWaveSize lanes: enough for full
    // packets through most of a path's bounces, small enough that a wave's buffers stay in cache.
    constexpr size_t kWaveSize = 256;
    return renderSampleBatches(ctx_, film, loop_, [&](const SampleInput* in, Rng* rngs, size_t n, Color* out) {
      thread_local PathWave wave;
      for (size_t b = 0; b < n; b += kWaveSize) {
        const size_t m = std::min(kWaveSize, n - b);
        // A batch's camera rays and hits are consecutive elements of one array (render_loop.h).
        pathRadianceBatch(ctx_, settings_, in[b].cameraRay, in[b].cameraHit, rngs + b, m, out + b, wave, query_);
      }
    });
  }

  const RenderContext& ctx_;
  const IntegratorSettings& settings_;
  const PathCore core_;
  const BatchQuery query_;
  const bool media_;  // the scene's media are followed (followsMedia)
  const std::string name_;
  const SampleEstimator estimator_;  // the scalar core's per-sample work
  const SteadyClock::time_point start_ = SteadyClock::now();
  const uint64_t rays0_;
  const CameraModel camera_;
  RenderLoopSettings loop_;
  RenderLoopResult total_;  // summed over the passes (its `interrupted` unused: finish is told)
};

class PathIntegrator final : public Integrator {
 public:
  PathIntegrator(const IntegratorSettings& s, PathCore core, BatchQuery query, std::string name = "path",
                 SampleEstimator estimator = pathRadiance)
      : settings_(s), core_(core), query_(query), name_(std::move(name)), estimator_(estimator) {
    if (s.maxDepth < -1) throw Error("integrator path: max_depth must be -1 (unbounded) or ≥ 0");
    if (s.rrDepth < 1) throw Error("integrator path: rr_depth must be ≥ 1");
  }
  std::string name() const override { return name_; }
  std::unique_ptr<PassRender> beginPasses(const RenderContext& ctx, RenderStats&) override {
    return std::make_unique<PathPasses>(ctx, settings_, core_, query_, name_, estimator_);
  }

 private:
  IntegratorSettings settings_;
  PathCore core_;
  BatchQuery query_;
  std::string name_;
  SampleEstimator estimator_;
};

}  // namespace

std::unique_ptr<Integrator> makePathIntegrator(const IntegratorSettings& settings, PathCore core, BatchQuery query) {
  return std::make_unique<PathIntegrator>(settings, core, query);
}

std::unique_ptr<Integrator> makeEstimatorIntegrator(const std::string& name, const IntegratorSettings& settings,
                                                    SampleEstimator estimator) {
  return std::make_unique<PathIntegrator>(settings, PathCore::Scalar, BatchQuery::Single, name, estimator);
}

}  // namespace rc
