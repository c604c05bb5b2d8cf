// bsdf "conductor": smooth metal, a Dirac reflection (Mitsuba 3 src/bsdfs/conductor.cpp).
//
// | parameter            | type        | default | meaning                                       |
// |----------------------|-------------|---------|-----------------------------------------------|
// | material             | string      | none    | "none" = F ≡ 1; named presets unsupported     |
// | eta, k               | rgb / float | 0, 1    | complex relative IOR (eta 0, k 1 gives F ≡ 1) |
// | specular_reflectance | rgb / float | 1       | multiplier s                                   |
//
// eval and pdf are 0 (delta lobe); sample returns the mirror direction with weight s·F(cosθo).
#include "bsdf/bsdf_params.h"
#include "bsdf/conductor_fresnel.h"
#include "bsdf/plugins.h"
#include "bsdf/warp.h"

namespace rc {
namespace {

class ConductorBsdf final : public Bsdf {
 public:
  explicit ConductorBsdf(const ConductorFresnel& fresnel) : fresnel_(fresnel) {}

  Color eval(const Vec3&, const Vec3&) const override { return Color(0.0f); }
  float pdf(const Vec3&, const Vec3&) const override { return 0.0f; }
  std::optional<BsdfSample> sample(const Vec3& wo, float, const Vec2&) const override {
    if (!(wo.z > 0.0f)) return std::nullopt;
    BsdfSample s;
    s.wi = reflectZ(wo);
    s.pdf = 0.0f;
    s.weight = fresnel_.eval(wo.z);
    s.lobe = kLobeDelta;
    return s;
  }
  uint32_t lobes() const override { return kLobeDelta; }
  std::string parameterKey() const override { return "conductor(" + fresnel_.key() + ")"; }
  std::string typeName() const override { return "conductor"; }

 private:
  ConductorFresnel fresnel_;
};

}  // namespace

std::shared_ptr<Bsdf> createConductorBsdf(const Properties& props, const std::vector<BsdfPtr>&) {
  return std::make_shared<ConductorBsdf>(readConductorFresnel(props));
}

}  // namespace rc
