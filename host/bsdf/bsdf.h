#pragma once
// BSDF interface. All directions are unit vectors in the local shading frame (z = shading normal).
// Naming follows the light-transport convention used by pbrt: `wo` points toward the viewer (the
// direction light leaves along), `wi` toward the light (the direction light arrives from).
// One-sided BSDFs (everything except `twosided` wrappers and `dielectric`) are black unless
// wo.z > 0 and (for reflection) wi.z > 0, exactly as Mitsuba 3.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "core/frame.h"
#include "core/math.h"
#include "texture/texture.h"

namespace rc {

class Bsdf;

// What a BSDF that perturbs the shading frame (normalmap, bumpmap) reads of its surface point, in
// the local coordinates of the unperturbed shading frame (z = the interpolated shading normal).
struct FramePoint {
  TexturePoint uv;
  Vec3 ng{0, 0, 1};              // geometric normal
  Vec3 dpdu{0.0f}, dpdv{0.0f};   // surface partials along u and v (zero where the shape has none)
  Vec3 wo{0, 0, 1};              // toward the viewer
};

enum BsdfLobe : uint32_t {
  kLobeDiffuse = 1u << 0,  // Lambertian-like, view-independent
  kLobeGlossy = 1u << 1,   // rough microfacet
  kLobeDelta = 1u << 2,    // Dirac (smooth conductor/dielectric/plastic specular part)
  kLobeTransmission = 1u << 3,
  // Set beside kLobeDelta | kLobeTransmission on a sample that passes through the surface unchanged
  // (Mitsuba's BSDFFlags::Null: the null BSDF, a mask's holes); Mitsuba's volpath does not count
  // such a crossing as a scattering vertex.
  kLobeNull = 1u << 4,
};

// eval() and pdf() of one pair of directions (Bsdf::evalPdf).
struct BsdfValue {
  Color f{0.0f};
  float pdf = 0.0f;
};

struct BsdfSample {
  Vec3 wi;              // sampled incoming direction (local)
  Color weight{0.0f};   // f·|cos θi| / pdf (for a delta lobe: the full throughput factor)
  float pdf = 0.0f;     // solid-angle density of the continuous part; 0 for a delta sample
  uint32_t lobe = 0;    // which lobe produced it (one BsdfLobe bit; a pass-through adds kLobeNull)
  float eta = 1.0f;     // relative IOR crossed (dielectric transmission), else 1
};

// Which BSDFs a wave of the path tracer shades as a group in vector passes (render/diffuse_shading.h),
// with the parameters those passes read; None: the lane is shaded through the virtual calls below.
enum class BsdfBatchKind : uint8_t { None, Diffuse };
struct BsdfBatchParams {
  BsdfBatchKind kind = BsdfBatchKind::None;
  Color reflectance{0.0f};  // Diffuse: ρ
};

class Bsdf {
 public:
  virtual ~Bsdf() = default;

  // f(wo, wi)·|cos θi|, excluding Dirac components.
  virtual Color eval(const Vec3& wo, const Vec3& wi) const = 0;
  // Solid-angle pdf with which sample() returns wi for the continuous lobes (0 for delta-only).
  virtual float pdf(const Vec3& wo, const Vec3& wi) const = 0;
  // Both at once (Mitsuba's eval_pdf), bit for bit the values of eval() and pdf(): a BSDF whose two
  // share work (a microfacet lobe's half vector, D and G1 of the viewer) overrides it to do it once.
  virtual BsdfValue evalPdf(const Vec3& wo, const Vec3& wi) const { return BsdfValue{eval(wo, wi), pdf(wo, wi)}; }
  // Importance-samples wi; u1 picks a lobe, u2 the direction. Empty when no valid sample.
  virtual std::optional<BsdfSample> sample(const Vec3& wo, float u1, const Vec2& u2) const = 0;

  virtual uint32_t lobes() const = 0;  // BsdfLobe bits present
  // Set only by a BSDF that is the same everywhere, keeps the hit's frame and has no tint: its
  // batched shading then needs nothing but these parameters.
  virtual BsdfBatchParams batchParams() const { return {}; }
  bool hasDelta() const { return lobes() & kLobeDelta; }
  bool isDiffuseOnly() const { return lobes() == kLobeDiffuse; }

  // Sharpness of the narrowest glossy lobe as an effective microfacet alpha (min of alpha_u/v);
  // +∞ when there is no glossy lobe. Used to choose the technique and SH order per material.
  virtual float glossyAlpha() const { return INFINITY; }
  // True when eval is invariant under rotation of (wo, wi) about the normal.
  virtual bool isotropic() const { return true; }

  // Canonical text of the type and every parameter value (hex floats): the key of cached
  // BRDF coefficient tables. Two BSDFs with equal keys have identical eval().
  virtual std::string parameterKey() const = 0;
  virtual std::string typeName() const = 0;

  // A colour factor on the whole BSDF at surface coordinates uv: a texture on a parameter that
  // scales every value (diffuse `reflectance`, a conductor's `specular_reflectance`). eval, pdf and
  // sample describe the BSDF with that factor 1, so coefficient tables stay per material; callers
  // multiply what leaves the shading point by tint(). `wo` (local) selects the side of a twosided.
  virtual Color tint(const TexturePoint& /*uv*/, const Vec3& /*wo*/) const { return Color(1.0f); }
  virtual bool tinted() const { return false; }

  // A texture on a parameter that is not a factor on the whole BSDF (a roughness, plastic's
  // diffuse_reflectance, a mask's opacity) makes the BSDF differ from point to point: at(uv) builds
  // the BSDF at surface coordinates uv (uniform, with the textures' values there). The BSDF itself
  // then describes the material with each textured parameter at the texture's mean. nullptr (the
  // default) means the BSDF is the same everywhere; use bsdfAt() below.
  virtual bool spatiallyVarying() const { return false; }
  virtual std::shared_ptr<const Bsdf> at(const TexturePoint& /*uv*/) const { return nullptr; }
  // Layered BSDFs (a dielectric coat over a diffuse base: plastic, roughplastic) as two BSDFs of
  // their own with eval = base.eval + coat.eval, each with its own pdf and sampling, so that an
  // integrator can estimate the lobes by different techniques (rcache serves the low-frequency
  // base from its records and samples the sharp coat). Both null when there is no such split;
  // the parts live as long as this BSDF.
  virtual const Bsdf* baseLayer() const { return nullptr; }
  virtual const Bsdf* coatLayer() const { return nullptr; }

  // normalmap / bumpmap: the BSDF turns the shading frame. perturbedFrame() is that frame at a
  // surface point as a rotation of the unperturbed one (its axes in the unperturbed local
  // coordinates); eval, pdf and sample describe the nested BSDF in the perturbed frame (what BRDF
  // coefficient tables hold). atFrame() builds the BSDF at a point shaded in the perturbed frame:
  // the nested BSDF at uv with the factors Mitsuba applies in the unperturbed frame, whose normal
  // is `baseNormal` in the perturbed local coordinates. Callers: geometry/shading_frame.h.
  virtual bool perturbsFrame() const { return false; }
  virtual Frame perturbedFrame(const FramePoint& /*point*/) const { return Frame(); }
  virtual std::shared_ptr<const Bsdf> atFrame(const TexturePoint& /*uv*/, const Vec3& /*baseNormal*/) const { return nullptr; }
  // Seen from behind, the point's frame may be mirrored to the viewer (a twosided material, or one
  // that perturbs the frame of a twosided material).
  virtual bool isTwoSided() const { return false; }
  // Mitsuba's eval_null_transmission: the share of a shadow ray that passes the surface unchanged
  // (1 for the null BSDF, 1 − opacity for a mask, 0 for every surface that is there). Only the
  // volumetric path tracer lets shadow rays through (render/volpath.h), as Mitsuba's volpath does.
  virtual Color nullTransmission() const { return Color(0.0f); }

  std::string id;  // the scene's id attribute, or "<type>#<n>" when anonymous
};

using BsdfPtr = std::shared_ptr<const Bsdf>;

// The BSDF at a surface point: `bsdf` itself unless it varies over the surface (Bsdf::at); then the
// point's BSDF, which `holder` keeps alive.
inline const Bsdf& bsdfAt(const Bsdf& bsdf, const TexturePoint& uv, BsdfPtr& holder) {
  if (!bsdf.spatiallyVarying()) return bsdf;
  holder = bsdf.at(uv);
  return holder ? *holder : bsdf;
}

}  // namespace rc
