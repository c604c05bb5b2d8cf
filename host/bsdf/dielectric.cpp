// bsdf "dielectric": smooth interface between two dielectrics, e.g. glass (Mitsuba 3 src/bsdfs/dielectric.cpp).
//
// | parameter              | type             | default        | meaning                         |
// |------------------------|------------------|----------------|---------------------------------|
// | int_ior                | float / IOR name | bk7 (1.5046)   | interior IOR (behind the normal) |
// | ext_ior                | float / IOR name | air (1.000277) | exterior IOR                    |
// | specular_reflectance   | rgb / float      | 1              | reflection multiplier           |
// | specular_transmittance | rgb / float      | 1              | transmission multiplier         |
//
// Delta reflection and refraction, chosen with probability F and 1 − F (so the weight is the
// multiplier alone); two-sided by nature (wo.z < 0 means inside). Transmitted radiance is scaled by
// η_ti² (solid-angle compression, radiance transport mode, as Mitsuba).
#include "bsdf/bsdf_params.h"
#include "bsdf/fresnel.h"
#include "bsdf/plugins.h"
#include "bsdf/warp.h"

namespace rc {
namespace {

class DielectricBsdf final : public Bsdf {
 public:
  DielectricBsdf(float eta, const Color& reflectance, const Color& transmittance)
      : eta_(eta), reflectance_(reflectance), transmittance_(transmittance) {}

  Color eval(const Vec3&, const Vec3&) const override { return Color(0.0f); }
  float pdf(const Vec3&, const Vec3&) const override { return 0.0f; }
  std::optional<BsdfSample> sample(const Vec3& wo, float u1, const Vec2&) const override {
    if (wo.z == 0.0f || !std::isfinite(wo.z)) return std::nullopt;
    const FresnelDielectric fr = fresnelDielectric(wo.z, eta_);
    BsdfSample s;
    s.pdf = 0.0f;
    if (u1 <= fr.r) {
      s.wi = reflectZ(wo);
      s.weight = reflectance_;
      s.lobe = kLobeDelta;
      s.eta = 1.0f;
    } else {
      s.wi = refractZ(wo, fr.cosThetaT, fr.etaTi);
      s.weight = transmittance_ * (fr.etaTi * fr.etaTi);
      s.lobe = kLobeDelta | kLobeTransmission;
      s.eta = fr.etaIt;
    }
    return s;
  }
  uint32_t lobes() const override { return kLobeDelta | kLobeTransmission; }
  std::string parameterKey() const override {
    return "dielectric(" + DielectricParams{eta_, reflectance_, transmittance_}.key() + ")";
  }
  std::string typeName() const override { return "dielectric"; }

 private:
  float eta_;
  Color reflectance_, transmittance_;
};

}  // namespace

std::shared_ptr<Bsdf> createDielectricBsdf(const Properties& props, const std::vector<BsdfPtr>&) {
  const DielectricParams d = readDielectricParams(props);
  return std::make_shared<DielectricBsdf>(d.eta, d.reflectance, d.transmittance);
}

}  // namespace rc
