// bsdf "mask": alpha cut-out around a nested BSDF (Mitsuba 3 src/bsdfs/mask.cpp).
//
// | parameter | type            | default | meaning                                                   |
// |-----------|-----------------|---------|-----------------------------------------------------------|
// | opacity   | float / texture | 0.5     | o: share of the surface that is there (clamped to [0, 1]) |
//
// One nested BSDF. f = o·f_nested; a ray passes through unchanged with probability 1 − o (wi = −wo,
// weight 1, a Dirac transmission like the null BSDF), else the nested BSDF is sampled with u1/o,
// keeping its weight, with pdf o·pdf_nested. As in Mitsuba's path integrator, shadow rays are
// blocked by the surface wherever it is (the cut-out shows in what the path continues to, not in
// visibility tests). A texture on opacity (Mitsuba's eval_1: luminance) or a nested BSDF that varies
// over the surface or carries a texture factor (Bsdf::tint, which must not scale the pass-through)
// make the mask vary per point (Bsdf::at): its point BSDF holds the opacity and the nested BSDF there.
#include "bsdf/bsdf_params.h"
#include "bsdf/pass_through.h"
#include "bsdf/plugins.h"
#include "bsdf/rough_textures.h"
#include "bsdf/textured.h"

namespace rc {
namespace {

class MaskBsdf final : public Bsdf {
 public:
  MaskBsdf(float opacity, TexturePtr opacityTexture, BsdfPtr nested)
      : opacity_(glm::clamp(opacity, 0.0f, 1.0f)), opacityTexture_(std::move(opacityTexture)), nested_(std::move(nested)) {}

  Color eval(const Vec3& wo, const Vec3& wi) const override { return opacity_ * nested_->eval(wo, wi); }
  float pdf(const Vec3& wo, const Vec3& wi) const override { return opacity_ * nested_->pdf(wo, wi); }
  std::optional<BsdfSample> sample(const Vec3& wo, float u1, const Vec2& u2) const override {
    if (!(u1 < opacity_)) return passThroughSample(wo);
    auto s = nested_->sample(wo, glm::clamp(u1 / opacity_, 0.0f, 0.99999994f), u2);
    if (!s) return std::nullopt;
    // Chosen with probability o, the nested part o·f keeps the nested weight.
    if (!(s->lobe & kLobeDelta)) s->pdf *= opacity_;
    return s;
  }
  uint32_t lobes() const override {
    uint32_t l = opacity_ > 0.0f || opacityTexture_ ? nested_->lobes() : 0u;
    if (opacity_ < 1.0f || opacityTexture_) l |= kLobeDelta | kLobeTransmission;
    return l;
  }
  // Mitsuba: 1 − o·(1 − the nested surface's own pass-through).
  Color nullTransmission() const override { return Color(1.0f) - opacity_ * (Color(1.0f) - nested_->nullTransmission()); }
  float glossyAlpha() const override { return nested_->glossyAlpha(); }
  bool isotropic() const override { return nested_->isotropic(); }
  std::string parameterKey() const override {
    return "mask(opacity=" + hexFloat(opacity_) + (opacityTexture_ ? ";" + textureFingerprint(*opacityTexture_) : "") +
           ";" + nested_->parameterKey() + ")";
  }
  std::string typeName() const override { return "mask"; }

  bool spatiallyVarying() const override {
    return opacityTexture_ || nested_->spatiallyVarying() || nested_->tinted();
  }
  BsdfPtr at(const TexturePoint& uv) const override {
    if (!spatiallyVarying()) return nullptr;
    const float opacity = opacityTexture_ ? textureValue1(*opacityTexture_, uv) : opacity_;
    BsdfPtr holder;
    const Bsdf& nestedHere = bsdfAt(*nested_, uv, holder);
    BsdfPtr nested = holder ? holder : nested_;
    if (nestedHere.tinted()) nested = bakeTint(nested, uv);
    auto point = std::make_shared<MaskBsdf>(opacity, nullptr, std::move(nested));
    point->id = id;
    return point;
  }

 private:
  float opacity_;
  TexturePtr opacityTexture_;
  BsdfPtr nested_;
};

}  // namespace

std::shared_ptr<Bsdf> createMaskBsdf(const Properties& props, const std::vector<BsdfPtr>& nested,
                                     const BsdfTextures& textures) {
  const Color c = props.getColor("opacity", Color(0.5f));
  const float opacity = luminance(c);
  if (!std::isfinite(opacity)) throwParamError(props, "opacity", "must be finite");
  return std::make_shared<MaskBsdf>(opacity, textureOf(textures, "opacity"), nested.at(0));
}

}  // namespace rc
