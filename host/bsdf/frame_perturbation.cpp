#include "bsdf/frame_perturbation.h"

#include <cmath>

#include "bsdf/bsdf_params.h"

namespace rc {
namespace {

bool finiteVec(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// tan²θ of a direction whose cosine to the axis is c (∞ at c = 0, as Mitsuba's Frame::tan_theta_2).
float tanTheta2(float c) { return std::fmax(0.0f, 1.0f - c * c) / (c * c); }

// The nested BSDF at one point shaded in the perturbed frame; `base` is the unperturbed normal in
// its local coordinates.
class PerturbedPointBsdf final : public Bsdf {
 public:
  PerturbedPointBsdf(BsdfPtr nested, const Vec3& base, bool shadowing, std::string type)
      : nested_(std::move(nested)), base_(base), shadowing_(shadowing), type_(std::move(type)) {
    id = nested_->id;
  }
  Color eval(const Vec3& wo, const Vec3& wi) const override {
    if (!sameSide(wi)) return Color(0.0f);
    return nested_->eval(wo, wi) * shadowing(wi);
  }
  float pdf(const Vec3& wo, const Vec3& wi) const override { return sameSide(wi) ? nested_->pdf(wo, wi) : 0.0f; }
  std::optional<BsdfSample> sample(const Vec3& wo, float u1, const Vec2& u2) const override {
    auto s = nested_->sample(wo, u1, u2);
    if (!s || !sameSide(s->wi)) return std::nullopt;
    s->weight *= shadowing(s->wi);
    return s;
  }
  uint32_t lobes() const override { return nested_->lobes(); }
  float glossyAlpha() const override { return nested_->glossyAlpha(); }
  bool isotropic() const override { return nested_->isotropic(); }
  std::string parameterKey() const override {
    return type_ + "_at(" + hexFloat(base_.x) + "," + hexFloat(base_.y) + "," + hexFloat(base_.z) +
           (shadowing_ ? ";shadowing" : "") + ";" + nested_->parameterKey() + ")";
  }
  std::string typeName() const override { return type_; }
  Color tint(const TexturePoint& uv, const Vec3& wo) const override { return nested_->tint(uv, wo); }
  bool tinted() const override { return nested_->tinted(); }
  bool isTwoSided() const override { return nested_->isTwoSided(); }

 private:
  // Mitsuba: the light direction must lie on the same side of both tangent planes.
  bool sameSide(const Vec3& wi) const { return wi.z * glm::dot(wi, base_) > 0.0f; }
  float shadowing(const Vec3& wi) const { return shadowing_ ? shadowTerminator(base_.z, glm::dot(wi, base_)) : 1.0f; }

  BsdfPtr nested_;
  Vec3 base_;
  bool shadowing_;
  std::string type_;
};

}  // namespace

float shadowTerminator(float cosTilt, float cosBase) {
  const float alpha2 = std::fmin(0.125f * tanTheta2(cosTilt), 1.0f);
  const float g = 2.0f / (1.0f + std::sqrt(1.0f + alpha2 * tanTheta2(cosBase)));
  return std::isfinite(g) ? g : 0.0f;
}

Frame FramePerturbingBsdf::perturbedFrame(const FramePoint& point) const {
  Vec3 n = perturbedNormal(point);
  if (!finiteVec(n) || !(glm::dot(n, n) > 0.0f)) return Frame();
  // Mitsuba: where the viewer sees the perturbed normal from the other side than the unperturbed
  // one, mirror it about the unperturbed normal.
  if (flipInvalid_ && point.wo.z * glm::dot(point.wo, n) <= 0.0f) n = Vec3(-n.x, -n.y, n.z);
  n = glm::normalize(n);
  const Frame f = Frame::fromNormalTangent(n, tangentHint(point));
  return finiteVec(f.t) && finiteVec(f.b) ? f : Frame();
}

BsdfPtr FramePerturbingBsdf::atFrame(const TexturePoint& uv, const Vec3& baseNormal) const {
  BsdfPtr holder = nested_->at(uv);
  return std::make_shared<PerturbedPointBsdf>(holder ? holder : nested_, baseNormal, shadowing_, typeName());
}

bool readFlipInvalidNormals(const Properties& props) { return props.getBool("flip_invalid_normals", true); }
bool readShadowingFunction(const Properties& props) { return props.getBool("use_shadowing_function", true); }

}  // namespace rc
