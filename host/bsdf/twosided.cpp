// bsdf "twosided": makes one-sided BSDFs usable from both sides (Mitsuba 3 src/bsdfs/twosided.cpp).
//
// | nested BSDFs | meaning                                                               |
// |--------------|-----------------------------------------------------------------------|
// | 1            | the same BSDF on both sides                                           |
// | 2            | first on the front (wo.z > 0), second on the back                     |
//
// No parameters. From the back, both directions are mirrored through the tangent plane (z → −z, as
// Mitsuba does) before the nested BSDF sees them, and the sampled direction is mirrored back.
#include "bsdf/plugins.h"
#include "core/error.h"

namespace rc {
namespace {

inline Vec3 flipZ(const Vec3& v) { return Vec3(v.x, v.y, -v.z); }

class TwoSidedBsdf final : public Bsdf {
 public:
  TwoSidedBsdf(BsdfPtr front, BsdfPtr back) : front_(std::move(front)), back_(std::move(back)) {}

  Color eval(const Vec3& wo, const Vec3& wi) const override {
    if (wo.z > 0.0f) return front_->eval(wo, wi);
    if (wo.z < 0.0f) return back_->eval(flipZ(wo), flipZ(wi));
    return Color(0.0f);
  }
  float pdf(const Vec3& wo, const Vec3& wi) const override {
    if (wo.z > 0.0f) return front_->pdf(wo, wi);
    if (wo.z < 0.0f) return back_->pdf(flipZ(wo), flipZ(wi));
    return 0.0f;
  }
  std::optional<BsdfSample> sample(const Vec3& wo, float u1, const Vec2& u2) const override {
    if (wo.z > 0.0f) return front_->sample(wo, u1, u2);
    if (!(wo.z < 0.0f)) return std::nullopt;
    auto s = back_->sample(flipZ(wo), u1, u2);
    if (s) s->wi = flipZ(s->wi);
    return s;
  }
  uint32_t lobes() const override { return front_->lobes() | back_->lobes(); }
  float glossyAlpha() const override { return std::fmin(front_->glossyAlpha(), back_->glossyAlpha()); }
  bool isotropic() const override { return front_->isotropic() && back_->isotropic(); }
  std::string parameterKey() const override {
    return "twosided(" + front_->parameterKey() + ";" + back_->parameterKey() + ")";
  }
  std::string typeName() const override { return "twosided"; }
  bool isTwoSided() const override { return true; }
  Color tint(const TexturePoint& uv, const Vec3& wo) const override {
    return wo.z < 0.0f ? back_->tint(uv, flipZ(wo)) : front_->tint(uv, wo);
  }
  bool tinted() const override { return front_->tinted() || back_->tinted(); }
  bool spatiallyVarying() const override { return front_->spatiallyVarying() || back_->spatiallyVarying(); }
  BsdfPtr at(const TexturePoint& uv) const override {
    if (!spatiallyVarying()) return nullptr;
    BsdfPtr front = front_->at(uv), back = back_ == front_ ? front : back_->at(uv);
    auto point = std::make_shared<TwoSidedBsdf>(front ? front : front_, back ? back : back_);
    point->id = id;
    return point;
  }

 private:
  BsdfPtr front_, back_;
};

}  // namespace

std::shared_ptr<Bsdf> createTwoSidedBsdf(const Properties& props, const std::vector<BsdfPtr>& nested) {
  if (nested.size() != 1 && nested.size() != 2)
    throw Error("<bsdf type=\"twosided\">: needs one or two nested BSDFs, got " + std::to_string(nested.size()));
  for (const BsdfPtr& b : nested) {
    if (!b) throw Error("<bsdf type=\"twosided\">: nested BSDF is null");
    // The radiance cache mirrors a two-sided point's frame to the viewer, so it cannot tell the
    // sides apart for a per-side texture factor.
    if (nested.size() == 2 && b->tinted())
      throw Error("<bsdf type=\"twosided\">: a textured reflectance on one of two different sides is not supported");
    // Mitsuba accepts only one-sided BSDFs here; these two already have a back side.
    if (b->typeName() == "twosided" || b->typeName() == "dielectric" || b->typeName() == "thindielectric" ||
        b->typeName() == "roughdielectric")
      throw Error("<bsdf type=\"twosided\">: nested '" + b->typeName() + "' is already two-sided");
  }
  (void)props;
  return std::make_shared<TwoSidedBsdf>(nested[0], nested.size() == 2 ? nested[1] : nested[0]);
}

}  // namespace rc
