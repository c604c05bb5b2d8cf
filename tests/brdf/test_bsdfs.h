#pragma once
// Small BSDFs of this folder's own, so the tables can be tested independently of host/bsdf:
// an (anisotropic) GGX/Beckmann microfacet conductor with Schlick Fresnel per channel, a
// Lambertian, a diffuse + glossy mix, and a delta stand-in. Sampling draws microfacet normals
// ∝ D(m)·cos θ_m by scaling standard (α = 1) slopes, whose density is exactly pdf().
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "bsdf/bsdf.h"

namespace rc::test {

inline std::string hexf(float v) {
  char b[32];
  std::snprintf(b, sizeof b, "%a", static_cast<double>(v));
  return b;
}

class TestMicrofacet : public Bsdf {
 public:
  TestMicrofacet(bool ggx, float au, float av, Color f0 = Color(0.95f, 0.64f, 0.54f))
      : ggx_(ggx), au_(au), av_(av), f0_(f0) {
    id = "test-microfacet";
  }
  float D(const Vec3& m) const {
    if (m.z <= 0) return 0;
    const double x = m.x / au_, y = m.y / av_, z = m.z;
    if (ggx_) {
      const double t = x * x + y * y + z * z;
      return float(1.0 / (kPiD * au_ * av_ * t * t));
    }
    const double z2 = z * z;
    return float(std::exp(-(x * x + y * y) / z2) / (kPiD * au_ * av_ * z2 * z2));
  }
  float G1(const Vec3& v) const {
    if (v.z <= 0) return 0;
    const double a2t2 = (double(v.x) * v.x * au_ * au_ + double(v.y) * v.y * av_ * av_) / (double(v.z) * v.z);
    if (a2t2 <= 0) return 1;
    double lambda;
    if (ggx_) {
      lambda = 0.5 * (-1.0 + std::sqrt(1.0 + a2t2));
    } else {
      const double a = 1.0 / std::sqrt(a2t2);
      lambda = 0.5 * (std::erf(a) - 1.0) + std::exp(-a * a) / (2.0 * a * std::sqrt(kPiD));
    }
    return float(1.0 / (1.0 + lambda));
  }
  Color fresnel(float c) const {
    const float k = std::pow(1.0f - std::fmax(0.0f, c), 5.0f);
    return f0_ + (Color(1.0f) - f0_) * k;
  }
  Color eval(const Vec3& wo, const Vec3& wi) const override {
    if (wo.z <= 0 || wi.z <= 0) return Color(0.0f);
    const Vec3 m = glm::normalize(wo + wi);
    return fresnel(glm::dot(wi, m)) * (D(m) * G1(wo) * G1(wi) / (4.0f * wo.z));
  }
  float pdf(const Vec3& wo, const Vec3& wi) const override {
    if (wo.z <= 0 || wi.z <= 0) return 0;
    const Vec3 m = glm::normalize(wo + wi);
    return D(m) * m.z / (4.0f * glm::dot(wo, m));
  }
  std::optional<BsdfSample> sample(const Vec3& wo, float, const Vec2& u) const override {
    if (wo.z <= 0) return std::nullopt;
    const double t2 = ggx_ ? u.x / (1.0 - u.x) : -std::log(1.0 - u.x);
    const double r = std::sqrt(t2), phi = 2.0 * kPiD * u.y;
    const Vec3 m = glm::normalize(Vec3(float(-r * std::cos(phi) * au_), float(-r * std::sin(phi) * av_), 1.0f));
    const Vec3 wi = 2.0f * glm::dot(wo, m) * m - wo;
    if (wi.z <= 0) return std::nullopt;
    BsdfSample s;
    s.wi = wi;
    s.pdf = pdf(wo, wi);
    if (!(s.pdf > 0)) return std::nullopt;
    s.weight = eval(wo, wi) / s.pdf;
    s.lobe = kLobeGlossy;
    return s;
  }
  uint32_t lobes() const override { return kLobeGlossy; }
  float glossyAlpha() const override { return std::fmin(au_, av_); }
  bool isotropic() const override { return au_ == av_; }
  std::string parameterKey() const override {
    return std::string("testmicrofacet,") + (ggx_ ? "ggx," : "beckmann,") + hexf(au_) + "," + hexf(av_) + "," +
           hexf(f0_.r) + "," + hexf(f0_.g) + "," + hexf(f0_.b);
  }
  std::string typeName() const override { return "testmicrofacet"; }

 private:
  bool ggx_;
  float au_, av_;
  Color f0_;
};

class TestLambert : public Bsdf {
 public:
  explicit TestLambert(Color rho) : rho_(rho) { id = "test-lambert"; }
  Color eval(const Vec3& wo, const Vec3& wi) const override {
    return (wo.z > 0 && wi.z > 0) ? rho_ * (wi.z * kInvPi) : Color(0.0f);
  }
  float pdf(const Vec3& wo, const Vec3& wi) const override { return (wo.z > 0 && wi.z > 0) ? wi.z * kInvPi : 0.0f; }
  std::optional<BsdfSample> sample(const Vec3& wo, float, const Vec2& u) const override {
    if (wo.z <= 0) return std::nullopt;
    const float r = std::sqrt(u.x), phi = 2 * kPi * u.y;
    BsdfSample s;
    s.wi = Vec3(r * std::cos(phi), r * std::sin(phi), std::sqrt(std::fmax(0.0f, 1 - u.x)));
    s.pdf = pdf(wo, s.wi);
    if (!(s.pdf > 0)) return std::nullopt;
    s.weight = rho_;
    s.lobe = kLobeDiffuse;
    return s;
  }
  uint32_t lobes() const override { return kLobeDiffuse; }
  std::string parameterKey() const override { return "testlambert," + hexf(rho_.r) + "," + hexf(rho_.g) + "," + hexf(rho_.b); }
  std::string typeName() const override { return "testlambert"; }

 private:
  Color rho_;
};

// kd·Lambert + glossy, sampled half/half (a plastic-like two-lobe material).
class TestMix : public Bsdf {
 public:
  TestMix(Color kd, std::shared_ptr<TestMicrofacet> glossy) : diffuse_(kd), glossy_(std::move(glossy)) { id = "test-mix"; }
  Color eval(const Vec3& wo, const Vec3& wi) const override { return diffuse_.eval(wo, wi) + glossy_->eval(wo, wi); }
  float pdf(const Vec3& wo, const Vec3& wi) const override {
    return 0.5f * diffuse_.pdf(wo, wi) + 0.5f * glossy_->pdf(wo, wi);
  }
  std::optional<BsdfSample> sample(const Vec3& wo, float u1, const Vec2& u2) const override {
    auto s = u1 < 0.5f ? diffuse_.sample(wo, 0, u2) : glossy_->sample(wo, 0, u2);
    if (!s) return s;
    s->pdf = pdf(wo, s->wi);
    if (!(s->pdf > 0)) return std::nullopt;
    s->weight = eval(wo, s->wi) / s->pdf;
    return s;
  }
  uint32_t lobes() const override { return kLobeDiffuse | kLobeGlossy; }
  float glossyAlpha() const override { return glossy_->glossyAlpha(); }
  bool isotropic() const override { return glossy_->isotropic(); }
  std::string parameterKey() const override { return "testmix," + diffuse_.parameterKey() + ";" + glossy_->parameterKey(); }
  std::string typeName() const override { return "testmix"; }

 private:
  TestLambert diffuse_;
  std::shared_ptr<TestMicrofacet> glossy_;
};

class TestMirror : public Bsdf {
 public:
  TestMirror() { id = "test-mirror"; }
  Color eval(const Vec3&, const Vec3&) const override { return Color(0.0f); }
  float pdf(const Vec3&, const Vec3&) const override { return 0.0f; }
  std::optional<BsdfSample> sample(const Vec3& wo, float, const Vec2&) const override {
    if (wo.z <= 0) return std::nullopt;
    BsdfSample s;
    s.wi = Vec3(-wo.x, -wo.y, wo.z);
    s.weight = Color(1.0f);
    s.lobe = kLobeDelta;
    return s;
  }
  uint32_t lobes() const override { return kLobeDelta; }
  std::string parameterKey() const override { return "testmirror"; }
  std::string typeName() const override { return "testmirror"; }
};

inline std::shared_ptr<TestMicrofacet> ggx(float a) { return std::make_shared<TestMicrofacet>(true, a, a); }
inline std::shared_ptr<TestMicrofacet> beckmann(float a) { return std::make_shared<TestMicrofacet>(false, a, a); }

}  // namespace rc::test
