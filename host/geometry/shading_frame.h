#pragma once
// The frame a hit is shaded in and the BSDF it is shaded with, for both integrators and the radiance
// cache: the hit's frame (Hit::frame) unless its material perturbs it (normalmap, bumpmap:
// Bsdf::perturbsFrame), then that frame turned by the material at the point.
#include "bsdf/bsdf.h"
#include "geometry/accel.h"

namespace rc {

// `woWorld` points toward the viewer. Inline for the common case (the hit's own frame): every path
// vertex calls it, and a Frame returned through memory stalls the loads that read it back.
Frame perturbedShadingFrame(const Bsdf& material, const Hit& hit, const Vec3& woWorld);
inline Frame shadingFrame(const Bsdf& material, const Hit& hit, const Vec3& woWorld) {
  return material.perturbsFrame() ? perturbedShadingFrame(material, hit, woWorld) : hit.frame();
}

// The BSDF at `hit` shaded in `frame` (shadingFrame, or its mirror to the viewer): bsdfAt(material,
// hit.uv) for materials that keep the frame; for those that perturb it, the point BSDF with the
// unperturbed normal `baseNormal` (world: hit.ns, mirrored with `frame` where that is mirrored) in
// `frame`'s coordinates. `holder` keeps a point BSDF alive.
const Bsdf& bsdfAt(const Bsdf& material, const Hit& hit, const Frame& frame, const Vec3& baseNormal, BsdfPtr& holder);

}  // namespace rc
