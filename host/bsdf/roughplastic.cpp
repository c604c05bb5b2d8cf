// bsdf "roughplastic": rough dielectric coating over a diffuse base (Mitsuba 3 src/bsdfs/roughplastic.cpp).
//
// | parameter            | type             | default              | meaning                                |
// |----------------------|------------------|----------------------|----------------------------------------|
// | diffuse_reflectance  | rgb / float / texture | 0.5             | ρ of the base layer                     |
// | specular_reflectance | rgb / float / texture | 1               | multiplier s of the coating reflection  |
// | int_ior              | float / IOR name | polypropylene (1.49) | interior IOR                            |
// | ext_ior              | float / IOR name | air (1.000277)       | exterior IOR                            |
// | nonlinear            | boolean          | false                | ρ/(1 − ρ·R_int) instead of ρ/(1 − R_int) |
// | distribution         | string           | beckmann             | "beckmann" or "ggx" (isotropic only)    |
// | alpha                | float            | 0.1                  | roughness (> 0)                         |
// | sample_visible       | boolean          | true                 | visible-normal sampling                 |
//
// f·cosθi = s·F(wo·h)·D(h)·G/(4 cosθo)
//         + ρ/(1 − R_int)·(1/η²)·T(θo)·T(θi)·cosθi/π,
// where T(μ) is the rough interface's transmittance, tabulated at 64 values of μ = cosθ in [0, 1]
// and interpolated linearly, and R_int = 2∫ R_internal(μ) μ dμ (mean over the same 64 μ) the
// internal reflectance for light leaving the base — both computed at construction exactly as
// Mitsuba does (Gauss–Legendre quadrature over visible normals, see microfacet.h).
// Sampling: specular lobe with probability ∝ (1 − T(θo))·w_s, diffuse ∝ T(θo)·(1 − w_s),
// w_s = mean(s)/(mean(ρ) + mean(s)); the returned pdf is the mixture, weight = eval/pdf. A texture
// on ρ or s makes the BSDF vary per point (Bsdf::at); w_s stays that of the textures' means and α
// is a plain number, as in Mitsuba.
// Layers (Bsdf::baseLayer/coatLayer): the coat is the first term, sampled by its microfacet
// distribution alone; the base the second, cosine-sampled.
#include <array>
#include <map>
#include <memory>
#include <mutex>
#include <tuple>

#include "bsdf/bsdf_layer.h"
#include "bsdf/bsdf_params.h"
#include "bsdf/coated_sample.h"
#include "bsdf/fresnel.h"
#include "bsdf/microfacet.h"
#include "bsdf/plastic_params.h"
#include "bsdf/plugins.h"
#include "bsdf/rough_textures.h"
#include "bsdf/warp.h"

namespace rc {
namespace {

constexpr int kTransmittanceRes = 64;  // Mitsuba's MI_ROUGH_TRANSMITTANCE_RES


struct InterfaceTables {
  std::array<float, kTransmittanceRes> externalTransmittance{};
  float internalReflectance = 0.0f;
};

// The tables depend only on (distribution, α, η) and cost ~0.1–0.3 s (1.1 M visible-normal
// samples), so materials that share them — common in scenes and tests — compute them once.
std::shared_ptr<const InterfaceTables> interfaceTables(const Microfacet& distr, float eta) {
  static std::mutex mutex;
  static std::map<std::tuple<int, float, float>, std::shared_ptr<const InterfaceTables>> cache;
  const auto key = std::make_tuple(static_cast<int>(distr.type()), distr.alphaU(), eta);
  {
    std::lock_guard<std::mutex> lock(mutex);
    auto it = cache.find(key);
    if (it != cache.end()) return it->second;
  }
  auto tables = std::make_shared<InterfaceTables>();
  // Mitsuba tabulates with visible-normal sampling regardless of sample_visible.
  const Microfacet vis(distr.type(), distr.alphaU(), distr.alphaV(), true);
  double internal = 0.0;
  for (int i = 0; i < kTransmittanceRes; ++i) {
    const float mu = std::fmax(1e-6f, static_cast<float>(i) / static_cast<float>(kTransmittanceRes - 1));
    const Vec3 w(std::sqrt(1.0f - mu * mu), 0.0f, mu);
    tables->externalTransmittance[i] = static_cast<float>(microfacetTransmittance(vis, w, eta));
    internal += static_cast<float>(microfacetReflectance(vis, w, 1.0f / eta)) * mu;
  }
  // Mitsuba: 2·mean(R(μ_i)·μ_i) over the 64 nodes (not a trapezoid rule; kept for equality).
  tables->internalReflectance = static_cast<float>(internal / kTransmittanceRes * 2.0);
  std::lock_guard<std::mutex> lock(mutex);
  return cache.emplace(key, tables).first->second;
}

class RoughPlasticBsdf final : public Bsdf {
 public:
  RoughPlasticBsdf(const Microfacet& distr, const PlasticParams& p)
      : distr_(distr), eta_(p.eta), nonlinear_(p.nonlinear), diffuseTexture_(p.diffuseTexture),
        specularTexture_(p.specularTexture) {
    invEta2_ = 1.0f / (eta_ * eta_);
    specularSamplingWeight_ = p.specularSamplingWeight();
    tables_ = interfaceTables(distr, eta_);
    internalReflectance_ = tables_->internalReflectance;
    setReflectances(p.diffuse, p.specular);
    layers_.bind(*this, kLobeGlossy);
  }

  float externalTransmittance(float cosTheta) const {
    // Mitsuba's lerp_gather: linear interpolation over μ = i/63.
    const float x = cosTheta * (kTransmittanceRes - 1);
    const int index = std::min(static_cast<int>(x), kTransmittanceRes - 2);
    const float w1 = x - static_cast<float>(index);
    const auto& t = tables_->externalTransmittance;
    return (1.0f - w1) * t[index] + w1 * t[index + 1];
  }
  float internalReflectance() const { return internalReflectance_; }

  Color eval(const Vec3& wo, const Vec3& wi) const override {
    if (!(wo.z > 0.0f && wi.z > 0.0f)) return Color(0.0f);
    return evalCoat(wo, wi) + evalBase(wo, wi);
  }
  // The two terms of eval, for wo.z > 0 and wi.z > 0.
  Color evalCoat(const Vec3& wo, const Vec3& wi) const { return evalCoat(wo, wi, distr_.halfTerms(wo, wi)); }
  Color evalCoat(const Vec3& wo, const Vec3& wi, const Microfacet::HalfTerms& m) const {
    const float f = fresnelDielectric(glm::dot(wo, m.h), eta_).r;
    const float g = m.g1o * distr_.smithG1(wi, m.h);
    return specular_ * (f * m.d * g / (4.0f * wo.z));
  }
  Color evalBase(const Vec3& wo, const Vec3& wi) const {
    const float to = externalTransmittance(wo.z), ti = externalTransmittance(wi.z);
    return diffuseScaled_ * (kInvPi * invEta2_ * wi.z * to * ti);
  }

  float pdf(const Vec3& wo, const Vec3& wi) const override {
    if (!(wo.z > 0.0f && wi.z > 0.0f)) return 0.0f;
    return mixturePdf(wo, wi, pdfCoat(wo, wi));
  }
  BsdfValue evalPdf(const Vec3& wo, const Vec3& wi) const override {
    if (!(wo.z > 0.0f && wi.z > 0.0f)) return BsdfValue{};
    const Microfacet::HalfTerms m = distr_.halfTerms(wo, wi);
    return BsdfValue{evalCoat(wo, wi, m) + evalBase(wo, wi), mixturePdf(wo, wi, pdfCoat(wo, wi, m))};
  }
  // The sampling mixture's density given the coat's (wo.z > 0, wi.z > 0).
  float mixturePdf(const Vec3& wo, const Vec3& wi, float coatPdf) const {
    const float pSpec = probSpecular(wo.z), pDiff = 1.0f - pSpec;
    return pSpec * coatPdf + pDiff * squareToCosineHemispherePdf(wi);
  }
  // Density of the coat's microfacet sampling alone (wo.z > 0, wi.z > 0).
  float pdfCoat(const Vec3& wo, const Vec3& wi) const { return pdfCoat(wo, wi, distr_.halfTerms(wo, wi)); }
  float pdfCoat(const Vec3& wo, const Vec3& wi, const Microfacet::HalfTerms& m) const {
    if (distr_.sampleVisible()) return m.d * m.g1o / (4.0f * wo.z);
    return distr_.pdf(wo, m.h) / (4.0f * glm::dot(wi, m.h));
  }
  Vec3 sampleCoat(const Vec3& wo, const Vec2& u2) const { return reflectAbout(wo, distr_.sample(wo, u2).first); }

  // The terms as BSDFs of their own (bsdf/bsdf_layer.h): the coat sampled by its distribution,
  // the base by the cosine.
  Color layerEval(bool coat, const Vec3& wo, const Vec3& wi) const { return coat ? evalCoat(wo, wi) : evalBase(wo, wi); }
  float layerPdf(bool coat, const Vec3& wo, const Vec3& wi) const {
    return coat ? pdfCoat(wo, wi) : squareToCosineHemispherePdf(wi);
  }
  std::optional<BsdfSample> layerSample(bool coat, const Vec3& wo, const Vec2& u2) const {
    BsdfSample s;
    s.wi = coat ? sampleCoat(wo, u2) : squareToCosineHemisphere(u2);
    s.lobe = coat ? kLobeGlossy : kLobeDiffuse;
    if (!(s.wi.z > 0.0f)) return std::nullopt;
    s.pdf = layerPdf(coat, wo, s.wi);
    if (!(s.pdf > 0.0f) || !std::isfinite(s.pdf)) return std::nullopt;
    s.weight = layerEval(coat, wo, s.wi) / s.pdf;
    return s;
  }

  std::optional<BsdfSample> sample(const Vec3& wo, float u1, const Vec2& u2) const override {
    return wo.z > 0.0f ? sampleCoatOrBase(*this, distr_, wo, u1 < probSpecular(wo.z), u2) : std::nullopt;
  }

  uint32_t lobes() const override { return kLobeDiffuse | kLobeGlossy; }
  float glossyAlpha() const override { return distr_.alphaU(); }
  std::string parameterKey() const override {
    return "roughplastic(distr=" + distr_.key() + ";diffuse_reflectance=" + hexColor(diffuse_) +
           ";specular_reflectance=" + hexColor(specular_) + ";eta=" + hexFloat(eta_) +
           ";nonlinear=" + (nonlinear_ ? "1" : "0") +
           (diffuseTexture_ ? ";diffuse_texture=" + textureFingerprint(*diffuseTexture_) : "") +
           (specularTexture_ ? ";specular_texture=" + textureFingerprint(*specularTexture_) : "") + ")";
  }
  std::string typeName() const override { return "roughplastic"; }
  const Bsdf* baseLayer() const override { return layers_.base.get(); }
  const Bsdf* coatLayer() const override { return layers_.coat.get(); }

  bool spatiallyVarying() const override { return diffuseTexture_ || specularTexture_; }
  BsdfPtr at(const TexturePoint& uv) const override {
    if (!spatiallyVarying()) return nullptr;
    auto point = std::make_shared<RoughPlasticBsdf>(*this);  // shares the interface tables
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
    const Color denom =
        nonlinear_ ? Color(1.0f) - diffuse * internalReflectance_ : Color(1.0f - internalReflectance_);
    diffuseScaled_ = diffuse / denom;
  }

  float probSpecular(float cosThetaO) const {
    const float t = externalTransmittance(cosThetaO);
    const float pSpec = (1.0f - t) * specularSamplingWeight_, pDiff = t * (1.0f - specularSamplingWeight_);
    const float sum = pSpec + pDiff;
    return sum > 0.0f ? pSpec / sum : 0.0f;
  }

  Microfacet distr_;
  Color diffuse_{0.5f}, specular_{1.0f};
  float eta_;
  bool nonlinear_;
  TexturePtr diffuseTexture_, specularTexture_;
  float invEta2_ = 1.0f, specularSamplingWeight_ = 0.5f, internalReflectance_ = 0.0f;
  std::shared_ptr<const InterfaceTables> tables_;
  Color diffuseScaled_{0.0f};
  BsdfLayers<RoughPlasticBsdf> layers_;  // bound to this object (a copy binds its own)
};

}  // namespace

std::shared_ptr<Bsdf> createRoughPlasticBsdf(const Properties& props, const std::vector<BsdfPtr>&,
                                             const BsdfTextures& textures) {
  const PlasticParams params = readPlasticParams(props, textures);
  return std::make_shared<RoughPlasticBsdf>(readMicrofacet(props, false), params);
}

}  // namespace rc
