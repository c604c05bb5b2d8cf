// bsdf "normalmap": a nested BSDF shaded in the frame of a normal read from a texture (Mitsuba 3
// src/bsdfs/normalmap.cpp). Shared parameters and the point's factors: bsdf/frame_perturbation.h.
//
// | parameter | type          | default | meaning                                                        |
// |-----------|---------------|---------|----------------------------------------------------------------|
// | normalmap | texture / rgb | —       | c: the normal 2c − 1 in the unperturbed shading frame (t = the mesh's uv tangent dp/du, n = the shading normal) |
//
// One nested BSDF. The perturbed tangent is the unperturbed one orthogonalised against the normal.
// A bitmap normal map is usually loaded with `raw` = true (no sRGB decoding), as Mitsuba's
// documentation advises; the plugin takes the texture's values as they come.
#include "bsdf/bsdf_params.h"
#include "bsdf/frame_perturbation.h"
#include "bsdf/plugins.h"
#include "bsdf/rough_textures.h"
#include "core/error.h"

namespace rc {
namespace {

class NormalMapBsdf final : public FramePerturbingBsdf {
 public:
  NormalMapBsdf(BsdfPtr nested, TexturePtr map, const Color& constant, bool flip, bool shadowing)
      : FramePerturbingBsdf(std::move(nested), flip, shadowing), map_(std::move(map)), constant_(constant) {}
  std::string typeName() const override { return "normalmap"; }

 protected:
  Vec3 perturbedNormal(const FramePoint& point) const override {
    const Color c = map_ ? map_->eval(point.uv) : constant_;
    return Vec3(2.0f * c.r - 1.0f, 2.0f * c.g - 1.0f, 2.0f * c.b - 1.0f);
  }
  Vec3 tangentHint(const FramePoint&) const override { return Vec3(1, 0, 0); }

 private:
  TexturePtr map_;
  Color constant_;
};

}  // namespace

std::shared_ptr<Bsdf> createNormalMapBsdf(const Properties& props, const std::vector<BsdfPtr>& nested,
                                          const BsdfTextures& textures) {
  if (nested.size() != 1 || !nested[0])
    throw Error("<bsdf type=\"normalmap\">: needs exactly one nested BSDF, got " + std::to_string(nested.size()));
  if (!props.has("normalmap")) throw Error("<bsdf type=\"normalmap\">: missing the 'normalmap' texture");
  const Color constant = props.getColor("normalmap", Color(0.5f, 0.5f, 1.0f));
  if (!isFinite(constant)) throwParamError(props, "normalmap", "must be finite");
  return std::make_shared<NormalMapBsdf>(nested[0], textureOf(textures, "normalmap"), constant,
                                         readFlipInvalidNormals(props), readShadowingFunction(props));
}

}  // namespace rc
