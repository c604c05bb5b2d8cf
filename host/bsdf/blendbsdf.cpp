// bsdf "blendbsdf": linear blend of two nested BSDFs (Mitsuba 3 src/bsdfs/blendbsdf.cpp).
//
// | parameter | type  | default | meaning                                               |
// |-----------|-------|---------|-------------------------------------------------------|
// | weight    | float / texture | 0.5 | w in [0, 1]: f = (1 − w)·f_first + w·f_second    |
//
// Two nested BSDFs. Sampling picks the second with probability w (u1 rescaled and reused), as
// Mitsuba. Unlike Mitsuba, which returns the chosen component's own weight and pdf, a continuous
// sample here reports the mixture pdf (1−w)p0 + w p1 and weight = eval/pdf of the mixture, so that
// sample() agrees with pdf() for MIS; the expected value is the same. Delta samples keep the
// component's weight (its selection probability cancels the blend factor). A texture on weight
// (Mitsuba's eval_1, clamped to [0, 1]) or a nested BSDF that varies makes the blend vary per point
// (Bsdf::at).
#include "bsdf/bsdf_params.h"
#include "bsdf/plugins.h"
#include "bsdf/rough_textures.h"
#include "core/error.h"

namespace rc {
namespace {

class BlendBsdf final : public Bsdf {
 public:
  BlendBsdf(float weight, BsdfPtr a, BsdfPtr b, TexturePtr weightTexture = nullptr)
      : w_(weight), a_(std::move(a)), b_(std::move(b)), weightTexture_(std::move(weightTexture)) {}

  Color eval(const Vec3& wo, const Vec3& wi) const override {
    return (1.0f - w_) * a_->eval(wo, wi) + w_ * b_->eval(wo, wi);
  }
  float pdf(const Vec3& wo, const Vec3& wi) const override {
    return (1.0f - w_) * a_->pdf(wo, wi) + w_ * b_->pdf(wo, wi);
  }
  std::optional<BsdfSample> sample(const Vec3& wo, float u1, const Vec2& u2) const override {
    const bool second = u1 <= w_ && w_ > 0.0f;
    const float prob = second ? w_ : 1.0f - w_;
    if (!(prob > 0.0f)) return std::nullopt;
    // Reuse u1 for the nested choice, rescaled to [0, 1) within the chosen interval.
    const float uNested = second ? u1 / w_ : (u1 - w_) / (1.0f - w_);
    auto s = (second ? b_ : a_)->sample(wo, glm::clamp(uNested, 0.0f, 0.99999994f), u2);
    if (!s) return std::nullopt;
    if (s->lobe & kLobeDelta) {
      // The blend's Dirac part is w_k·(component's); chosen with probability w_k, the two cancel
      // and the component's own weight is the throughput (as Mitsuba).
      s->pdf = 0.0f;
      return s;
    }
    s->pdf = pdf(wo, s->wi);
    if (!(s->pdf > 0.0f)) return std::nullopt;
    s->weight = eval(wo, s->wi) / s->pdf;
    return s;
  }
  uint32_t lobes() const override {
    uint32_t l = 0;
    if (w_ < 1.0f || weightTexture_) l |= a_->lobes();
    if (w_ > 0.0f || weightTexture_) l |= b_->lobes();
    return l;
  }
  float glossyAlpha() const override {
    return std::fmin(w_ < 1.0f || weightTexture_ ? a_->glossyAlpha() : INFINITY,
                     w_ > 0.0f || weightTexture_ ? b_->glossyAlpha() : INFINITY);
  }
  bool isotropic() const override { return a_->isotropic() && b_->isotropic(); }
  std::string parameterKey() const override {
    return "blendbsdf(weight=" + hexFloat(w_) + (weightTexture_ ? ":" + textureFingerprint(*weightTexture_) : "") +
           ";" + a_->parameterKey() + ";" + b_->parameterKey() + ")";
  }
  std::string typeName() const override { return "blendbsdf"; }
  bool spatiallyVarying() const override {
    return weightTexture_ || a_->spatiallyVarying() || b_->spatiallyVarying();
  }
  BsdfPtr at(const TexturePoint& uv) const override {
    if (!spatiallyVarying()) return nullptr;
    BsdfPtr a = a_->at(uv), b = b_->at(uv);
    const float w = weightTexture_ ? glm::clamp(textureValue1(*weightTexture_, uv), 0.0f, 1.0f) : w_;
    auto point = std::make_shared<BlendBsdf>(w, a ? a : a_, b ? b : b_);
    point->id = id;
    return point;
  }

 private:
  float w_;
  BsdfPtr a_, b_;
  TexturePtr weightTexture_;
};

}  // namespace

std::shared_ptr<Bsdf> createBlendBsdf(const Properties& props, const std::vector<BsdfPtr>& nested,
                                      const BsdfTextures& textures) {
  if (nested.size() != 2)
    throw Error("<bsdf type=\"blendbsdf\">: needs exactly two nested BSDFs, got " + std::to_string(nested.size()));
  for (const BsdfPtr& b : nested) {
    if (!b) throw Error("<bsdf type=\"blendbsdf\">: nested BSDF is null");
    // A texture factor on one of two blended BSDFs does not scale the blend as a whole.
    if (b->tinted())
      throw Error("<bsdf type=\"blendbsdf\">: a nested BSDF with a textured reflectance is not supported");
  }
  const float w = readFloatIn(props, "weight", 0.5f, 0.0f, 1.0f);
  return std::make_shared<BlendBsdf>(w, nested[0], nested[1], textureOf(textures, "weight"));
}

}  // namespace rc
