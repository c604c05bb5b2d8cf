// bsdf "bumpmap": a nested BSDF shaded in the frame of a height field's normal (Mitsuba 3
// src/bsdfs/bumpmap.cpp). Shared parameters and the point's factors: bsdf/frame_perturbation.h.
//
// | parameter        | type    | default | meaning                                                  |
// |------------------|---------|---------|----------------------------------------------------------|
// | (any name)       | texture | —       | the height field h (Mitsuba's eval_1: luminance); its one texture child |
// | scale            | float   | 1       | s: the height field's gradient is scaled by s            |
//
// One nested BSDF. With the surface partials dp/du, dp/dv (their components along the shading
// normal replaced by s·∂h/∂u and s·∂h/∂v), the perturbed normal is dp/du × dp/dv, turned to the
// side of the geometric normal; the tangent is dp/du orthogonalised against it. Where the shape has
// no partials (a mesh without uvs) the frame stays unperturbed. The texture must have a gradient
// (a bitmap; Mitsuba refuses the others too).
#include "bsdf/bsdf_params.h"
#include "bsdf/frame_perturbation.h"
#include "bsdf/plugins.h"
#include "bsdf/rough_textures.h"
#include "core/error.h"

namespace rc {
namespace {

class BumpMapBsdf final : public FramePerturbingBsdf {
 public:
  BumpMapBsdf(BsdfPtr nested, TexturePtr height, float scale, bool flip, bool shadowing)
      : FramePerturbingBsdf(std::move(nested), flip, shadowing), height_(std::move(height)), scale_(scale) {}
  std::string typeName() const override { return "bumpmap"; }

 protected:
  Vec3 perturbedNormal(const FramePoint& point) const override {
    if (!(glm::dot(point.dpdu, point.dpdu) > 0.0f) || !(glm::dot(point.dpdv, point.dpdv) > 0.0f)) return Vec3(0, 0, 1);
    const Vec2 grad = height_ ? scale_ * height_->gradient1(point.uv) : Vec2(0.0f);
    const Vec3 dpdu(point.dpdu.x, point.dpdu.y, grad.x), dpdv(point.dpdv.x, point.dpdv.y, grad.y);
    const Vec3 n = glm::cross(dpdu, dpdv);
    return glm::dot(point.ng, n) < 0.0f ? -n : n;
  }
  Vec3 tangentHint(const FramePoint& point) const override { return point.dpdu; }

 private:
  TexturePtr height_;  // null: a texture lenient mode left out (flat)
  float scale_;
};

}  // namespace

std::shared_ptr<Bsdf> createBumpMapBsdf(const Properties& props, const std::vector<BsdfPtr>& nested,
                                        const BsdfTextures& textures) {
  if (nested.size() != 1 || !nested[0])
    throw Error("<bsdf type=\"bumpmap\">: needs exactly one nested BSDF, got " + std::to_string(nested.size()));
  if (!props.has(kBumpMapTextureParameter))
    throw Error("<bsdf type=\"bumpmap\">: needs exactly one nested <texture> (the height field)");
  (void)props.getColor(kBumpMapTextureParameter, Color(0.0f));  // its mean: read, the texture is what counts
  const TexturePtr height = textureOf(textures, kBumpMapTextureParameter);
  if (height && !height->hasGradient())
    throw Error("<bsdf type=\"bumpmap\">: the height texture has no gradient (only a bitmap has one, as in Mitsuba 3)");
  const float scale = props.getFloat("scale", 1.0f);
  if (!std::isfinite(scale)) throwParamError(props, "scale", "must be finite");
  return std::make_shared<BumpMapBsdf>(nested[0], height, scale, readFlipInvalidNormals(props),
                                       readShadowingFunction(props));
}

}  // namespace rc
