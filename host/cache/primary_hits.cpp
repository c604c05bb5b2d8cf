#include "cache/primary_hits.h"

#include "core/parallel.h"
#include "render/direct_light.h"
#include "render/hidden_emitters.h"
#include "render/light_sampler.h"
#include "scene/integrator_params.h"

namespace rc {

Primary PrimaryHits::of(const Vec2& filmPos, int pixel, uint64_t sampleSeed, const Ray& ray, const Hit& cameraHit) const {
  const Hit hit = hideEmitters_ ? behindAreaEmitters(ctx_, ray, cameraHit) : cameraHit;
  Primary p;
  p.filmPos = filmPos;
  p.sp = engine_.shadePointOf(hit, ray.d, 1, 0, sampleSeed);
  p.sp.pixel = pixel;
  if (withinMaxDepth(maxDepth_, 1) && !hideEmitters_) {
    if (!hit.valid()) p.Le = ctx_.lights.environment(ray.d);
    else if (hit.emitter >= 0) p.Le = emitted(ctx_.scene, hit, -ray.d);
  }
  return p;
}

void PrimaryHits::trace(const std::vector<Vec2>& filmPos, const std::vector<int>& pixel,
                        const std::vector<uint64_t>& seeds, std::vector<Primary>& out) const {
  out.resize(filmPos.size());
  parallelFor(filmPos.size(), 256, [&](size_t b, size_t e) {
    std::vector<Ray> rays(e - b);
    std::vector<Hit> hits(e - b);
    for (size_t i = b; i < e; ++i) rays[i - b] = camera_.generate(filmPos[i]);
    ctx_.accel.intersect(rays.data(), hits.data(), e - b, true);
    for (size_t i = b; i < e; ++i) out[i] = of(filmPos[i], pixel[i], seeds[i], rays[i - b], hits[i - b]);
  });
}

}  // namespace rc
