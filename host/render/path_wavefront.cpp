#include "render/path_wavefront.h"

#include <algorithm>

#include "geometry/shading_frame.h"
#include "render/direct_light.h"
#include "render/hidden_emitters.h"
#include "render/light_sampler.h"

namespace rc {

namespace {

template <class T>
void fit(std::vector<T>& v, size_t n) {
  if (v.size() < n) v.resize(n);
}

void prepare(PathWave& w, size_t count) {
  fit(w.rays, count);
  fit(w.radiance, count);
  fit(w.throughput, count);
  fit(w.prevP, count);
  fit(w.eta, count);
  fit(w.prevPdf, count);
  fit(w.prevDelta, count);
  fit(w.active, count);
  fit(w.next, count);
  fit(w.continues, count);
  w.diffuse.reset(count);
  fit(w.shadowRays, count);
  fit(w.shadowValue, count);
  fit(w.shadowLane, count);
  fit(w.blocked, count);
  fit(w.shadowOrder, count);
  fit(w.octants, count);
  fit(w.waveRays, count);
  fit(w.waveHits, count);
  fit(w.escapedEntry, count);
  w.escaped.fit(count);
}

// Writes the ids id(0) … id(n − 1) to out ordered by the octant of their direction dir(id) (a stable
// counting sort), so that a packet's rays share the order in which they visit the BVH's children.
// `octants` holds n bytes of scratch.
template <class Id, class Dir>
void orderByOctant(size_t n, const Id& id, const Dir& dir, uint8_t* octants, uint32_t* out) {
  size_t start[9] = {0};
  for (size_t k = 0; k < n; ++k) {
    const Vec3& d = dir(id(k));
    octants[k] = static_cast<uint8_t>((d.x < 0.0f ? 1 : 0) | (d.y < 0.0f ? 2 : 0) | (d.z < 0.0f ? 4 : 0));
    ++start[octants[k] + 1];
  }
  for (int o = 0; o < 8; ++o) start[o + 1] += start[o];
  for (size_t k = 0; k < n; ++k) out[start[octants[k]]++] = id(k);
}

// The lanes' state at their camera rays.
void startLanes(PathWave& w, const Ray* cameraRays, size_t count) {
  for (size_t i = 0; i < count; ++i) {
    w.radiance[i] = Color(0.0f);
    w.throughput[i] = Color(1.0f);
    w.eta[i] = 1.0f;
    w.prevP[i] = Vec3(0.0f);
    w.prevPdf[i] = 0.0f;
    w.prevDelta[i] = 1;
    w.rays[i] = cameraRays[i];
    w.active[i] = static_cast<uint32_t>(i);
  }
}

// The environment along the bounce's segments that escaped (lane i's in w.escaped at entry
// w.escapedEntry[i]), looked up in one pass over the wave; nothing when no term would use it.
void lookUpEscaped(const RenderContext& ctx, const IntegratorSettings& settings, PathWave& w, const Hit* hits,
                   size_t live, int depth) {
  if (!ctx.lights.hasEnvironment() || (depth == 0 && settings.hideEmitters)) return;
  LightSampler::EnvironmentWave& env = w.escaped;
  size_t n = 0;
  for (size_t k = 0; k < live; ++k) {
    const uint32_t i = w.active[k];
    if (hits[depth == 0 ? i : k].valid()) continue;
    const Vec3& d = w.rays[i].d;
    env.x[n] = d.x;
    env.y[n] = d.y;
    env.z[n] = d.z;
    w.escapedEntry[i] = static_cast<uint32_t>(n++);
  }
  // The camera rays' term is the radiance alone (LightSampler::environment); later ones weigh it by MIS.
  ctx.lights.environmentLookups(env, n, depth > 0);
}

// One bounce's shading, all in pathRadiance's order of draws and additions.
class BounceShader {
 public:
  BounceShader(const RenderContext& ctx, const IntegratorSettings& settings, Rng* rngs, PathWave& w, int depth)
      : ctx_(ctx), settings_(settings), rngs_(rngs), w_(w), depth_(depth) {}

  size_t shadows = 0;

  // Lane i, whose segment w.rays[i] found `hit` (valid until the bounce is shaded): adds the emission
  // the segment found, queues the vertex's shadow ray, and marks the lane (w.continues) for the next
  // bounce unless its path ends here. A diffuse vertex joins the bounce's diffuse group instead,
  // which shadeDiffuseGroup shades after the last lane.
  // (Always inline, as extend and continueAlong: the wave loop inlined them before the diffuse group
  // was split off, and as calls they cost envmap_product 1.5 % more instructions.)
  [[gnu::always_inline]] void shade(uint32_t i, const Hit& found) {
    w_.continues[i] = 0;
    const Ray& ray = w_.rays[i];
    // Hidden emitters let the camera ray through (render/hidden_emitters.h); `found` stays uncopied otherwise.
    const Hit& hit = depth_ == 0 && settings_.hideEmitters ? (behind_ = behindAreaEmitters(ctx_, ray, found)) : found;
    Color& throughput = w_.throughput[i];
    // Emission found by this segment: full weight for the camera ray, MIS against light sampling after.
    if (depth_ == 0) {
      if (!settings_.hideEmitters)
        w_.radiance[i] += throughput * (hit.valid() ? emitted(ctx_.scene, hit, -ray.d) : escapedEnvironment(i).radiance);
    } else {
      w_.radiance[i] += throughput * (hit.valid() ? emitterMis(ctx_, w_.prevP[i], ray.d, hit, w_.prevPdf[i], w_.prevDelta[i] != 0)
                                                  : environmentMis(escapedEnvironment(i), w_.prevPdf[i], w_.prevDelta[i] != 0));
    }
    if (!hit.valid()) return;
    // Mitsuba: a vertex may extend the path only while the path has fewer than max_depth segments.
    if (settings_.maxDepth >= 0 && depth_ + 1 >= settings_.maxDepth) return;
    const std::vector<BsdfPtr>& bsdfs = ctx_.scene.bsdfs;
    if (hit.bsdf < 0 || hit.bsdf >= static_cast<int>(bsdfs.size()) || !bsdfs[hit.bsdf]) return;
    // (A hit behind hidden emitters lives in behind_, which the next lane overwrites: shaded here.)
    if (const BsdfBatchParams batch = bsdfs[hit.bsdf]->batchParams(); batch.kind == BsdfBatchKind::Diffuse && &hit == &found)
      return joinDiffuseGroup(i, hit, batch.reflectance);
    // The frame a normal/bump map turns, and the BSDF at this point (Bsdf::at, Bsdf::atFrame).
    const Frame frame = shadingFrame(*bsdfs[hit.bsdf], hit, -ray.d);
    BsdfPtr pointBsdf;
    const Bsdf& bsdf = bsdfAt(*bsdfs[hit.bsdf], hit, frame, hit.ns, pointBsdf);
    const Vec3 wo = frame.toLocal(-ray.d);
    // A textured factor scales everything this vertex reflects (Bsdf::tint), not its emission.
    if (bsdf.tinted()) throughput *= bsdf.tint(hit.uv, wo);
    Rng& rng = rngs_[i];
    // Light sampling: its shadow ray joins the bounce's occlusion query; the value is added after.
    if (std::optional<UnshadowedLight> light = lightSampleUnshadowed(ctx_, hit, frame, wo, bsdf, rng, 1)) {
      w_.shadowRays[shadows] = light->shadow;
      w_.shadowValue[shadows] = throughput * light->value;
      w_.shadowLane[shadows] = i;
      ++shadows;
    }
    w_.continues[i] = extend(i, hit, frame, wo, bsdf, rng);
  }

  // The diffuse group's light samples and BSDF samples as passes over its arrays
  // (render/diffuse_shading.h), then per lane its shadow ray, its next segment and Russian roulette.
  void shadeDiffuseGroup() {
    DiffuseGroup& g = w_.diffuse;
    if (g.size == 0) return;
    diffuseShadingTerms(g);
    for (size_t k = 0; k < g.size; ++k) {
      const uint32_t i = g.lane[k];
      if (g.valueOn[k] != 0.0f) {
        w_.shadowRays[shadows] = shadowRay(*g.hit[k], g.light[k]);
        w_.shadowValue[shadows] = Color(g.valueR[k], g.valueG[k], g.valueB[k]);
        w_.shadowLane[shadows] = i;
        ++shadows;
      }
      if (g.extends[k] == 0.0f) continue;
      w_.throughput[i] = Color(g.thrR[k], g.thrG[k], g.thrB[k]);
      w_.continues[i] = continueAlong(i, *g.hit[k], Vec3(g.dirX[k], g.dirY[k], g.dirZ[k]), g.pdf[k], false, rngs_[i]);
    }
  }

 private:
  const RenderContext& ctx_;
  const IntegratorSettings& settings_;
  Rng* rngs_;
  PathWave& w_;
  const int depth_;
  Hit behind_;  // what a camera ray found behind hidden area emitters (reused: not built per lane)

  // What lookUpEscaped found along lane i's escaped segment (LightSampler::environmentLookup's
  // numbers; zero without an environment).
  LightSampler::EnvironmentLookup escapedEnvironment(uint32_t i) const {
    if (!ctx_.lights.hasEnvironment()) return {};
    return w_.escaped.at(w_.escapedEntry[i]);
  }

  // A diffuse vertex's draws (lightSampleUnshadowed's three, then the BSDF sample's three) and its
  // light sample, into the bounce's diffuse group.
  void joinDiffuseGroup(uint32_t i, const Hit& hit, const Color& reflectance) {
    Rng& rng = rngs_[i];
    const Vec2 uLight = rng.next2D();
    const float uEmitter = rng.nextFloat();
    const Vec2 uBsdf = rng.next2D();
    rng.nextFloat();  // the lobe's number: the diffuse lobe is the only one
    const Frame frame = hit.frame();
    const size_t k = w_.diffuse.add(i, hit, frame, frame.toLocal(-w_.rays[i].d).z, reflectance, w_.throughput[i], uBsdf);
    if (!ctx_.lights.emitsLight()) return;
    const std::optional<LightSample> ls = ctx_.lights.sample(hit.p, uLight, uEmitter);
    if (ls && (ls->pdf > 0.0f || ls->delta)) w_.diffuse.setLight(k, *ls);
  }

  // BSDF sampling and Russian roulette: true when the path continues along the new w.rays[i].
  [[gnu::always_inline]] bool extend(uint32_t i, const Hit& hit, const Frame& frame, const Vec3& wo, const Bsdf& bsdf, Rng& rng) {
    Color& throughput = w_.throughput[i];
    const Vec2 u = rng.next2D();
    const float uLobe = rng.nextFloat();
    const std::optional<BsdfSample> bs = bsdf.sample(wo, uLobe, u);
    if (!bs) return false;
    throughput *= bs->weight;
    w_.eta[i] *= bs->eta;
    if (!(maxComponent(throughput) > 0.0f) || !isFinite(throughput)) return false;
    return continueAlong(i, hit, frame.toWorld(bs->wi), bs->pdf, (bs->lobe & kLobeDelta) != 0, rng);
  }

  // The lane's next segment from `hit` along world direction `dir` (sampled with density `pdf`), then
  // Russian roulette: true when the path continues.
  [[gnu::always_inline]] bool continueAlong(uint32_t i, const Hit& hit, const Vec3& dir, float pdf, bool delta, Rng& rng) {
    Color& throughput = w_.throughput[i];
    w_.prevP[i] = hit.p;
    w_.prevPdf[i] = pdf;
    w_.prevDelta[i] = delta;
    w_.rays[i] = Accel::spawnRay(hit, dir);
    // Russian roulette (Mitsuba 3): once depth ≥ rr_depth, continue with q = min(max(β)·η², 0.95).
    const int segments = depth_ + 1;
    const float uRr = rng.nextFloat();
    if (segments >= settings_.rrDepth) {
      const float q = std::min(maxComponent(throughput) * w_.eta[i] * w_.eta[i], 0.95f);
      if (!(uRr < q)) return false;
      throughput /= q;
    }
    return true;
  }
};

}  // namespace

void pathRadianceBatch(const RenderContext& ctx, const IntegratorSettings& settings, const Ray* cameraRays,
                       const Hit* cameraHits, Rng* rngs, size_t count, Color* out, PathWave& w, BatchQuery query) {
  if (settings.maxDepth == 0) {
    std::fill(out, out + count, Color(0.0f));
    return;
  }
  prepare(w, count);
  startLanes(w, cameraRays, count);
  size_t live = count;
  for (int depth = 0; live > 0; ++depth) {
    // This bounce's segments: the camera rays' hits are given; later ones go to the BVH together.
    const Hit* hits = cameraHits;
    if (depth > 0) {
      orderByOctant(live, [&](size_t k) { return w.active[k]; }, [&](uint32_t i) -> const Vec3& { return w.rays[i].d; },
                    w.octants.data(), w.next.data());
      std::swap(w.active, w.next);
      for (size_t k = 0; k < live; ++k) w.waveRays[k] = w.rays[w.active[k]];
      ctx.accel.intersectBatch(w.waveRays.data(), w.waveHits.data(), live, query);
      hits = w.waveHits.data();
    }
    lookUpEscaped(ctx, settings, w, hits, live, depth);
    BounceShader shader(ctx, settings, rngs, w, depth);
    w.diffuse.size = 0;
    for (size_t k = 0; k < live; ++k) shader.shade(w.active[k], hits[depth == 0 ? w.active[k] : k]);
    shader.shadeDiffuseGroup();
    // The next bounce's lanes in this bounce's order, whichever pass shaded them.
    size_t survivors = 0;
    for (size_t k = 0; k < live; ++k)
      if (w.continues[w.active[k]]) w.next[survivors++] = w.active[k];
    // Each lane has at most one shadow ray per bounce, added before the next bounce's emission:
    // the same order of additions as pathRadiance, whatever the order in which the rays are traced.
    // They go to the BVH ordered by octant too (the bounce's rays and hits are no longer needed,
    // so waveRays holds them).
    if (const size_t shadows = shader.shadows; shadows > 0) {
      orderByOctant(shadows, [](size_t k) { return static_cast<uint32_t>(k); },
                    [&](uint32_t s) -> const Vec3& { return w.shadowRays[s].d; }, w.octants.data(),
                    w.shadowOrder.data());
      for (size_t j = 0; j < shadows; ++j) w.waveRays[j] = w.shadowRays[w.shadowOrder[j]];
      ctx.accel.occludedBatch(w.waveRays.data(), w.blocked.data(), shadows, query);
      for (size_t j = 0; j < shadows; ++j)
        if (!w.blocked[j]) w.radiance[w.shadowLane[w.shadowOrder[j]]] += w.shadowValue[w.shadowOrder[j]];
    }
    std::swap(w.active, w.next);
    live = survivors;
  }
  std::copy(w.radiance.begin(), w.radiance.begin() + count, out);
}

}  // namespace rc
