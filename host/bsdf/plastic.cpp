// bsdf "plastic": smooth dielectric coating over a diffuse base (Mitsuba 3 src/bsdfs/plastic.cpp).
//
// | parameter            | type               | default       | meaning                                    |
// |----------------------|--------------------|---------------|--------------------------------------------|
// | diffuse_reflectance  | rgb / float / texture | 0.5        | ρ of the base layer                         |
// | specular_reflectance | rgb / float / texture | 1          | multiplier s of the coating's reflection    |
// | int_ior              | float / IOR name   | polypropylene (1.49) | interior IOR                        |
// | ext_ior              | float / IOR name   | air (1.000277)       | exterior IOR                        |
// | nonlinear            | boolean            | false         | ρ/(1 − ρ·Fdr) instead of ρ/(1 − Fdr)        |
//
// Delta reflection s·F(θo) plus a diffuse lobe that accounts for the light trapped under the coating:
//   f_d·cosθi = ρ/(1 − Fdr_int)·(1/η²)·(1 − F(θo))·(1 − F(θi))·cosθi/π, η = int/ext,
// Fdr_int = fresnelDiffuseReflectance(1/η). Lobe choice: p_spec ∝ F(θo)·w_s, p_diff ∝ (1 − F(θo))·(1 − w_s),
// w_s = mean(s)/(mean(ρ) + mean(s)). A texture on ρ or s makes the BSDF vary per point (Bsdf::at);
// w_s stays that of the textures' means, as in Mitsuba.
// Layers (Bsdf::baseLayer/coatLayer): the coat is the delta reflection s·F(θo) alone (always
// sampled), the base f_d, cosine-sampled.
#include "bsdf/bsdf_layer.h"
#include "bsdf/bsdf_params.h"
#include "bsdf/fresnel.h"
#include "bsdf/plastic_params.h"
#include "bsdf/plugins.h"
#include "bsdf/rough_textures.h"
#include "bsdf/warp.h"

namespace rc {
namespace {

class PlasticBsdf final : public Bsdf {
 public:
  explicit PlasticBsdf(const PlasticParams& p)
      : eta_(p.eta), nonlinear_(p.nonlinear), diffuseTexture_(p.diffuseTexture), specularTexture_(p.specularTexture) {
    invEta2_ = 1.0f / (eta_ * eta_);
    fdrInt_ = fresnelDiffuseReflectance(1.0f / eta_);
    specularSamplingWeight_ = p.specularSamplingWeight();
    setReflectances(p.diffuse, p.specular);
    layers_.bind(*this, kLobeDelta);
  }

  Color eval(const Vec3& wo, const Vec3& wi) const override {
    if (!(wo.z > 0.0f && wi.z > 0.0f)) return Color(0.0f);
    const float fo = fresnelDielectric(wo.z, eta_).r, fi = fresnelDielectric(wi.z, eta_).r;
    return diffuseScaled_ * (squareToCosineHemispherePdf(wi) * invEta2_ * (1.0f - fo) * (1.0f - fi));
  }
  float pdf(const Vec3& wo, const Vec3& wi) const override {
    if (!(wo.z > 0.0f && wi.z > 0.0f)) return 0.0f;
    return squareToCosineHemispherePdf(wi) * probDiffuse(fresnelDielectric(wo.z, eta_).r);
  }
  std::optional<BsdfSample> sample(const Vec3& wo, float u1, const Vec2& u2) const override {
    if (!(wo.z > 0.0f)) return std::nullopt;
    const float fo = fresnelDielectric(wo.z, eta_).r;
    const float pDiff = probDiffuse(fo), pSpec = 1.0f - pDiff;
    BsdfSample s;
    if (u1 < pSpec) {
      s.wi = reflectZ(wo);
      s.pdf = 0.0f;
      s.weight = specular_ * (fo / pSpec);
      s.lobe = kLobeDelta;
      return s;
    }
    s.wi = squareToCosineHemisphere(u2);
    s.pdf = pDiff * squareToCosineHemispherePdf(s.wi);
    if (!(s.pdf > 0.0f)) return std::nullopt;
    const float fi = fresnelDielectric(s.wi.z, eta_).r;
    s.weight = diffuseScaled_ * (invEta2_ * (1.0f - fo) * (1.0f - fi) / pDiff);
    s.lobe = kLobeDiffuse;
    return s;
  }
  uint32_t lobes() const override { return kLobeDiffuse | kLobeDelta; }
  std::string parameterKey() const override {
    return "plastic(diffuse_reflectance=" + hexColor(diffuse_) + ";specular_reflectance=" + hexColor(specular_) +
           ";eta=" + hexFloat(eta_) + ";nonlinear=" + (nonlinear_ ? "1" : "0") +
           (diffuseTexture_ ? ";diffuse_texture=" + textureFingerprint(*diffuseTexture_) : "") +
           (specularTexture_ ? ";specular_texture=" + textureFingerprint(*specularTexture_) : "") + ")";
  }
  std::string typeName() const override { return "plastic"; }
  const Bsdf* baseLayer() const override { return layers_.base.get(); }
  const Bsdf* coatLayer() const override { return layers_.coat.get(); }
  // The terms as BSDFs of their own (bsdf/bsdf_layer.h): the delta coat s·F(θo) always taken,
  // the base cosine-sampled.
  Color layerEval(bool coat, const Vec3& wo, const Vec3& wi) const { return coat ? Color(0.0f) : eval(wo, wi); }
  float layerPdf(bool coat, const Vec3& /*wo*/, const Vec3& wi) const {
    return coat ? 0.0f : squareToCosineHemispherePdf(wi);
  }
  std::optional<BsdfSample> layerSample(bool coat, const Vec3& wo, const Vec2& u2) const {
    BsdfSample s;
    if (coat) {
      s.wi = reflectZ(wo);
      s.weight = specular_ * fresnelDielectric(wo.z, eta_).r;
      s.lobe = kLobeDelta;
      return s;
    }
    s.wi = squareToCosineHemisphere(u2);
    s.pdf = squareToCosineHemispherePdf(s.wi);
    if (!(s.pdf > 0.0f)) return std::nullopt;
    s.weight = eval(wo, s.wi) / s.pdf;
    s.lobe = kLobeDiffuse;
    return s;
  }

  bool spatiallyVarying() const override { return diffuseTexture_ || specularTexture_; }
  BsdfPtr at(const TexturePoint& uv) const override {
    if (!spatiallyVarying()) return nullptr;
    auto point = std::make_shared<PlasticBsdf>(*this);
    point->diffuseTexture_ = point->specularTexture_ = nullptr;
    point->setReflectances(diffuseTexture_ ? diffuseTexture_->eval(uv) : diffuse_,
                           specularTexture_ ? specularTexture_->eval(uv) : specular_);
    point->layers_.bind(*point, layers_.coat->lobes());
    return point;
  }

 private:
  void setReflectances(const Color& diffuse, const Color& specular) {
    diffuse_ = diffuse;
    specular_ = specular;
    const Color denom = nonlinear_ ? Color(1.0f) - diffuse * fdrInt_ : Color(1.0f - fdrInt_);
    diffuseScaled_ = diffuse / denom;
  }

  float probDiffuse(float fo) const {
    const float pSpec = fo * specularSamplingWeight_, pDiff = (1.0f - fo) * (1.0f - specularSamplingWeight_);
    const float sum = pSpec + pDiff;
    return sum > 0.0f ? pDiff / sum : 0.0f;  // sum = 0 only for a black, index-matched coating
  }

  Color diffuse_{0.5f}, specular_{1.0f};
  float eta_;
  bool nonlinear_;
  TexturePtr diffuseTexture_, specularTexture_;
  float invEta2_ = 1.0f, fdrInt_ = 0.0f, specularSamplingWeight_ = 0.5f;
  Color diffuseScaled_{0.0f};
  BsdfLayers<PlasticBsdf> layers_;  // bound to this object (a copy binds its own)
};

}  // namespace

std::shared_ptr<Bsdf> createPlasticBsdf(const Properties& props, const std::vector<BsdfPtr>&,
                                        const BsdfTextures& textures) {
  return std::make_shared<PlasticBsdf>(readPlasticParams(props, textures));
}

}  // namespace rc
