// bsdf "thindielectric": a thin dielectric sheet, e.g. window glass (Mitsuba 3 src/bsdfs/thindielectric.cpp).
//
// | parameter              | type             | default        | meaning                         |
// |------------------------|------------------|----------------|---------------------------------|
// | int_ior                | float / IOR name | bk7 (1.5046)   | the sheet's IOR                 |
// | ext_ior                | float / IOR name | air (1.000277) | the surrounding IOR             |
// | specular_reflectance   | rgb / float      | 1              | reflection multiplier           |
// | specular_transmittance | rgb / float      | 1              | transmission multiplier         |
//
// Light reflects with R = 2r/(1 + r), r the Fresnel reflectance at the first face (the series of
// internal reflections summed), or passes straight through (wi = −wo, no refraction: the sheet's
// two faces are parallel) with 1 − R; both delta, chosen with those probabilities, so the weight is
// the multiplier alone. Two-sided by nature.
#include <cmath>

#include "bsdf/bsdf_params.h"
#include "bsdf/fresnel.h"
#include "bsdf/plugins.h"
#include "bsdf/warp.h"
#include "core/error.h"

namespace rc {
namespace {

class ThinDielectricBsdf final : public Bsdf {
 public:
  ThinDielectricBsdf(float eta, const Color& reflectance, const Color& transmittance)
      : eta_(eta), reflectance_(reflectance), transmittance_(transmittance) {}

  Color eval(const Vec3&, const Vec3&) const override { return Color(0.0f); }
  float pdf(const Vec3&, const Vec3&) const override { return 0.0f; }
  std::optional<BsdfSample> sample(const Vec3& wo, float u1, const Vec2&) const override {
    if (wo.z == 0.0f || !std::isfinite(wo.z)) return std::nullopt;
    float r = fresnelDielectric(std::fabs(wo.z), eta_).r;
    r *= 2.0f / (1.0f + r);
    BsdfSample s;
    s.pdf = 0.0f;
    s.eta = 1.0f;
    if (u1 <= r) {
      s.wi = reflectZ(wo);
      s.weight = reflectance_;
      s.lobe = kLobeDelta;
    } else {
      s.wi = -wo;
      s.weight = transmittance_;
      s.lobe = kLobeDelta | kLobeTransmission;
    }
    return s;
  }
  uint32_t lobes() const override { return kLobeDelta | kLobeTransmission; }
  std::string parameterKey() const override {
    return "thindielectric(" + DielectricParams{eta_, reflectance_, transmittance_}.key() + ")";
  }
  std::string typeName() const override { return "thindielectric"; }

 private:
  float eta_;
  Color reflectance_, transmittance_;
};

}  // namespace

std::shared_ptr<Bsdf> createThinDielectricBsdf(const Properties& props, const std::vector<BsdfPtr>&) {
  const DielectricParams d = readDielectricParams(props);
  return std::make_shared<ThinDielectricBsdf>(d.eta, d.reflectance, d.transmittance);
}

}  // namespace rc
