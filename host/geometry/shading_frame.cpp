#include "geometry/shading_frame.h"

namespace rc {

Frame perturbedShadingFrame(const Bsdf& material, const Hit& hit, const Vec3& woWorld) {
  const Frame base = hit.frame();
  FramePoint point;
  point.uv = hit.uv;
  point.ng = base.toLocal(hit.ng);
  point.dpdu = base.toLocal(hit.dpdu);
  point.dpdv = base.toLocal(hit.dpdv);
  point.wo = base.toLocal(woWorld);
  const Frame turn = material.perturbedFrame(point);
  return Frame(base.toWorld(turn.t), base.toWorld(turn.b), base.toWorld(turn.n));
}

const Bsdf& bsdfAt(const Bsdf& material, const Hit& hit, const Frame& frame, const Vec3& baseNormal, BsdfPtr& holder) {
  if (!material.perturbsFrame()) return bsdfAt(material, hit.uv, holder);
  holder = material.atFrame(hit.uv, frame.toLocal(baseNormal));
  return holder ? *holder : material;
}

}  // namespace rc
