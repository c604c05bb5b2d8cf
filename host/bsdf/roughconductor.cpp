// bsdf "roughconductor": microfacet reflection from a rough metal (Mitsuba 3 src/bsdfs/roughconductor.cpp).
//
// | parameter            | type        | default   | meaning                                        |
// |----------------------|-------------|-----------|------------------------------------------------|
// | distribution         | string      | beckmann  | "beckmann" or "ggx"                            |
// | alpha                | float / texture | 0.1   | isotropic roughness (> 0)                      |
// | alpha_u, alpha_v     | float / texture | —     | anisotropic roughness along the frame's t / b  |
// | sample_visible       | boolean     | true      | sample visible normals (else all normals)      |
// | material             | string      | none      | "none" = F ≡ 1; named presets unsupported      |
// | eta, k               | rgb / float | 0, 1      | complex relative IOR (eta 0, k 1 gives F ≡ 1)  |
// | specular_reflectance | rgb / float | 1         | multiplier s                                    |
//
// f(wo, wi) = s·F(wo·h)·D(h)·G1(wo,h)·G1(wi,h) / (4 cosθo cosθi), h = normalize(wo + wi).
// A texture on the roughness (Mitsuba's eval_1) makes the BSDF vary per point (Bsdf::at); s as a
// texture is a factor on the whole BSDF (bsdf/textured.h).
#include "bsdf/bsdf_params.h"
#include "bsdf/conductor_fresnel.h"
#include "bsdf/microfacet.h"
#include "bsdf/plugins.h"
#include "bsdf/alpha_family.h"
#include "bsdf/rough_textures.h"

namespace rc {
namespace {

class RoughConductorBsdf final : public Bsdf, public AlphaFamily {
 public:
  RoughConductorBsdf(const Microfacet& distr, const ConductorFresnel& fresnel, RoughnessTextures roughness)
      : distr_(distr), fresnel_(fresnel), roughness_(std::move(roughness)) {}

  Color eval(const Vec3& wo, const Vec3& wi) const override {
    if (!(wo.z > 0.0f && wi.z > 0.0f)) return Color(0.0f);
    return eval(wo, wi, distr_.halfTerms(wo, wi));
  }

  float pdf(const Vec3& wo, const Vec3& wi) const override {
    if (!(wo.z > 0.0f && wi.z > 0.0f)) return 0.0f;
    return pdf(wo, wi, distr_.halfTerms(wo, wi));
  }

  BsdfValue evalPdf(const Vec3& wo, const Vec3& wi) const override {
    if (!(wo.z > 0.0f && wi.z > 0.0f)) return BsdfValue{};
    const Microfacet::HalfTerms m = distr_.halfTerms(wo, wi);
    return BsdfValue{eval(wo, wi, m), pdf(wo, wi, m)};
  }

  std::optional<BsdfSample> sample(const Vec3& wo, float, const Vec2& u2) const override {
    if (!(wo.z > 0.0f)) return std::nullopt;
    const auto [m, pdfM] = distr_.sample(wo, u2);
    const Vec3 wi = 2.0f * glm::dot(wo, m) * m - wo;
    if (!(pdfM > 0.0f) || !(wi.z > 0.0f)) return std::nullopt;
    BsdfSample s;
    s.wi = wi;
    // Visible-normal sampling leaves only the shadowing term of the outgoing direction.
    const float weight = distr_.sampleVisible() ? distr_.smithG1(wi, m)
                                                : distr_.G(wo, wi, m) * glm::dot(wo, m) / (wo.z * m.z);
    s.pdf = pdfM / (4.0f * glm::dot(wi, m));
    if (!(s.pdf > 0.0f) || !std::isfinite(s.pdf)) return std::nullopt;
    s.weight = fresnel_.eval(glm::dot(wo, m)) * weight;
    s.lobe = kLobeGlossy;
    return s;
  }

  uint32_t lobes() const override { return kLobeGlossy; }
  float glossyAlpha() const override { return std::fmin(distr_.alphaU(), distr_.alphaV()); }
  bool isotropic() const override { return distr_.isotropic() && roughness_.isotropic(); }
  std::string parameterKey() const override {
    return "roughconductor(distr=" + distr_.key() + ";" + fresnel_.key() +
           (roughness_.textured() ? ";" + roughness_.key() : "") + ")";
  }
  std::string typeName() const override { return "roughconductor"; }

  bool spatiallyVarying() const override { return roughness_.textured(); }
  BsdfPtr at(const TexturePoint& uv) const override {
    if (!roughness_.textured()) return nullptr;
    auto point = std::make_shared<RoughConductorBsdf>(roughness_.distributionAt(distr_, uv), fresnel_,
                                                      RoughnessTextures());
    point->id = id;
    return point;
  }

  bool variesOnlyInAlpha() const override { return roughness_.textured() && roughness_.isotropic() && distr_.isotropic(); }
  std::pair<float, float> alphaRange() const override { return roughness_.range(distr_); }
  float alphaAt(const TexturePoint& uv) const override { return roughness_.distributionAt(distr_, uv).alphaU(); }
  BsdfPtr withAlpha(float alpha) const override {
    auto node = std::make_shared<RoughConductorBsdf>(Microfacet(distr_.type(), alpha, alpha, distr_.sampleVisible()),
                                                     fresnel_, RoughnessTextures());
    node->id = id;
    return node;
  }

 private:
  // eval and pdf from the half vector's terms (wo.z > 0, wi.z > 0).
  Color eval(const Vec3& wo, const Vec3& wi, const Microfacet::HalfTerms& m) const {
    if (m.d == 0.0f) return Color(0.0f);
    const float g = m.g1o * distr_.smithG1(wi, m.h);
    return fresnel_.eval(glm::dot(wo, m.h)) * (m.d * g / (4.0f * wo.z));
  }
  float pdf(const Vec3& wo, const Vec3& wi, const Microfacet::HalfTerms& m) const {
    if (!(glm::dot(wo, m.h) > 0.0f && glm::dot(wi, m.h) > 0.0f)) return 0.0f;
    // Jacobian of the reflection map dωm/dωi = 1/(4 |wi·m|).
    if (distr_.sampleVisible()) return m.d * m.g1o / (4.0f * wo.z);
    return distr_.pdf(wo, m.h) / (4.0f * glm::dot(wi, m.h));
  }

  Microfacet distr_;
  ConductorFresnel fresnel_;
  RoughnessTextures roughness_;
};

}  // namespace

std::shared_ptr<Bsdf> createRoughConductorBsdf(const Properties& props, const std::vector<BsdfPtr>&,
                                               const BsdfTextures& textures) {
  const Microfacet distr = readMicrofacet(props, true);
  return std::make_shared<RoughConductorBsdf>(distr, readConductorFresnel(props), readRoughnessTextures(textures));
}

}  // namespace rc
