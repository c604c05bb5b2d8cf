// bsdf "pplastic": Baek et al.'s polarised plastic (Mitsuba 3 src/bsdfs/pplastic.cpp), in RGB mode.
//
// | parameter            | type                  | default              | meaning                               |
// |----------------------|-----------------------|----------------------|---------------------------------------|
// | diffuse_reflectance  | rgb / float / texture | 0.5                  | ρ of the base layer                   |
// | specular_reflectance | rgb / float / texture | 1                    | multiplier s of the coating reflection |
// | int_ior              | float / IOR name      | polypropylene (1.49) | interior IOR                          |
// | ext_ior              | float / IOR name      | air (1.000277)       | exterior IOR                          |
// | eta                  | float                 | int_ior / ext_ior    | relative IOR (instead of the two)     |
// | distribution         | string                | beckmann             | "beckmann" or "ggx"                   |
// | alpha                | float                 | 0.1                  | roughness (or alpha_u and alpha_v)    |
// | sample_visible       | boolean               | true                 | visible-normal sampling               |
//
// Mitsuba's unpolarised branch (what its RGB variants render): no internal scattering, just
//   f·cosθi = s·F(wo·h)·D(h)·G/(4 cosθo) + ρ·(1 − F(cosθo))·(1 − F(cosθi))·cosθi/π,
// F the dielectric Fresnel reflectance at η. Sampling: the specular lobe with the fixed probability
// w_s = mean(s)/(mean(ρ) + mean(s)), else cosine; the pdf is the mixture (the specular density is
// D·G1(wo)/(4 cosθo) with visible normals, else pdf(m)/(4 wi·h), zero where wo·h or wi·h ≤ 0).
// A texture on ρ or s makes the BSDF vary per point (Bsdf::at); w_s stays that of the means.
#include "bsdf/bsdf_params.h"
#include "bsdf/coated_sample.h"
#include "bsdf/fresnel.h"
#include "bsdf/microfacet.h"
#include "bsdf/plugins.h"
#include "bsdf/rough_textures.h"
#include "bsdf/warp.h"

namespace rc {
namespace {

inline float channelMean(const Color& c) { return (c.r + c.g + c.b) / 3.0f; }

class PolarizedPlasticBsdf final : public Bsdf {
 public:
  PolarizedPlasticBsdf(const Microfacet& distr, const Color& diffuse, const Color& specular, float eta,
                       TexturePtr diffuseTexture, TexturePtr specularTexture)
      : distr_(distr), diffuse_(diffuse), specular_(specular), eta_(eta),
        diffuseTexture_(std::move(diffuseTexture)), specularTexture_(std::move(specularTexture)) {
    const float dMean = channelMean(diffuse), sMean = channelMean(specular);
    specularSamplingWeight_ = sMean / (dMean + sMean);
  }

  Color eval(const Vec3& wo, const Vec3& wi) const override {
    if (!(wo.z > 0.0f && wi.z > 0.0f)) return Color(0.0f);
    const Vec3 h = glm::normalize(wo + wi);
    const float f = fresnelDielectric(glm::dot(wo, h), eta_).r;
    Color value = specular_ * (f * distr_.D(h) * distr_.G(wo, wi, h) / (4.0f * wo.z));
    const float ro = fresnelDielectric(wo.z, eta_).r, ri = fresnelDielectric(wi.z, eta_).r;
    value += diffuse_ * ((1.0f - ro) * (1.0f - ri) * kInvPi * wi.z);
    return value;
  }

  float pdf(const Vec3& wo, const Vec3& wi) const override {
    if (!(wo.z > 0.0f && wi.z > 0.0f)) return 0.0f;
    const Vec3 h = glm::normalize(wo + wi);
    float spec = 0.0f;
    if (glm::dot(wo, h) > 0.0f && glm::dot(wi, h) > 0.0f) {
      if (distr_.sampleVisible()) spec = distr_.D(h) * distr_.smithG1(wo, h) / (4.0f * wo.z);
      else spec = distr_.pdf(wo, h) / (4.0f * glm::dot(wi, h));
    }
    return specularSamplingWeight_ * spec + (1.0f - specularSamplingWeight_) * squareToCosineHemispherePdf(wi);
  }

  std::optional<BsdfSample> sample(const Vec3& wo, float u1, const Vec2& u2) const override {
    return wo.z > 0.0f ? sampleCoatOrBase(*this, distr_, wo, u1 < specularSamplingWeight_, u2) : std::nullopt;
  }

  uint32_t lobes() const override { return kLobeDiffuse | kLobeGlossy; }
  float glossyAlpha() const override { return std::min(distr_.alphaU(), distr_.alphaV()); }
  bool isotropic() const override { return distr_.isotropic(); }
  std::string parameterKey() const override {
    return "pplastic(distr=" + distr_.key() + ";diffuse_reflectance=" + hexColor(diffuse_) +
           ";specular_reflectance=" + hexColor(specular_) + ";eta=" + hexFloat(eta_) +
           (diffuseTexture_ ? ";diffuse_texture=" + textureFingerprint(*diffuseTexture_) : "") +
           (specularTexture_ ? ";specular_texture=" + textureFingerprint(*specularTexture_) : "") + ")";
  }
  std::string typeName() const override { return "pplastic"; }

  bool spatiallyVarying() const override { return diffuseTexture_ || specularTexture_; }
  BsdfPtr at(const TexturePoint& uv) const override {
    if (!spatiallyVarying()) return nullptr;
    auto point = std::make_shared<PolarizedPlasticBsdf>(*this);
    point->diffuseTexture_ = point->specularTexture_ = nullptr;
    if (diffuseTexture_) point->diffuse_ = diffuseTexture_->eval(uv);
    if (specularTexture_) point->specular_ = specularTexture_->eval(uv);
    return point;
  }

 private:
  Microfacet distr_;
  Color diffuse_, specular_;
  float eta_;
  TexturePtr diffuseTexture_, specularTexture_;
  float specularSamplingWeight_ = 0.5f;
};

}  // namespace

std::shared_ptr<Bsdf> createPolarizedPlasticBsdf(const Properties& props, const std::vector<BsdfPtr>&,
                                                 const BsdfTextures& textures) {
  const Color diffuse = readReflectance(props, "diffuse_reflectance", 0.5f);
  const Color specular = readReflectance(props, "specular_reflectance", 1.0f);
  float eta;
  if (props.has("eta")) {
    if (props.has("int_ior") || props.has("ext_ior"))
      throwParamError(props, "eta", "give either 'eta' or 'int_ior'/'ext_ior', not both");
    eta = props.getFloat("eta", 1.0f);
    if (!(std::isfinite(eta) && eta > 0.0f)) throwParamError(props, "eta", "must be a finite number > 0");
  } else {
    const float intIor = readIor(props, "int_ior", "polypropylene");
    const float extIor = readIor(props, "ext_ior", "air");
    if (intIor == extIor) throwParamError(props, "int_ior", "the interior and exterior IOR must differ");
    eta = intIor / extIor;
  }
  if (channelMean(diffuse) + channelMean(specular) <= 0.0f)
    throwParamError(props, "diffuse_reflectance", "diffuse and specular reflectance are both zero");
  return std::make_shared<PolarizedPlasticBsdf>(readMicrofacet(props, true), diffuse, specular, eta,
                                                textureOf(textures, "diffuse_reflectance"),
                                                textureOf(textures, "specular_reflectance"));
}

}  // namespace rc
