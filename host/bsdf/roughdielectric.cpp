// bsdf "roughdielectric": rough interface between two dielectrics, e.g. ground glass — microfacet
// reflection and refraction after Walter et al. 2007 (Mitsuba 3 src/bsdfs/roughdielectric.cpp).
//
// | parameter              | type             | default        | meaning                                      |
// |------------------------|------------------|----------------|----------------------------------------------|
// | int_ior                | float / IOR name | bk7 (1.5046)   | interior IOR (behind the normal)             |
// | ext_ior                | float / IOR name | air (1.000277) | exterior IOR; must differ from int_ior       |
// | specular_reflectance   | rgb / float      | 1              | reflection multiplier                        |
// | specular_transmittance | rgb / float      | 1              | transmission multiplier                      |
// | distribution           | string           | beckmann       | "beckmann" or "ggx"                          |
// | alpha                  | float / texture  | 0.1            | isotropic roughness (> 0)                    |
// | alpha_u, alpha_v       | float / texture  | —              | anisotropic roughness along the frame's t / b |
// | sample_visible         | boolean          | true           | sample visible normals (else all normals)    |
//
// With η the relative IOR across the interface seen from wo (int/ext outside, ext/int inside) and
// the generalized half vector m = ±normalize(wo + η_r·wi) (η_r = 1 for reflection, η otherwise),
// pointing to the normal's side:
//   reflection   f·|cosθi| = s_r·F(wo·m)·D(m)·G(wo,wi,m) / (4|cosθo|)
//   transmission f·|cosθi| = s_t·(1/η²)·η²·(1 − F)·D·G·|wo·m|·|wi·m| / (|cosθo|·(wo·m + η·wi·m)²)
// (radiance transport: the 1/η² solid-angle compression of Mitsuba's radiance mode cancels the η²
// of Walter's BTDF). Two-sided by nature. Sampling picks a microfacet normal (visible normals of
// the distribution seen from the side of wo), then reflection with probability F, refraction with
// 1 − F; the pdf is that of pdf(). With sample_visible = false the normals come from the
// distribution with α scaled by 1.2 − 0.2·√|cosθo| (Walter's trick, as Mitsuba) and the weight is
// eval/pdf (Mitsuba's weight there omits the ratio of the scaled to the unscaled D).
// A texture on alpha/alpha_u/alpha_v makes the BSDF vary over the surface (Bsdf::at).
#include "bsdf/bsdf_params.h"
#include "bsdf/fresnel.h"
#include "bsdf/microfacet.h"
#include "bsdf/plugins.h"
#include "bsdf/rough_textures.h"
#include "bsdf/warp.h"
#include "core/error.h"

namespace rc {
namespace {


class RoughDielectricBsdf final : public Bsdf {
 public:
  RoughDielectricBsdf(const Microfacet& distr, const DielectricParams& params, RoughnessTextures roughness)
      : distr_(distr), params_(params), invEta_(1.0f / params.eta), roughness_(std::move(roughness)) {}

  Color eval(const Vec3& wo, const Vec3& wi) const override {
    const float cosO = wo.z, cosI = wi.z;
    if (cosO == 0.0f || !std::isfinite(cosO)) return Color(0.0f);
    const bool reflect = cosO * cosI > 0.0f;
    const float eta = cosO > 0.0f ? params_.eta : invEta_;
    const Vec3 m = generalizedHalfVector(wo, wi, reflect, eta);
    const float d = distr_.D(m);
    if (d == 0.0f) return Color(0.0f);
    const float f = fresnelDielectric(glm::dot(wo, m), params_.eta).r;
    const float g = distr_.G(wo, wi, m);
    if (reflect) return params_.reflectance * (f * d * g / (4.0f * std::fabs(cosO)));
    const float dotOM = glm::dot(wo, m), dotIM = glm::dot(wi, m), denom = dotOM + eta * dotIM;
    const float value = std::fabs((1.0f - f) * d * g * dotOM * dotIM / (cosO * denom * denom));
    return params_.transmittance * value;
  }

  float pdf(const Vec3& wo, const Vec3& wi) const override {
    const float cosO = wo.z, cosI = wi.z;
    if (cosO == 0.0f || !std::isfinite(cosO)) return 0.0f;
    const bool reflect = cosO * cosI > 0.0f;
    const float eta = cosO > 0.0f ? params_.eta : invEta_;
    const Vec3 m = generalizedHalfVector(wo, wi, reflect, eta);
    const float dotOM = glm::dot(wo, m), dotIM = glm::dot(wi, m);
    // The side tests of smithG1 (eval and sample give zero there), replicated.
    if (!(dotOM * cosO > 0.0f && dotIM * cosI > 0.0f)) return 0.0f;
    const float denom = dotOM + eta * dotIM;
    const float jacobian = reflect ? 1.0f / (4.0f * dotIM) : eta * eta * dotIM / (denom * denom);
    float prob = samplingDistribution(cosO).pdf(mulSign(wo, cosO), m);
    const float f = fresnelDielectric(dotOM, params_.eta).r;
    prob *= reflect ? f : 1.0f - f;
    const float result = std::fabs(prob * jacobian);
    return std::isfinite(result) ? result : 0.0f;
  }

  std::optional<BsdfSample> sample(const Vec3& wo, float u1, const Vec2& u2) const override {
    const float cosO = wo.z;
    if (cosO == 0.0f || !std::isfinite(cosO)) return std::nullopt;
    const auto [m, pdfM] = samplingDistribution(cosO).sample(mulSign(wo, cosO), u2);
    if (!(pdfM > 0.0f)) return std::nullopt;
    const float dotOM = glm::dot(wo, m);
    const FresnelDielectric fr = fresnelDielectric(dotOM, params_.eta);
    BsdfSample s;
    float jacobian;
    if (u1 <= fr.r) {
      s.wi = reflectAbout(wo, m);
      s.weight = params_.reflectance;
      s.lobe = kLobeGlossy;
      s.eta = 1.0f;
      s.pdf = pdfM * fr.r;
      jacobian = 1.0f / (4.0f * glm::dot(s.wi, m));
    } else {
      // Refraction about m: wi = m·(wo·m·η_ti + cos θt) − wo·η_ti.
      s.wi = m * (dotOM * fr.etaTi + fr.cosThetaT) - wo * fr.etaTi;
      s.weight = params_.transmittance * (fr.etaTi * fr.etaTi);
      s.lobe = kLobeGlossy | kLobeTransmission;
      s.eta = fr.etaIt;
      s.pdf = pdfM * (1.0f - fr.r);
      const float denom = dotOM + fr.etaIt * glm::dot(s.wi, m);
      jacobian = fr.etaIt * fr.etaIt * glm::dot(s.wi, m) / (denom * denom);
    }
    s.pdf = std::fabs(s.pdf * jacobian);
    // A direction on the wrong side of the macro-surface for the chosen lobe has G = 0.
    const bool sideOk = (s.lobe & kLobeTransmission) ? s.wi.z * cosO < 0.0f : s.wi.z * cosO > 0.0f;
    if (!sideOk || !(s.pdf > 0.0f) || !std::isfinite(s.pdf)) return std::nullopt;
    if (distr_.sampleVisible()) {
      s.weight *= distr_.smithG1(s.wi, m);
    } else {
      const float p = pdf(wo, s.wi);
      if (!(p > 0.0f)) return std::nullopt;
      s.pdf = p;
      s.weight = eval(wo, s.wi) / p;
    }
    if (!(maxComponent(s.weight) > 0.0f) || !isFinite(s.weight)) return std::nullopt;
    return s;
  }

  uint32_t lobes() const override { return kLobeGlossy | kLobeTransmission; }
  float glossyAlpha() const override { return std::fmin(distr_.alphaU(), distr_.alphaV()); }
  bool isotropic() const override { return distr_.isotropic() && roughness_.isotropic(); }
  std::string parameterKey() const override {
    return "roughdielectric(distr=" + distr_.key() + ";" + roughness_.key() + ";" + params_.key() + ")";
  }
  std::string typeName() const override { return "roughdielectric"; }

  bool spatiallyVarying() const override { return roughness_.textured(); }
  BsdfPtr at(const TexturePoint& uv) const override {
    if (!roughness_.textured()) return nullptr;
    auto point = std::make_shared<RoughDielectricBsdf>(roughness_.distributionAt(distr_, uv), params_,
                                                       RoughnessTextures());
    point->id = id;
    return point;
  }

 private:
  Microfacet samplingDistribution(float cosO) const {
    if (distr_.sampleVisible()) return distr_;
    const float scale = 1.2f - 0.2f * std::sqrt(std::fabs(cosO));
    return Microfacet(distr_.type(), distr_.alphaU() * scale, distr_.alphaV() * scale, false);
  }

  Microfacet distr_;
  DielectricParams params_;
  float invEta_;
  RoughnessTextures roughness_;
};

}  // namespace

std::shared_ptr<Bsdf> createRoughDielectricBsdf(const Properties& props, const std::vector<BsdfPtr>&,
                                                const BsdfTextures& textures) {
  const DielectricParams params = readDielectricParams(props);
  if (params.eta == 1.0f)
    throwParamError(props, props.has("int_ior") ? "int_ior" : "ext_ior",
                    "the interior and exterior indices of refraction must differ");
  const Microfacet distr = readMicrofacet(props, true);
  return std::make_shared<RoughDielectricBsdf>(distr, params, readRoughnessTextures(textures));
}

}  // namespace rc
