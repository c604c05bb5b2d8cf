#include "bsdf/rough_textures.h"

#include <cstdio>

#include "bsdf/bsdf_params.h"
#include "core/user_cache.h"

namespace rc {

TexturePtr textureOf(const BsdfTextures& textures, const std::string& name) {
  const auto it = textures.find(name);
  return it == textures.end() ? nullptr : it->second;
}

float textureValue1(const Texture& texture, const TexturePoint& uv) { return texture.eval1(uv); }

std::string textureFingerprint(const Texture& texture) {
  constexpr int kLattice = 17;
  uint64_t hash = fnv1a64("texture", 7);
  for (int j = 0; j < kLattice; ++j)
    for (int i = 0; i < kLattice; ++i) {
      const Color c = texture.eval(TexturePoint(Vec2((i + 0.5f) / kLattice, (j + 0.5f) / kLattice)));
      hash = fnv1a64(&c.r, 3 * sizeof(float), hash);
    }
  char buf[32];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(hash));
  return "texture(" + hexColor(texture.mean()) + ";" + buf + ")";
}

Microfacet RoughnessTextures::distributionAt(const Microfacet& base, const TexturePoint& uv) const {
  const float au = u_ ? textureValue1(*u_, uv) : base.alphaU();
  const float av = v_ ? (v_ == u_ ? au : textureValue1(*v_, uv)) : base.alphaV();
  // The Microfacet constructor clamps α to Mitsuba's 1e-4 floor; a texture can reach 0.
  return Microfacet(base.type(), au, av, base.sampleVisible());
}

std::pair<float, float> RoughnessTextures::range(const Microfacet& base) const {
  constexpr int kLattice = 257;
  float lo = INFINITY, hi = -INFINITY;
  for (int j = 0; j < kLattice; ++j)
    for (int i = 0; i < kLattice; ++i) {
      const float a = distributionAt(base, TexturePoint(Vec2((i + 0.5f) / kLattice, (j + 0.5f) / kLattice))).alphaU();
      lo = std::fmin(lo, a);
      hi = std::fmax(hi, a);
    }
  return {lo, hi};
}

std::string RoughnessTextures::key() const {
  if (!textured()) return "";
  return "alpha_u=" + (u_ ? textureFingerprint(*u_) : std::string("-")) +
         ";alpha_v=" + (v_ ? (v_ == u_ ? std::string("=u") : textureFingerprint(*v_)) : std::string("-"));
}

RoughnessTextures readRoughnessTextures(const BsdfTextures& textures) {
  if (TexturePtr a = textureOf(textures, "alpha")) return RoughnessTextures(a, a);
  return RoughnessTextures(textureOf(textures, "alpha_u"), textureOf(textures, "alpha_v"));
}

}  // namespace rc
