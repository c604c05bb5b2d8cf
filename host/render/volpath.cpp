// The volumetric path tracer (render/volpath.h): Mitsuba 3's volpath loop, one scalar path at a time.
#include "render/volpath.h"

#include <algorithm>
#include <cmath>

#include "geometry/shading_frame.h"
#include "render/direct_light.h"
#include "render/hidden_emitters.h"
#include "render/light_sampler.h"
#include "render/medium_tracking.h"
#include "render/phase_function.h"

namespace rc {

namespace {

// A shadow ray stops this many crossings of null surfaces in: a finite bound on the work per ray
// whatever the scene (a stack of invisible surfaces), far above any meaningful nesting.
constexpr int kMaxShadowCrossings = 1024;

// The material of a hit, null where the surface has none (the path ends there).
const Bsdf* materialOf(const Scene& scene, const Hit& hit) {
  if (hit.bsdf < 0 || hit.bsdf >= static_cast<int>(scene.bsdfs.size())) return nullptr;
  return scene.bsdfs[hit.bsdf].get();
}

const MediumInterface* mediaOf(const Scene& scene, const Hit& hit) {
  if (hit.mesh >= 0) return &scene.meshes[hit.mesh].media;
  if (hit.sphere >= 0) return &scene.spheres[hit.sphere].media;
  return nullptr;
}

// The medium a ray leaving `hit` along `dir` travels in (Mitsuba's SurfaceInteraction::target_medium):
// the exterior on the side the geometric normal points to. Surfaces without media keep `current`.
int mediumAfter(const Scene& scene, const Hit& hit, const Vec3& dir, int current) {
  const MediumInterface* media = mediaOf(scene, hit);
  if (!media || !media->transition()) return current;
  return glm::dot(hit.ng, dir) > 0.0f ? media->exterior : media->interior;
}

// The shadow ray from a point in a medium (no surface to offset from) to a light sample.
Ray rayToLight(const Vec3& p, const LightSample& ls) {
  Ray r;
  r.o = p;
  r.d = ls.wi;
  if (std::isfinite(ls.dist)) {
    const float margin = std::max(offset::kRelativeOffset * std::max(maxAbs(ls.lightPoint), ls.dist), offset::kAbsoluteFloor);
    r.tMax = std::max(0.0f, ls.dist - margin);
  }
  return r;
}

// Next-event estimation from a scattering point in a medium: one light sample, its phase value
// and transmittance, MIS-weighted against phase sampling. Consumes 3 numbers, and in a
// heterogeneous medium those of the shadow ray's tracking.
Color mediumLight(const RenderContext& ctx, const Vec3& p, const Vec3& wi, int medium, Rng& rng) {
  const Vec2 u = rng.next2D();
  const float uLight = rng.nextFloat();
  if (!ctx.lights.emitsLight()) return Color(0.0f);
  const std::optional<LightSample> ls = ctx.lights.sample(p, u, uLight);
  if (!ls || !(ls->pdf > 0.0f || ls->delta) || !(maxComponent(ls->radiance) > 0.0f)) return Color(0.0f);
  const float f = phaseValue(ctx.scene.media[medium].phase, wi, ls->wi);
  const Color tr = shadowTransmittance(ctx, rayToLight(p, *ls), medium, rng);
  return f * ls->radiance * tr * (ls->delta ? 1.0f : powerHeuristic(ls->pdf, f));
}

}  // namespace

bool sceneUsesMedia(const Scene& scene) {
  if (scene.cameraMedium >= 0) return true;
  for (const Mesh& m : scene.meshes)
    if (m.media.transition()) return true;
  for (const Sphere& s : scene.spheres)
    if (s.media.transition()) return true;
  return false;
}

bool followsMedia(const Scene& scene, const std::string& integrator) {
  const std::string& estimator = integrator == "rcache" ? scene.integrator.type : integrator;
  return (estimator == "volpath" || estimator == "volpathmis" || estimator == "prbvolpath") && sceneUsesMedia(scene);
}

Color shadowTransmittance(const RenderContext& ctx, Ray ray, int medium, Rng& rng) {
  const Scene& scene = ctx.scene;
  Color tr(1.0f);
  for (int crossing = 0; crossing < kMaxShadowCrossings; ++crossing) {
    const Hit hit = ctx.accel.intersect(ray);
    if (medium >= 0) tr *= mediumTransmittance(scene.media[medium], ray, hit.valid() ? hit.t : ray.tMax, rng);
    if (!hit.valid()) return tr;
    const Bsdf* material = materialOf(scene, hit);
    if (!material) return Color(0.0f);
    BsdfPtr holder;
    tr *= bsdfAt(*material, hit.uv, holder).nullTransmission();
    if (!(maxComponent(tr) > 0.0f)) return Color(0.0f);
    medium = mediumAfter(scene, hit, ray.d, medium);
    Ray next = Accel::spawnRay(hit, ray.d);
    if (std::isfinite(ray.tMax)) next.tMax = std::max(0.0f, ray.tMax - glm::dot(next.o - ray.o, ray.d));
    ray = next;
  }
  return Color(0.0f);
}

Color volPathRadiance(const RenderContext& ctx, const IntegratorSettings& settings, const Ray& cameraRay, Rng& rng) {
  const Scene& scene = ctx.scene;
  // Mitsuba compares depths as unsigned integers: max_depth −1 never stops a path.
  const uint32_t maxDepth = static_cast<uint32_t>(settings.maxDepth);
  const uint32_t rrDepth = static_cast<uint32_t>(std::max(settings.rrDepth, 0));
  Color L(0.0f), beta(1.0f);
  float eta = 1.0f;
  Ray ray = cameraRay;
  int medium = scene.cameraMedium;
  uint32_t depth = 0;
  bool specularChain = !settings.hideEmitters;  // emission found next counts whole
  Vec3 lastScatter = ray.o;                      // where the last non-null scattering happened
  float lastScatterPdf = 1.0f;                   // its direction's density (MIS against light sampling)

  for (;;) {
    // ---- Termination: Russian roulette, then the depth bound ----
    if (!(maxComponent(beta) > 0.0f) || !isFinite(beta)) break;
    const float q = std::min(maxComponent(beta) * eta * eta, 0.95f);
    const float uRr = rng.nextFloat();
    if (depth > rrDepth) {
      if (!(uRr < q)) break;
      beta /= q;
    }
    if (depth >= maxDepth) break;

    Hit hit = ctx.accel.intersect(ray);

    // ---- Free flight through the medium the ray is in ----
    if (medium >= 0) {
      const Medium& m = scene.media[medium];
      const FreeFlight flight = sampleFreeFlight(m, ray, hit.t, rng);
      beta *= flight.weight;
      if (flight.scattered) {
        // ---- Scattering in the medium ----
        const Vec3 p = flight.p;
        if (++depth >= maxDepth) break;
        const Vec3 wi = -ray.d;
        if (m.sampleEmitters) L += beta * mediumLight(ctx, p, wi, medium, rng);
        specularChain = !m.sampleEmitters;
        const PhaseSample ps = samplePhase(m.phase, wi, rng.next2D());
        ray = Ray();
        ray.o = p;
        ray.d = ps.wo;
        lastScatter = p;
        lastScatterPdf = ps.pdf;
        continue;
      }
      // The flight passed the surface (or left for good); nothing passed ends the path.
      if (!(maxComponent(flight.weight) > 0.0f)) break;
    }

    // A camera ray that reached a hidden area emitter goes on to what lies behind it (Mitsuba's volpath
    // skips them once the flight has reached the surface).
    if (depth == 0 && settings.hideEmitters) hit = behindAreaEmitters(ctx, ray, hit);

    // ---- Emission found by this segment ----
    if (!(depth == 0 && settings.hideEmitters))
      L += beta * emitterMis(ctx, lastScatter, ray.d, hit, lastScatterPdf, depth == 0 || specularChain);
    if (!hit.valid()) break;
    const Bsdf* material = materialOf(scene, hit);
    if (!material) break;
    const Frame frame = shadingFrame(*material, hit, -ray.d);
    BsdfPtr pointBsdf;
    const Bsdf& bsdf = bsdfAt(*material, hit, frame, hit.ns, pointBsdf);
    const Vec3 wo = frame.toLocal(-ray.d);
    if (bsdf.tinted()) beta *= bsdf.tint(hit.uv, wo);

    // ---- Emitter sampling at the surface: the shadow ray starts in the medium on its side ----
    if (depth + 1 < maxDepth)
      if (const std::optional<UnshadowedLight> light = lightSampleUnshadowed(ctx, hit, frame, wo, bsdf, rng, 1))
        L += beta * light->value *
             shadowTransmittance(ctx, light->shadow, mediumAfter(scene, hit, light->shadow.d, medium), rng);

    // ---- BSDF sampling ----
    const Vec2 u = rng.next2D();
    const float uLobe = rng.nextFloat();
    const std::optional<BsdfSample> bs = bsdf.sample(wo, uLobe, u);
    if (!bs) break;
    beta *= bs->weight;
    eta *= bs->eta;
    const Vec3 dir = frame.toWorld(bs->wi);
    if (!(bs->lobe & kLobeNull)) {
      ++depth;
      lastScatter = hit.p;
      lastScatterPdf = bs->pdf;
      if (bs->lobe & kLobeDelta) specularChain = true;
    }
    if (!(bs->lobe & kLobeDelta)) specularChain = false;
    medium = mediumAfter(scene, hit, dir, medium);
    ray = Accel::spawnRay(hit, dir);
  }
  return L;
}

}  // namespace rc
