#pragma once
// Beckmann and GGX microfacet distributions as in Mitsuba 3 (include/mitsuba/render/microfacet.h):
// D, separable Smith G (Beckmann with Mitsuba's rational G1 fit), and sampling of all normals or of
// the visible normals (Heitz & d'Eon 2014 / Jakob's Beckmann inversion; GGX: Heitz's exact routine).
// Directions are local (z = normal); `wi` here is the direction sampling starts from (the viewer).
#include <string>
#include <utility>

#include "core/math.h"
#include "core/properties.h"

namespace rc {

enum class MicrofacetType { Beckmann, GGX };

class Microfacet {
 public:
  Microfacet(MicrofacetType type, float alphaU, float alphaV, bool sampleVisible = true);

  MicrofacetType type() const { return type_; }
  float alphaU() const { return alphaU_; }
  float alphaV() const { return alphaV_; }
  bool sampleVisible() const { return sampleVisible_; }
  bool isotropic() const { return alphaU_ == alphaV_; }

  float D(const Vec3& m) const;
  float smithG1(const Vec3& v, const Vec3& m) const;
  float G(const Vec3& wi, const Vec3& wo, const Vec3& m) const { return smithG1(wi, m) * smithG1(wo, m); }
  // What a reflection's eval and pdf share: its half vector h = normalize(wo + wi), D(h) and the
  // viewer's G1(wo, h) — G(wo, wi, h) is g1o · smithG1(wi, h), the visible-normal pdf D · g1o.
  struct HalfTerms {
    Vec3 h;
    float d, g1o;
  };
  HalfTerms halfTerms(const Vec3& wo, const Vec3& wi) const {
    const Vec3 h = glm::normalize(wo + wi);
    return HalfTerms{h, D(h), smithG1(wo, h)};
  }
  // Density of sample() over microfacet normals (solid angle of m).
  float pdf(const Vec3& wi, const Vec3& m) const;
  // Returns (m, pdf(m)); pdf 0 when sampling failed.
  std::pair<Vec3, float> sample(const Vec3& wi, const Vec2& u) const;

  // Visible-normal sampling for α = 1 in slope space (Mitsuba's sample_visible_11).
  Vec2 sampleVisible11(float cosThetaI, Vec2 u) const;

  std::string key() const;  // "type,αu,αv,visible" in hex floats

 private:
  MicrofacetType type_;
  float alphaU_, alphaV_;
  bool sampleVisible_;
};

// Reads distribution / alpha | alpha_u+alpha_v / sample_visible with Mitsuba's defaults and rules
// (both alpha_u and alpha_v or neither; not together with alpha). α must be finite and > 0.
Microfacet readMicrofacet(const Properties& props, bool allowAnisotropic);

// Albedo of a dielectric microfacet reflection lobe F·D·G/(4 cos θi) for incidence wi (wi.z > 0),
// by Gauss–Legendre quadrature over the visible-normal sampling domain (Mitsuba's
// eval_reflectance: 32² nodes for eta > 1, 128² otherwise).
double microfacetReflectance(const Microfacet& distr, const Vec3& wi, float eta);

// Transmittance 1 − (reflected + absorbed) of a rough dielectric interface for incidence wi: the
// quadrature of (1 − F)·G1(wt) over refracted directions wt (Mitsuba's eval_transmittance).
double microfacetTransmittance(const Microfacet& distr, const Vec3& wi, float eta);

// Inverse error function, Giles' single-precision approximation (|x| < 1).
float erfInv(float x);

}  // namespace rc
