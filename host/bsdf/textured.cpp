#include "bsdf/textured.h"

#include "bsdf/alpha_family.h"
#include "bsdf/bsdf_params.h"

namespace rc {
namespace {

class TexturedBsdf final : public Bsdf, public AlphaFamily {
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
  Color tint(const TexturePoint& uv, const Vec3&) const override { return factor_->eval(uv); }
  bool tinted() const override { return true; }
  bool spatiallyVarying() const override { return unit_->spatiallyVarying(); }
  BsdfPtr at(const TexturePoint& uv) const override {
    BsdfPtr unitHere = unit_->at(uv);
    return unitHere ? std::make_shared<TexturedBsdf>(std::move(unitHere), factor_) : nullptr;
  }
  // The factor applies outside the tables: the family is the unit BSDF's.
  bool variesOnlyInAlpha() const override { return alphaFamilyOf(*unit_) != nullptr; }
  std::pair<float, float> alphaRange() const override { return alphaFamilyOf(*unit_)->alphaRange(); }
  float alphaAt(const TexturePoint& uv) const override { return alphaFamilyOf(*unit_)->alphaAt(uv); }
  BsdfPtr withAlpha(float alpha) const override { return alphaFamilyOf(*unit_)->withAlpha(alpha); }

 private:
  BsdfPtr unit_;
  TexturePtr factor_;
};

class TintBakedBsdf final : public Bsdf {
 public:
  TintBakedBsdf(BsdfPtr tinted, const TexturePoint& uv) : tinted_(std::move(tinted)), uv_(uv) { id = tinted_->id; }
  Color eval(const Vec3& wo, const Vec3& wi) const override { return tinted_->tint(uv_, wo) * tinted_->eval(wo, wi); }
  float pdf(const Vec3& wo, const Vec3& wi) const override { return tinted_->pdf(wo, wi); }
  std::optional<BsdfSample> sample(const Vec3& wo, float u1, const Vec2& u2) const override {
    auto s = tinted_->sample(wo, u1, u2);
    if (s) s->weight *= tinted_->tint(uv_, wo);
    return s;
  }
  uint32_t lobes() const override { return tinted_->lobes(); }
  float glossyAlpha() const override { return tinted_->glossyAlpha(); }
  bool isotropic() const override { return tinted_->isotropic(); }
  std::string parameterKey() const override {
    // A mesh attribute's value depends on the triangle and barycentrics too.
    const std::string where = uv_.attributes ? "," + std::to_string(reinterpret_cast<uintptr_t>(uv_.attributes)) + "," +
                                                   std::to_string(uv_.face) + "," + hexFloat(uv_.bary.x) + "," +
                                                   hexFloat(uv_.bary.y)
                                             : "";
    return "tint_at(" + hexFloat(uv_.x) + "," + hexFloat(uv_.y) + where + ";" + tinted_->parameterKey() + ")";
  }
  std::string typeName() const override { return tinted_->typeName(); }

 private:
  BsdfPtr tinted_;
  TexturePoint uv_;
};

}  // namespace

BsdfPtr bakeTint(BsdfPtr tinted, const TexturePoint& uv) { return std::make_shared<TintBakedBsdf>(std::move(tinted), uv); }

BsdfPtr makeTexturedBsdf(BsdfPtr unit, TexturePtr factor) {
  return std::make_shared<TexturedBsdf>(std::move(unit), std::move(factor));
}

bool isBsdfFactorParameter(const std::string& bsdfType, const std::string& parameter) {
  if (bsdfType == "diffuse") return parameter == "reflectance";
  if (bsdfType == "conductor" || bsdfType == "roughconductor") return parameter == "specular_reflectance";
  return false;
}

}  // namespace rc
