#include "render/direct_light.h"

#include <algorithm>

#include "render/light_sampler.h"

namespace rc {

namespace {
// True when the BSDF has a lobe that light sampling can hit (a non-delta component).
bool hasSmoothLobe(const Bsdf& bsdf) { return (bsdf.lobes() & (kLobeDiffuse | kLobeGlossy)) != 0; }
}  // namespace

Color emitted(const Scene& scene, const Hit& hit, const Vec3& wo) { return emitted(scene.emitters, hit, wo); }

Color emitted(const std::vector<Emitter>& emitters, const Hit& hit, const Vec3& wo) {
  if (!hit.valid() || hit.emitter < 0) return Color(0.0f);
  const Emitter& e = emitters[hit.emitter];
  if (e.type != EmitterType::Area) return Color(0.0f);
  return glm::dot(hit.ng, wo) > 0.0f ? e.radiance : Color(0.0f);
}

Ray shadowRay(const Hit& hit, const LightSample& ls) {
  return std::isinf(ls.dist) ? Accel::spawnRay(hit, ls.wi) : Accel::spawnRayTo(hit, ls.lightPoint);
}

bool visible(const Accel& accel, const Hit& hit, const LightSample& ls) { return !accel.occluded(shadowRay(hit, ls)); }

std::optional<UnshadowedLight> lightSampleUnshadowed(const RenderContext& ctx, const Hit& hit, const Frame& frame,
                                                     const Vec3& woLocal, const Bsdf& bsdf, Rng& rng,
                                                     int misLightSamples, int misBsdfSamples) {
  // Always draw the same three numbers so the stream stays aligned whatever happens below; the
  // point on the light first, so that it gets a low-discrepancy pair of its own.
  const Vec2 u = rng.next2D();
  const float uLight = rng.nextFloat();
  if (!ctx.lights.emitsLight() || !hasSmoothLobe(bsdf)) return std::nullopt;
  const std::optional<LightSample> ls = ctx.lights.sample(hit.p, u, uLight);
  if (!ls || !(ls->pdf > 0.0f || ls->delta)) return std::nullopt;
  const Vec3 wiLocal = frame.toLocal(ls->wi);
  // The BSDF's density only where MIS weighs the sample, then with its value in one call.
  const bool weighted = misLightSamples != 0 && misBsdfSamples != 0 && !ls->delta;
  const BsdfValue f = weighted ? bsdf.evalPdf(woLocal, wiLocal) : BsdfValue{bsdf.eval(woLocal, wiLocal), 0.0f};
  if (maxComponent(f.f) <= 0.0f || maxComponent(ls->radiance) <= 0.0f) return std::nullopt;
  UnshadowedLight out;
  out.shadow = shadowRay(hit, *ls);
  if (!weighted) {
    out.value = f.f * ls->radiance;
  } else {
    out.value = f.f * ls->radiance *
                powerHeuristic(static_cast<float>(misLightSamples) * ls->pdf, static_cast<float>(misBsdfSamples) * f.pdf);
  }
  return out;
}

namespace {
// One light sample and its shadow ray.
Color lightSampleContribution(const RenderContext& ctx, const Hit& hit, const Frame& frame, const Vec3& woLocal,
                              const Bsdf& bsdf, Rng& rng, int misLightSamples, int misBsdfSamples = 1) {
  const std::optional<UnshadowedLight> light =
      lightSampleUnshadowed(ctx, hit, frame, woLocal, bsdf, rng, misLightSamples, misBsdfSamples);
  if (!light || ctx.accel.occluded(light->shadow)) return Color(0.0f);
  return light->value;
}
}  // namespace

Color directLightLightOnly(const RenderContext& ctx, const Hit& hit, const Frame& frame, const Vec3& woLocal,
                           const Bsdf& bsdf, Rng& rng) {
  return lightSampleContribution(ctx, hit, frame, woLocal, bsdf, rng, 0);
}

bool cheapestIsLightOnly(const RenderContext& ctx, const Hit& hit, const Bsdf& bsdf, int lightSamples) {
  return lightSamples == 1 && bsdf.isDiffuseOnly() && ctx.lights.solidAngleBound(hit.p) <= kSmallLightsSolidAngle;
}

Color directLightCheapest(const RenderContext& ctx, const Hit& hit, const Frame& frame, const Vec3& woLocal,
                          const Bsdf& bsdf, Rng& rng, int lightSamples, bool* lightOnly) {
  const bool small = cheapestIsLightOnly(ctx, hit, bsdf, lightSamples);
  if (lightOnly) *lightOnly = small;
  return small ? directLightLightOnly(ctx, hit, frame, woLocal, bsdf, rng)
               : directLight(ctx, hit, frame, woLocal, bsdf, rng, lightSamples);
}

Color emitterMis(const RenderContext& ctx, const Vec3& from, const Vec3& dirWorld, const Hit& next, float bsdfPdf,
                 bool delta, int lightSamples, int bsdfSamples) {
  if (!next.valid()) {
    if (!ctx.lights.hasEnvironment()) return Color(0.0f);
    return environmentMis(ctx.lights.environmentLookup(dirWorld), bsdfPdf, delta, lightSamples, bsdfSamples);
  }
  const Color Le = emitted(ctx.lights.emitters(), next, -dirWorld);
  if (maxComponent(Le) <= 0.0f) return Color(0.0f);
  if (delta) return Le;
  return Le * powerHeuristic(static_cast<float>(bsdfSamples) * bsdfPdf,
                             static_cast<float>(lightSamples) * ctx.lights.pdf(next, from));
}

Color environmentMis(const LightSampler::EnvironmentLookup& env, float bsdfPdf, bool delta, int lightSamples,
                     int bsdfSamples) {
  if (maxComponent(env.radiance) <= 0.0f) return Color(0.0f);
  if (delta) return env.radiance;
  return env.radiance * powerHeuristic(static_cast<float>(bsdfSamples) * bsdfPdf, static_cast<float>(lightSamples) * env.pdf);
}

Color lightStrategyMis(const RenderContext& ctx, const Hit& hit, const Frame& frame, const Vec3& woLocal,
                       const Bsdf& bsdf, Rng& rng, int lightSamples, int bsdfSamples) {
  lightSamples = std::max(1, lightSamples);
  Color L(0.0f);
  for (int k = 0; k < lightSamples; ++k)
    L += lightSampleContribution(ctx, hit, frame, woLocal, bsdf, rng, lightSamples, bsdfSamples);
  if (lightSamples > 1) L /= static_cast<float>(lightSamples);
  return L;
}

void lightStrategyMisBatch(const RenderContext& ctx, const LightStrategyPoint* points, Rng* rngs, size_t count,
                           int lightSamples, Color* out, LightBatchScratch& scratch, BatchQuery query) {
  lightSamples = std::max(1, lightSamples);
  scratch.lights.clear();
  scratch.owner.clear();
  for (size_t i = 0; i < count; ++i) {
    const LightStrategyPoint& p = points[i];
    for (int k = 0; k < lightSamples; ++k)
      if (std::optional<UnshadowedLight> light =
              lightSampleUnshadowed(ctx, *p.hit, p.frame, p.woLocal, *p.bsdf, rngs[i], lightSamples)) {
        scratch.lights.push_back(*light);
        scratch.owner.push_back(static_cast<uint32_t>(i));
      }
  }
  const size_t n = scratch.lights.size();
  scratch.rays.resize(n);
  scratch.blocked.resize(n);
  for (size_t j = 0; j < n; ++j) scratch.rays[j] = scratch.lights[j].shadow;
  ctx.accel.occludedBatch(scratch.rays.data(), scratch.blocked.data(), n, query);
  // Summed per point in light-sample order (the order of lightStrategyMis's additions).
  std::fill(out, out + count, Color(0.0f));
  for (size_t j = 0; j < n; ++j)
    if (!scratch.blocked[j]) out[scratch.owner[j]] += scratch.lights[j].value;
  if (lightSamples > 1)
    for (size_t i = 0; i < count; ++i) out[i] /= static_cast<float>(lightSamples);
}

Color directLight(const RenderContext& ctx, const Hit& hit, const Frame& frame, const Vec3& woLocal, const Bsdf& bsdf,
                  Rng& rng, int lightSamples) {
  Color L = lightStrategyMis(ctx, hit, frame, woLocal, bsdf, rng, lightSamples);
  const Vec2 u = rng.next2D();
  const float uLobe = rng.nextFloat();
  if (!ctx.lights.emitsLight()) return L;  // black lights: the BSDF ray could find no emission
  const std::optional<BsdfSample> bs = bsdf.sample(woLocal, uLobe, u);
  if (!bs || maxComponent(bs->weight) <= 0.0f) return L;
  const Vec3 dir = frame.toWorld(bs->wi);
  const Hit next = ctx.accel.intersect(Accel::spawnRay(hit, dir));
  L += bs->weight * emitterMis(ctx, hit.p, dir, next, bs->pdf, (bs->lobe & kLobeDelta) != 0, lightSamples);
  return L;
}

}  // namespace rc
