#pragma once
// What normalmap and bumpmap share (Mitsuba 3 src/bsdfs/normalmap.cpp, bumpmap.cpp): a nested BSDF
// shaded in a perturbed frame (Bsdf::perturbsFrame), the flip of invalid normals, and the point
// BSDF with the factors Mitsuba applies in the unperturbed frame.
//
// | parameter              | type | default | meaning                                                   |
// |------------------------|------|---------|-----------------------------------------------------------|
// | flip_invalid_normals   | bool | true    | mirror the perturbed normal about the unperturbed one where the viewer sees it from the other side |
// | use_shadowing_function | bool | true    | Estevez et al. 2019's shadowing term on the light direction |
//
// At a point, f(wo, wi) = f_nested(wo, wi)·G(wi) in the perturbed frame where wi lies on the same
// side of the unperturbed and of the perturbed tangent plane, else 0; the sample's weight carries G.
// G(wi) = 2 / (1 + √(1 + α²·tan²θ_i)), θ_i measured from the unperturbed normal, α² = min(⅛·tan²θ_n, 1),
// θ_n the tilt of the perturbed normal.
#include <string>

#include "bsdf/bsdf.h"
#include "core/properties.h"

namespace rc {

class FramePerturbingBsdf : public Bsdf {
 public:
  FramePerturbingBsdf(BsdfPtr nested, bool flipInvalidNormals, bool shadowing)
      : nested_(std::move(nested)), flipInvalid_(flipInvalidNormals), shadowing_(shadowing) {}

  // The nested BSDF in the perturbed frame: its coefficient tables are the nested BSDF's.
  Color eval(const Vec3& wo, const Vec3& wi) const override { return nested_->eval(wo, wi); }
  float pdf(const Vec3& wo, const Vec3& wi) const override { return nested_->pdf(wo, wi); }
  std::optional<BsdfSample> sample(const Vec3& wo, float u1, const Vec2& u2) const override {
    return nested_->sample(wo, u1, u2);
  }
  uint32_t lobes() const override { return nested_->lobes(); }
  float glossyAlpha() const override { return nested_->glossyAlpha(); }
  bool isotropic() const override { return nested_->isotropic(); }
  std::string parameterKey() const override { return nested_->parameterKey(); }
  Color tint(const TexturePoint& uv, const Vec3& wo) const override { return nested_->tint(uv, wo); }
  bool tinted() const override { return nested_->tinted(); }
  bool spatiallyVarying() const override { return nested_->spatiallyVarying(); }
  BsdfPtr at(const TexturePoint& uv) const override { return nested_->at(uv); }
  bool isTwoSided() const override { return nested_->isTwoSided(); }

  bool perturbsFrame() const override { return true; }
  Frame perturbedFrame(const FramePoint& point) const override;
  BsdfPtr atFrame(const TexturePoint& uv, const Vec3& baseNormal) const override;

 protected:
  // The perturbed normal at the point (unperturbed local coordinates, any length; zero or not
  // finite: no perturbation there).
  virtual Vec3 perturbedNormal(const FramePoint& point) const = 0;
  // The direction the perturbed tangent is orthogonalised from (Gram–Schmidt against the normal).
  virtual Vec3 tangentHint(const FramePoint& point) const = 0;

 private:
  BsdfPtr nested_;
  bool flipInvalid_, shadowing_;
};

// Estevez et al. 2019's shadowing term G (above); cosTilt = cos θ_n, cosBase = cos θ_i.
float shadowTerminator(float cosTilt, float cosBase);

bool readFlipInvalidNormals(const Properties& props);
bool readShadowingFunction(const Properties& props);

}  // namespace rc
