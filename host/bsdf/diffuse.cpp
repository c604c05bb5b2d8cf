// bsdf "diffuse": ideal Lambertian reflector (Mitsuba 3 src/bsdfs/diffuse.cpp).
//
// | parameter   | type        | default | meaning                        |
// |-------------|-------------|---------|--------------------------------|
// | reflectance | rgb / float | 0.5     | albedo ρ, each component ≥ 0   |
//
// f = ρ/π for wo.z > 0 and wi.z > 0; sampled with the cosine-weighted hemisphere (weight = ρ).
#include "bsdf/bsdf_params.h"
#include "bsdf/diffuse_lobe.h"
#include "bsdf/plugins.h"
#include "bsdf/warp.h"

namespace rc {
namespace {

class DiffuseBsdf final : public Bsdf {
 public:
  explicit DiffuseBsdf(const Color& reflectance) : reflectance_(reflectance) {}

  Color eval(const Vec3& wo, const Vec3& wi) const override { return reflectance_ * lambertCosineTerm(wo.z, wi.z); }
  float pdf(const Vec3& wo, const Vec3& wi) const override { return lambertCosineTerm(wo.z, wi.z); }
  std::optional<BsdfSample> sample(const Vec3& wo, float, const Vec2& u2) const override {
    if (!(wo.z > 0.0f)) return std::nullopt;
    BsdfSample s;
    s.wi = squareToCosineHemisphere(u2);
    s.pdf = squareToCosineHemispherePdf(s.wi);
    if (!(s.pdf > 0.0f)) return std::nullopt;
    s.weight = reflectance_;
    s.lobe = kLobeDiffuse;
    return s;
  }
  uint32_t lobes() const override { return kLobeDiffuse; }
  BsdfBatchParams batchParams() const override { return BsdfBatchParams{BsdfBatchKind::Diffuse, reflectance_}; }
  std::string parameterKey() const override { return "diffuse(reflectance=" + hexColor(reflectance_) + ")"; }
  std::string typeName() const override { return "diffuse"; }

 private:
  Color reflectance_;
};

}  // namespace

std::shared_ptr<Bsdf> createDiffuseBsdf(const Properties& props, const std::vector<BsdfPtr>&) {
  return std::make_shared<DiffuseBsdf>(readReflectance(props, "reflectance", 0.5f));
}

}  // namespace rc
