#include "bsdf/textured.h"

namespace rc {
namespace {

class TexturedBsdf final : public Bsdf {
 public:
  TexturedBsdf(BsdfPtr unit, TexturePtr factor) : unit_(std::move(unit)), factor_(std::move(factor)) { id = unit_->id; }
  Color eval(const Vec3& wo, const Vec3& wi) const override { return unit_->eval(wo, wi); }
  float pdf(const Vec3& wo, const Vec3& wi) const override { return unit_->pdf(wo, wi); }
  std::optional<BsdfSample> sample(const Vec3& wo, float u1, const Vec2& u2) const override {
    return unit_->sample(wo, u1, u2);
  }
  uint32_t lobes() const override { return unit_->lobes(); }
  float glossyAlpha() const override { return unit_->glossyAlpha(); }
  bool isotropic() const override { return unit_->isotropic(); }
  // Same tables as the untextured BSDF: the factor is applied outside them.
  std::string parameterKey() const override { return unit_->parameterKey(); }
  std::string typeName() const override { return unit_->typeName(); }
  Color tint(const Vec2& uv, const Vec3&) const override { return factor_->eval(uv); }
  bool tinted() const override { return true; }

 private:
  BsdfPtr unit_;
  TexturePtr factor_;
};

}  // namespace

BsdfPtr makeTexturedBsdf(BsdfPtr unit, TexturePtr factor) {
  return std::make_shared<TexturedBsdf>(std::move(unit), std::move(factor));
}

bool isBsdfFactorParameter(const std::string& bsdfType, const std::string& parameter) {
  if (bsdfType == "diffuse") return parameter == "reflectance";
  if (bsdfType == "conductor" || bsdfType == "roughconductor") return parameter == "specular_reflectance";
  return false;
}

}  // namespace rc
