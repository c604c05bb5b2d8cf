#pragma once
// Textured BSDF parameters evaluated per point (Bsdf::at): the scalar value of a texture (Mitsuba's
// eval_1, Texture::eval1), a content fingerprint for parameterKey(), and the
// textures of a microfacet roughness (alpha, or alpha_u / alpha_v).
#include <string>
#include <utility>

#include "bsdf/microfacet.h"
#include "bsdf/bsdf_textures.h"

namespace rc {

// The texture on `name`, null when the parameter is not textured.
TexturePtr textureOf(const BsdfTextures& textures, const std::string& name);
// Mitsuba's Texture::eval_1 in RGB mode (Texture::eval1).
float textureValue1(const Texture& texture, const TexturePoint& uv);
// Text that changes whenever the texture's values do (its mean in hex floats and a hash of its values on a
// fixed 17×17 uv lattice), so keys of different textures differ.
std::string textureFingerprint(const Texture& texture);

class RoughnessTextures {
 public:
  RoughnessTextures() = default;
  RoughnessTextures(TexturePtr alphaU, TexturePtr alphaV) : u_(std::move(alphaU)), v_(std::move(alphaV)) {}
  bool textured() const { return u_ || v_; }
  bool isotropic() const { return u_ == v_; }
  // `base` with α taken from the textures at uv (the untextured one of alpha_u/alpha_v kept).
  Microfacet distributionAt(const Microfacet& base, const TexturePoint& uv) const;
  std::string key() const;  // "" when untextured
  // The smallest and largest α_u the textures give `base` over a 257×257 uv lattice (bilinear and
  // nearest bitmaps up to that size and checkerboards reach their extremes on it).
  std::pair<float, float> range(const Microfacet& base) const;

 private:
  TexturePtr u_, v_;
};

// alpha → both; alpha_u / alpha_v → each (readMicrofacet has checked which are given).
RoughnessTextures readRoughnessTextures(const BsdfTextures& textures);

}  // namespace rc
