#include "render/hidden_emitters.h"

namespace rc {

namespace {
// Each step leaves the surface it found along the same direction, so the walk ends; the bound only
// guards against a degenerate stack of coincident emitters (a ray that kept finding one would render
// as the hidden background instead of hanging the render).
constexpr int kMaxEmitterCrossings = 1024;
}  // namespace

bool onAreaEmitter(const Scene& scene, const Hit& hit) {
  return hit.valid() && hit.emitter >= 0 && hit.emitter < static_cast<int>(scene.emitters.size()) &&
         scene.emitters[hit.emitter].type == EmitterType::Area;
}

Hit behindAreaEmitters(const RenderContext& ctx, const Ray& cameraRay, const Hit& hit) {
  Hit behind = hit;
  for (int crossing = 0; onAreaEmitter(ctx.scene, behind); ++crossing) {
    if (crossing == kMaxEmitterCrossings) return Hit{};
    const Ray next = Accel::spawnRay(behind, cameraRay.d);
    behind = ctx.accel.intersect(next);
    if (behind.valid()) behind.t = glm::dot(behind.p - cameraRay.o, cameraRay.d) / glm::dot(cameraRay.d, cameraRay.d);
  }
  return behind;
}

}  // namespace rc
