// bsdf "principled": Disney's principled BSDF as Mitsuba 3 defines it (src/bsdfs/principled.cpp,
// principledhelpers.h).
//
// | parameter                         | type            | default | meaning                                          |
// |-----------------------------------|-----------------|---------|--------------------------------------------------|
// | base_color                        | rgb / texture   | 0.5     | c: diffuse colour, metal F0, transmission tint    |
// | roughness                         | float / texture | 0.5     | r: GGX α = max(0.001, r²) (anisotropy below)      |
// | anisotropic                       | float / texture | 0       | a: α_u = α/√(1 − 0.9a), α_v = α·√(1 − 0.9a)       |
// | metallic                          | float / texture | 0       | m: weight of the Schlick metal reflection         |
// | spec_trans                        | float / texture | 0       | t: weight of rough dielectric transmission        |
// | specular                          | float           | 0.5     | s: η = 2/(1 − √(0.08 s)) − 1 (not with eta)       |
// | eta                               | float           | —       | η of the dielectric interface (not with specular) |
// | spec_tint                         | float / texture | 0       | tints the dielectric reflection toward c          |
// | sheen, sheen_tint                 | float / texture | 0       | retro-reflective sheen and its tint toward c      |
// | flatness                          | float / texture | 0       | blend of the diffuse toward the fake subsurface   |
// | clearcoat, clearcoat_gloss        | float / texture | 0       | GTR1 coat (α lerp(0.1, 0.001, gloss)), Schlick 0.04 |
// | main_specular_sampling_rate       | float           | 1       | lobe-selection weight of the main specular        |
// | clearcoat_sampling_rate           | float           | 1       | lobe-selection weight of the clearcoat            |
// | diffuse_reflectance_sampling_rate | float           | 1       | lobe-selection weight of the diffuse              |
//
// With w_brdf = (1 − m)(1 − t), w_bsdf = (1 − m)·t and h the generalized half vector (as
// roughdielectric), from the front (wo.z > 0):
//   main specular  F_p·D·G/(4|cosθo|), F_p = (1 − m)(1 − tint)·F_dielectric + m·Schlick(c)
//                  + (1 − m)·tint·Schlick(c/lum(c)·R0(η))
//   transmission   √c·w_bsdf·(roughdielectric's BTDF term, radiance mode)
//   clearcoat      ¼·clearcoat·Schlick(0.04)·D_GTR1·G(α 0.25)·|cosθi| (Mitsuba's form, as given)
//   diffuse        w_brdf·c/π·|cosθi|·lerp(f_diff + f_retro, f_ss, flatness) + sheen term
// and from the back only w_bsdf·F_dielectric reflection and the transmission. The optional lobes
// are on only when their parameter is given and not the number 0 (Mitsuba's get_flag). Sampling
// picks diffuse / clearcoat / main specular by the sampling rates (the main specular split into
// reflection and transmission by F at the sampled normal), then pdf() and weight eval/pdf. Eval of a
// scalar texture is its luminance (Mitsuba's eval_1). Any texture makes the BSDF vary per point
// (Bsdf::at). Nothing is substituted: the lobes above are Mitsuba's; `principledthin` is not here.
#include <array>

#include "bsdf/bsdf_params.h"
#include "bsdf/fresnel.h"
#include "bsdf/microfacet.h"
#include "bsdf/plugins.h"
#include "bsdf/rough_textures.h"
#include "bsdf/warp.h"
#include "core/error.h"

namespace rc {
namespace {

enum Scalar { kRoughness, kAnisotropic, kMetallic, kSpecTrans, kSpecTint, kSheen, kSheenTint, kFlatness,
              kClearcoat, kClearcoatGloss, kScalarCount };
const char* const kScalarNames[kScalarCount] = {"roughness", "anisotropic", "metallic",  "spec_trans",
                                                "spec_tint", "sheen",       "sheen_tint", "flatness",
                                                "clearcoat", "clearcoat_gloss"};

struct PrincipledParams {
  Color baseColor{0.5f};
  std::array<float, kScalarCount> value{};
  std::array<bool, kScalarCount> has{};  // lobe switches (Mitsuba's m_has_*)
  float eta = 1.5f;
  float specularRate = 1.0f, clearcoatRate = 1.0f, diffuseRate = 1.0f;
  float operator[](Scalar s) const { return value[s]; }
};

inline float lerp(float a, float b, float t) { return a + t * (b - a); }
inline float schlickWeight(float c) {
  const float m = glm::clamp(1.0f - c, 0.0f, 1.0f);
  return (m * m) * (m * m) * m;
}
inline float schlickR0(float eta) { return ((eta - 1.0f) / (eta + 1.0f)) * ((eta - 1.0f) / (eta + 1.0f)); }
// Schlick's Fresnel with reflectance r0 at normal incidence, using the transmitted angle when
// light leaves the denser side (Mitsuba's calc_schlick).
inline float schlick(float r0, float cosI, float eta) {
  const float etaIt = cosI >= 0.0f ? eta : 1.0f / eta, etaTi = 1.0f / etaIt;
  const float cosT = safeSqrt(1.0f - (1.0f - cosI * cosI) * etaTi * etaTi);
  const float w = etaIt > 1.0f ? schlickWeight(std::fabs(cosI)) : schlickWeight(cosT);
  return lerp(w, 1.0f, r0);
}
inline Color schlick(const Color& r0, float cosI, float eta) {
  return Color(schlick(r0.r, cosI, eta), schlick(r0.g, cosI, eta), schlick(r0.b, cosI, eta));
}
// Isotropic GGX Smith G1 with the clearcoat's fixed α (Mitsuba's smith_ggx1).
inline float smithGgx1(const Vec3& v, const Vec3& h, float alpha) {
  const float c2 = v.z * v.z, tan2 = (1.0f - c2) / c2;
  float g = 2.0f / (1.0f + std::sqrt(1.0f + alpha * alpha * tan2));
  if (v.z == 1.0f) g = 1.0f;
  if (glm::dot(v, h) * v.z <= 0.0f) g = 0.0f;
  return g;
}
// Reflection: both directions on the side of m facing wo; transmission: wi on the other.
inline bool compatible(const Vec3& m, const Vec3& wo, const Vec3& wi, float cosO, bool reflection) {
  const Vec3 mo = mulSign(m, cosO);
  return glm::dot(wo, mo) > 0.0f && (reflection ? glm::dot(wi, mo) > 0.0f : glm::dot(wi, -mo) > 0.0f);
}

// The Berry / GTR1 distribution of the clearcoat.
class Gtr1 {
 public:
  explicit Gtr1(float alpha) : a2_(alpha * alpha) {}
  float D(const Vec3& m) const {
    const float r = (a2_ - 1.0f) / (kPi * std::log(a2_) * (1.0f + (a2_ - 1.0f) * m.z * m.z));
    return r * m.z > 1e-20f ? r : 0.0f;
  }
  float pdf(const Vec3& m) const { return m.z < 0.0f ? 0.0f : m.z * D(m); }
  Vec3 sample(const Vec2& u) const {
    const float phi = 2.0f * kPi * u.x;
    const float cos2 = (1.0f - std::pow(a2_, 1.0f - u.y)) / (1.0f - a2_);
    const float sinT = safeSqrt(1.0f - cos2), cosT = safeSqrt(cos2);
    return Vec3(std::cos(phi) * sinT, std::sin(phi) * sinT, cosT);
  }

 private:
  float a2_;
};

struct LobeProbabilities {
  float diffuse, clearcoat, reflect, transmit;
};

class PrincipledBsdf final : public Bsdf {
 public:
  PrincipledBsdf(const PrincipledParams& p, TexturePtr baseTexture, std::array<TexturePtr, kScalarCount> textures)
      : p_(p), baseTexture_(std::move(baseTexture)), textures_(std::move(textures)) {
    const float r2 = p_[kRoughness] * p_[kRoughness];
    float au = std::fmax(0.001f, r2), av = au;
    if (p_.has[kAnisotropic]) {
      const float aspect = std::sqrt(1.0f - 0.9f * p_[kAnisotropic]);
      au = std::fmax(0.001f, r2 / aspect);
      av = std::fmax(0.001f, r2 * aspect);
    }
    distr_ = Microfacet(MicrofacetType::GGX, au, av, true);
    brdfWeight_ = (1.0f - p_[kMetallic]) * (1.0f - p_[kSpecTrans]);
    bsdfWeight_ = p_.has[kSpecTrans] ? (1.0f - p_[kMetallic]) * p_[kSpecTrans] : 0.0f;
  }

  Color eval(const Vec3& wo, const Vec3& wi) const override {
    const float cosO = wo.z, cosI = wi.z;
    if (cosO == 0.0f || !std::isfinite(cosO)) return Color(0.0f);
    const bool front = cosO > 0.0f, reflect = cosO * cosI > 0.0f, refract = cosO * cosI < 0.0f;
    const float etaPath = front ? p_.eta : 1.0f / p_.eta;
    const Vec3 h = generalizedHalfVector(wo, wi, reflect, etaPath);
    const float dotOH = glm::dot(wo, h), dotIH = glm::dot(wi, h);
    const float F = fresnelDielectric(dotOH, p_.eta).r;
    const bool reflOk = compatible(h, wo, wi, cosO, true), transOk = compatible(h, wo, wi, cosO, false);
    const float D = distr_.D(h), G = distr_.G(wo, wi, h);
    const Color& c = p_.baseColor;
    Color value(0.0f);
    if (reflect && reflOk && F > 0.0f) value += principledFresnel(F, dotOH, front) * (D * G / (4.0f * std::fabs(cosO)));
    if (bsdfWeight_ > 0.0f && refract && transOk && F < 1.0f) {
      // Radiance mode: the 1/η² compression cancels Walter's η² (see roughdielectric.cpp).
      const float denom = dotOH + etaPath * dotIH;
      const float t = std::fabs((1.0f - F) * D * G * dotOH * dotIH / (cosO * denom * denom));
      value += Color(std::sqrt(c.r), std::sqrt(c.g), std::sqrt(c.b)) * (bsdfWeight_ * t);
    }
    if (p_.has[kClearcoat] && p_[kClearcoat] > 0.0f && reflect && reflOk && front) {
      const float fcc = schlick(0.04f, dotOH, p_.eta);
      const float dcc = Gtr1(lerp(0.1f, 0.001f, p_[kClearcoatGloss])).D(h);
      const float gcc = smithGgx1(wo, h, 0.25f) * smithGgx1(wi, h, 0.25f);
      value += Color(0.25f * p_[kClearcoat] * fcc * dcc * gcc * std::fabs(cosI));
    }
    if (brdfWeight_ > 0.0f && reflect && front) {
      const float fi = schlickWeight(std::fabs(cosI)), fo = schlickWeight(std::fabs(cosO));
      const float fDiff = (1.0f - 0.5f * fo) * (1.0f - 0.5f * fi);
      const float cosD = dotIH, rr = 2.0f * p_[kRoughness] * cosD * cosD;
      const float fRetro = rr * (fi + fo + fi * fo * (rr - 1.0f));
      float shape = fDiff + fRetro;
      if (p_.has[kFlatness]) {
        const float fss90 = rr / 2.0f, fss = lerp(1.0f, fss90, fi) * lerp(1.0f, fss90, fo);
        const float fSs = 1.25f * (fss * (1.0f / (std::fabs(cosI) + std::fabs(cosO)) - 0.5f) + 0.5f);
        shape = lerp(shape, fSs, p_[kFlatness]);
      }
      value += c * (brdfWeight_ * std::fabs(cosI) * kInvPi * shape);
      if (p_.has[kSheen] && p_[kSheen] > 0.0f && 1.0f - p_[kMetallic] > 0.0f) {
        const float fd = schlickWeight(std::fabs(cosD));
        Color sheenColor(1.0f);
        if (p_.has[kSheenTint]) {
          const float lum = luminance(c);
          const Color tint = lum > 0.0f ? c / lum : Color(1.0f);
          sheenColor = Color(1.0f) + p_[kSheenTint] * (tint - Color(1.0f));
        }
        value += sheenColor * (p_[kSheen] * (1.0f - p_[kMetallic]) * fd * std::fabs(cosI));
      }
    }
    return isFinite(value) ? value : Color(0.0f);
  }

  float pdf(const Vec3& wo, const Vec3& wi) const override {
    const float cosO = wo.z, cosI = wi.z;
    if (cosO == 0.0f || !std::isfinite(cosO)) return 0.0f;
    const bool front = cosO > 0.0f, reflect = cosO * cosI > 0.0f, refract = cosO * cosI < 0.0f;
    const float etaPath = front ? p_.eta : 1.0f / p_.eta;
    const Vec3 h = generalizedHalfVector(wo, wi, reflect, etaPath);
    const float dotOH = glm::dot(wo, h), dotIH = glm::dot(wi, h);
    const LobeProbabilities prob = probabilities(fresnelDielectric(dotOH, p_.eta).r, front);
    float jacobian;
    if (p_.has[kSpecTrans] && !reflect) {
      const float denom = dotOH + etaPath * dotIH;
      jacobian = std::fabs(etaPath * etaPath * dotIH / (denom * denom));
    } else {
      jacobian = std::fabs(1.0f / (4.0f * dotIH));
    }
    const bool reflOk = reflect && compatible(h, wo, wi, cosO, true);
    const float pdfH = distr_.pdf(mulSign(wo, cosO), h);
    float result = 0.0f;
    if (reflOk) result += prob.reflect * pdfH * jacobian;
    if (reflect) result += prob.diffuse * squareToCosineHemispherePdf(wi);
    if (p_.has[kSpecTrans] && refract && compatible(h, wo, wi, cosO, false)) result += prob.transmit * pdfH * jacobian;
    if (p_.has[kClearcoat] && reflOk)
      result += prob.clearcoat * Gtr1(lerp(0.1f, 0.001f, p_[kClearcoatGloss])).pdf(h) * jacobian;
    return std::isfinite(result) && result > 0.0f ? result : 0.0f;
  }

  std::optional<BsdfSample> sample(const Vec3& wo, float u1, const Vec2& u2) const override {
    const float cosO = wo.z;
    if (cosO == 0.0f || !std::isfinite(cosO)) return std::nullopt;
    const bool front = cosO > 0.0f;
    if (!front && !(bsdfWeight_ > 0.0f)) return std::nullopt;
    const Vec3 m = distr_.sample(mulSign(wo, cosO), u2).first;
    const FresnelDielectric fr = fresnelDielectric(glm::dot(wo, m), p_.eta);
    const LobeProbabilities prob = probabilities(fr.r, front);
    BsdfSample s;
    bool ok;
    if (u1 < prob.diffuse) {
      s.wi = squareToCosineHemisphere(u2);
      s.lobe = kLobeDiffuse;
      ok = cosO * s.wi.z > 0.0f;
    } else if (u1 < prob.diffuse + prob.clearcoat) {
      const Vec3 mcc = Gtr1(lerp(0.1f, 0.001f, p_[kClearcoatGloss])).sample(u2);
      s.wi = reflectAbout(wo, mcc);
      s.lobe = kLobeGlossy;
      ok = compatible(mcc, wo, s.wi, cosO, true) && cosO * s.wi.z > 0.0f;
    } else if (u1 < prob.diffuse + prob.clearcoat + prob.transmit) {
      s.wi = m * (glm::dot(wo, m) * fr.etaTi + fr.cosThetaT) - wo * fr.etaTi;
      s.lobe = kLobeGlossy | kLobeTransmission;
      s.eta = fr.etaIt;
      ok = compatible(m, wo, s.wi, cosO, false) && cosO * s.wi.z < 0.0f;
    } else {
      s.wi = reflectAbout(wo, m);
      s.lobe = kLobeGlossy;
      ok = compatible(m, wo, s.wi, cosO, true) && cosO * s.wi.z > 0.0f;
    }
    if (!ok) return std::nullopt;
    s.pdf = pdf(wo, s.wi);
    if (!(s.pdf > 0.0f)) return std::nullopt;
    s.weight = eval(wo, s.wi) / s.pdf;
    if (!isFinite(s.weight) || !(maxComponent(s.weight) > 0.0f)) return std::nullopt;
    return s;
  }

  uint32_t lobes() const override {
    uint32_t l = kLobeGlossy;
    if (brdfWeight_ > 0.0f || baseTexture_ || textures_[kMetallic] || textures_[kSpecTrans]) l |= kLobeDiffuse;
    if (p_.has[kSpecTrans]) l |= kLobeTransmission;
    return l;
  }
  float glossyAlpha() const override {
    float a = std::fmin(distr_.alphaU(), distr_.alphaV());
    if (p_.has[kClearcoat] && p_[kClearcoat] > 0.0f) a = std::fmin(a, lerp(0.1f, 0.001f, p_[kClearcoatGloss]));
    return a;
  }
  bool isotropic() const override { return !p_.has[kAnisotropic] || (p_[kAnisotropic] == 0.0f && !textures_[kAnisotropic]); }
  std::string parameterKey() const override {
    std::string k = "principled(base_color=" + hexColor(p_.baseColor);
    if (baseTexture_) k += ":" + textureFingerprint(*baseTexture_);
    for (int i = 0; i < kScalarCount; ++i) {
      k += std::string(";") + kScalarNames[i] + "=" + (p_.has[i] ? hexFloat(p_.value[i]) : "off");
      if (textures_[i]) k += ":" + textureFingerprint(*textures_[i]);
    }
    return k + ";eta=" + hexFloat(p_.eta) + ";rates=" + hexFloat(p_.specularRate) + "," + hexFloat(p_.clearcoatRate) +
           "," + hexFloat(p_.diffuseRate) + ")";
  }
  std::string typeName() const override { return "principled"; }

  bool spatiallyVarying() const override {
    if (baseTexture_) return true;
    for (const TexturePtr& t : textures_)
      if (t) return true;
    return false;
  }
  BsdfPtr at(const TexturePoint& uv) const override {
    if (!spatiallyVarying()) return nullptr;
    PrincipledParams here = p_;
    if (baseTexture_) here.baseColor = baseTexture_->eval(uv);
    for (int i = 0; i < kScalarCount; ++i)
      if (textures_[i]) here.value[i] = textureValue1(*textures_[i], uv);
    auto point = std::make_shared<PrincipledBsdf>(here, nullptr, std::array<TexturePtr, kScalarCount>{});
    point->id = id;
    return point;
  }

 private:
  // Lobe choice: the main specular's share split by F into reflection and transmission; from the
  // back, only the dielectric interface (F and 1 − F).
  LobeProbabilities probabilities(float F, bool front) const {
    LobeProbabilities p{};
    if (front) {
      p.reflect = p_.specularRate * (1.0f - bsdfWeight_ * (1.0f - F));
      p.transmit = p_.has[kSpecTrans] ? p_.specularRate * bsdfWeight_ * (1.0f - F) : 0.0f;
      p.clearcoat = p_.has[kClearcoat] ? 0.25f * p_[kClearcoat] * p_.clearcoatRate : 0.0f;
      p.diffuse = brdfWeight_ * p_.diffuseRate;
    } else {
      p.reflect = F;
      p.transmit = p_.has[kSpecTrans] ? 1.0f - F : 0.0f;
    }
    const float total = p.reflect + p.transmit + p.clearcoat + p.diffuse;
    if (total > 0.0f) {
      p.reflect /= total;
      p.transmit /= total;
      p.clearcoat /= total;
      p.diffuse /= total;
    }
    return p;
  }
  Color principledFresnel(float fDielectric, float cosI, bool front) const {
    if (!front) return Color(bsdfWeight_ * fDielectric);
    const Color& c = p_.baseColor;
    const float metallic = p_[kMetallic], tint = p_.has[kSpecTint] ? p_[kSpecTint] : 0.0f;
    Color fSchlick(0.0f);
    if (p_.has[kMetallic]) fSchlick += metallic * schlick(c, cosI, p_.eta);
    if (p_.has[kSpecTint]) {
      const float lum = luminance(c), etaIt = cosI >= 0.0f ? p_.eta : 1.0f / p_.eta;
      const Color cTint = lum > 0.0f ? c / lum : Color(1.0f);
      fSchlick += (1.0f - metallic) * tint * schlick(cTint * schlickR0(etaIt), cosI, p_.eta);
    }
    return Color((1.0f - metallic) * (1.0f - tint) * fDielectric) + fSchlick;
  }

  PrincipledParams p_;
  TexturePtr baseTexture_;
  std::array<TexturePtr, kScalarCount> textures_;
  Microfacet distr_{MicrofacetType::GGX, 0.25f, 0.25f, true};
  float brdfWeight_ = 1.0f, bsdfWeight_ = 0.0f;
};

}  // namespace

std::shared_ptr<Bsdf> createPrincipledBsdf(const Properties& props, const std::vector<BsdfPtr>&,
                                           const BsdfTextures& textures) {
  PrincipledParams p;
  p.baseColor = readReflectance(props, "base_color", 0.5f);
  std::array<TexturePtr, kScalarCount> scalarTextures;
  for (int i = 0; i < kScalarCount; ++i) {
    const std::string name = kScalarNames[i];
    const float fallback = i == kRoughness ? 0.5f : 0.0f;
    p.value[i] = readFloatIn(props, name, fallback, 0.0f, i == kSheen || i == kClearcoat ? INFINITY : 1.0f);
    scalarTextures[i] = textureOf(textures, name);
    // Mitsuba's get_flag: a lobe is on when its parameter is given, unless as the number 0.
    p.has[i] = scalarTextures[i] || (props.has(name) && p.value[i] != 0.0f);
  }
  if (props.has("eta") && props.has("specular"))
    throwParamError(props, "specular", "give either 'eta' or 'specular', not both");
  if (props.has("eta")) {
    p.eta = props.getFloat("eta", 1.5f);
    if (!std::isfinite(p.eta) || !(p.eta > 0.0f)) throwParamError(props, "eta", "must be a positive finite number");
    if (p.has[kSpecTrans] && p.eta == 1.0f) p.eta = 1.001f;  // Mitsuba: η = 1 cannot transmit
  } else {
    float specular = readFloatIn(props, "specular", 0.5f, 0.0f, 12.0f);  // √(0.08·12.5) = 1: η → ∞
    if (p.has[kSpecTrans] && specular == 0.0f) specular = 1e-3f;
    p.eta = 2.0f / (1.0f - std::sqrt(0.08f * specular)) - 1.0f;
  }
  p.specularRate = readFloatIn(props, "main_specular_sampling_rate", 1.0f, 0.0f, INFINITY);
  p.clearcoatRate = readFloatIn(props, "clearcoat_sampling_rate", 1.0f, 0.0f, INFINITY);
  p.diffuseRate = readFloatIn(props, "diffuse_reflectance_sampling_rate", 1.0f, 0.0f, INFINITY);
  return std::make_shared<PrincipledBsdf>(p, textureOf(textures, "base_color"), scalarTextures);
}

}  // namespace rc
