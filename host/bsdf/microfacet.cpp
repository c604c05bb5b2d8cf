#include "bsdf/microfacet.h"

#include <vector>

#include "bsdf/bsdf_params.h"
#include "bsdf/fresnel.h"
#include "bsdf/warp.h"

namespace rc {

namespace {
constexpr float kInvSqrtPi = 0.56418958354775628695f;

// (sin φ, cos φ) of a direction, (0, 1) at the pole, as Mitsuba's Frame3f::sincos_phi.
void sinCosPhi(const Vec3& v, float* s, float* c) {
  const float sin2 = v.x * v.x + v.y * v.y;
  if (sin2 <= 4.0f * 5.96e-8f) {
    *s = 0.0f;
    *c = 1.0f;
    return;
  }
  const float inv = 1.0f / std::sqrt(sin2);
  *s = glm::clamp(v.y * inv, -1.0f, 1.0f);
  *c = glm::clamp(v.x * inv, -1.0f, 1.0f);
}

}  // namespace

float erfInv(float x) {
  // Giles, "Approximating the erfinv function" (GPU Gems Pro 2010), single precision — the same
  // approximation Dr.Jit's erfinv uses, so Mitsuba's Beckmann sampling is reproduced closely.
  float w = -std::log((1.0f - x) * (1.0f + x)), p;
  if (w < 5.0f) {
    w -= 2.5f;
    p = 2.81022636e-08f;
    p = 3.43273939e-07f + p * w; p = -3.5233877e-06f + p * w; p = -4.39150654e-06f + p * w;
    p = 0.00021858087f + p * w;  p = -0.00125372503f + p * w; p = -0.00417768164f + p * w;
    p = 0.246640727f + p * w;    p = 1.50140941f + p * w;
  } else {
    w = std::sqrt(w) - 3.0f;
    p = -0.000200214257f;
    p = 0.000100950558f + p * w; p = 0.00134934322f + p * w; p = -0.00367342844f + p * w;
    p = 0.00573950773f + p * w;  p = -0.0076224613f + p * w; p = 0.00943887047f + p * w;
    p = 1.00167406f + p * w;     p = 2.83297682f + p * w;
  }
  return p * x;
}

Microfacet::Microfacet(MicrofacetType type, float alphaU, float alphaV, bool sampleVisible)
    : type_(type),
      // Mitsuba clamps to 1e-4 to keep D finite; validation rejects α ≤ 0 before this.
      alphaU_(std::fmax(alphaU, 1e-4f)),
      alphaV_(std::fmax(alphaV, 1e-4f)),
      sampleVisible_(sampleVisible) {}

float Microfacet::D(const Vec3& m) const {
  const float alphaUV = alphaU_ * alphaV_, cosTheta = m.z, cos2 = cosTheta * cosTheta;
  float result;
  if (type_ == MicrofacetType::Beckmann) {
    const float ex = m.x / alphaU_, ey = m.y / alphaV_;
    result = std::exp(-(ex * ex + ey * ey) / cos2) / (kPi * alphaUV * cos2 * cos2);
  } else {
    const float ex = m.x / alphaU_, ey = m.y / alphaV_;
    const float t = ex * ex + ey * ey + m.z * m.z;
    result = 1.0f / (kPi * alphaUV * t * t);
  }
  // As Mitsuba: drop negligible/backfacing values to avoid numerical trouble downstream.
  return result * cosTheta > 1e-20f ? result : 0.0f;
}

float Microfacet::smithG1(const Vec3& v, const Vec3& m) const {
  const float xyAlpha2 = (alphaU_ * v.x) * (alphaU_ * v.x) + (alphaV_ * v.y) * (alphaV_ * v.y);
  const float tanThetaAlpha2 = xyAlpha2 / (v.z * v.z);
  float result;
  if (type_ == MicrofacetType::Beckmann) {
    // Mitsuba's rational fit of the Beckmann Smith G1 (< 0.35 % relative error).
    const float a = 1.0f / std::sqrt(tanThetaAlpha2), a2 = a * a;
    result = a >= 1.6f ? 1.0f : (3.535f * a + 2.181f * a2) / (1.0f + 2.276f * a + 2.577f * a2);
  } else {
    result = 2.0f / (1.0f + std::sqrt(1.0f + tanThetaAlpha2));
  }
  if (xyAlpha2 == 0.0f) result = 1.0f;  // perpendicular: no shadowing
  // The back of a microfacet is never visible from the front and vice versa.
  if (glm::dot(v, m) * v.z <= 0.0f) result = 0.0f;
  return result;
}

float Microfacet::pdf(const Vec3& wi, const Vec3& m) const {
  const float d = D(m);
  if (sampleVisible_) return d * smithG1(wi, m) * std::fabs(glm::dot(wi, m)) / wi.z;
  return d * m.z;
}

Vec2 Microfacet::sampleVisible11(float cosThetaI, Vec2 u) const {
  if (type_ == MicrofacetType::Beckmann) {
    // Jakob's numerical inversion of the Beckmann visible-slope CDF, parameterized in erf space.
    const float tanThetaI = safeSqrt(1.0f - cosThetaI * cosThetaI) / cosThetaI;
    const float cotThetaI = 1.0f / tanThetaI;
    const float maxval = std::erf(cotThetaI);
    u = glm::clamp(u, Vec2(1e-6f), Vec2(1.0f - 1e-6f));
    // Initial guess: the analytic solution for θi = π/2 (the most nonlinear case).
    float x = maxval - (maxval + 1.0f) * std::erf(std::sqrt(-std::log(u.x)));
    u.x *= 1.0f + maxval + kInvSqrtPi * tanThetaI * std::exp(-cotThetaI * cotThetaI);
    for (int i = 0; i < 3; ++i) {
      const float slope = erfInv(x);
      const float value = 1.0f + x + kInvSqrtPi * tanThetaI * std::exp(-slope * slope) - u.x;
      const float derivative = 1.0f - slope * tanThetaI;
      x -= value / derivative;
    }
    return Vec2(erfInv(x), erfInv(2.0f * u.y - 1.0f));
  }
  // GGX (Heitz, "A Simpler and Exact Sampling Routine for the GGX Distribution of Visible
  // Normals"): project a disk sample onto the visible half of the truncated ellipsoid.
  Vec2 p = squareToUniformDiskConcentric(u);
  const float s = 0.5f * (1.0f + cosThetaI);
  p.y = glm::mix(safeSqrt(1.0f - p.x * p.x), p.y, s);
  const float x = p.x, y = p.y, z = safeSqrt(1.0f - x * x - y * y);
  const float sinThetaI = safeSqrt(1.0f - cosThetaI * cosThetaI);
  const float norm = 1.0f / (sinThetaI * y + cosThetaI * z);
  return Vec2(cosThetaI * y - sinThetaI * z, x) * norm;
}

std::pair<Vec3, float> Microfacet::sample(const Vec3& wi, const Vec2& u) const {
  if (!sampleVisible_) {
    float sinPhi, cosPhi, alpha2;
    if (isotropic()) {
      sinPhi = std::sin(2.0f * kPi * u.y);
      cosPhi = std::cos(2.0f * kPi * u.y);
      alpha2 = alphaU_ * alphaU_;
    } else {
      const float ratio = alphaV_ / alphaU_, tmp = ratio * std::tan(2.0f * kPi * u.y);
      cosPhi = 1.0f / std::sqrt(tmp * tmp + 1.0f);
      cosPhi = std::copysign(cosPhi, std::fabs(u.y - 0.5f) - 0.25f);
      sinPhi = cosPhi * tmp;
      alpha2 = 1.0f / ((cosPhi / alphaU_) * (cosPhi / alphaU_) + (sinPhi / alphaV_) * (sinPhi / alphaV_));
    }
    float cosTheta, pdf;
    if (type_ == MicrofacetType::Beckmann) {
      cosTheta = 1.0f / std::sqrt(1.0f - alpha2 * std::log(1.0f - u.x));
      const float cos3 = fmaxInline(cosTheta * cosTheta * cosTheta, 1e-20f);
      pdf = (1.0f - u.x) / (kPi * alphaU_ * alphaV_ * cos3);
    } else {
      const float tan2 = alpha2 * u.x / (1.0f - u.x);
      cosTheta = 1.0f / std::sqrt(1.0f + tan2);
      const float temp = 1.0f + tan2 / alpha2, cos3 = fmaxInline(cosTheta * cosTheta * cosTheta, 1e-20f);
      pdf = 1.0f / (kPi * alphaU_ * alphaV_ * cos3 * temp * temp);
    }
    const float sinTheta = safeSqrt(1.0f - cosTheta * cosTheta);
    return {Vec3(cosPhi * sinTheta, sinPhi * sinTheta, cosTheta), pdf};
  }
  // Visible normals: stretch wi to the α = 1 configuration, sample slopes, rotate back, unstretch.
  const Vec3 wiP = glm::normalize(Vec3(alphaU_ * wi.x, alphaV_ * wi.y, wi.z));
  float sinPhi, cosPhi;
  sinCosPhi(wiP, &sinPhi, &cosPhi);
  Vec2 slope = sampleVisible11(wiP.z, u);
  slope = Vec2((cosPhi * slope.x - sinPhi * slope.y) * alphaU_, (sinPhi * slope.x + cosPhi * slope.y) * alphaV_);
  const Vec3 m = glm::normalize(Vec3(-slope.x, -slope.y, 1.0f));
  if (!std::isfinite(m.x) || !std::isfinite(m.y) || !std::isfinite(m.z)) return {Vec3(0, 0, 1), 0.0f};
  return {m, pdf(wi, m)};
}

std::string Microfacet::key() const {
  return std::string(type_ == MicrofacetType::Beckmann ? "beckmann" : "ggx") + "," + hexFloat(alphaU_) + "," +
         hexFloat(alphaV_) + "," + (sampleVisible_ ? "vis" : "all");
}

static float readAlpha(const Properties& props, const std::string& name) {
  const float a = props.getFloat(name, 0.1f);
  if (!std::isfinite(a) || !(a > 0.0f))
    throwParamError(props, name, "roughness must be a finite number > 0 (use the smooth plugin for a mirror)");
  return a;
}

Microfacet readMicrofacet(const Properties& props, bool allowAnisotropic) {
  MicrofacetType type = MicrofacetType::Beckmann;  // Mitsuba 3 default
  const std::string distr = props.getString("distribution", "beckmann");
  if (distr == "ggx") type = MicrofacetType::GGX;
  else if (distr != "beckmann")
    throwParamError(props, "distribution", "must be \"beckmann\" or \"ggx\", got \"" + distr + "\"");

  float au = 0.1f, av = 0.1f;
  const bool hasU = props.has("alpha_u"), hasV = props.has("alpha_v");
  if (props.has("alpha")) {
    if (hasU || hasV) throwParamError(props, "alpha", "give either 'alpha' or 'alpha_u'/'alpha_v', not both");
    au = av = readAlpha(props, "alpha");
  } else if (allowAnisotropic && (hasU || hasV)) {
    if (!hasU || !hasV) throwParamError(props, hasU ? "alpha_u" : "alpha_v", "'alpha_u' and 'alpha_v' must be given together");
    au = readAlpha(props, "alpha_u");
    av = readAlpha(props, "alpha_v");
  }
  const bool visible = props.getBool("sample_visible", true);
  return Microfacet(type, au, av, visible);
}

// Gauss–Legendre nodes/weights on [−1, 1] (Newton on P_n, double precision).
static void gaussLegendre(int n, std::vector<double>* nodes, std::vector<double>* weights) {
  nodes->resize(n);
  weights->resize(n);
  for (int i = 0; i < n; ++i) {
    double x = std::cos(kPiD * (i + 0.75) / (n + 0.5)), dp = 1.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (x * p1 - p0) / (x * x - 1.0);
      const double dx = p1 / dp;
      x -= dx;
      if (std::fabs(dx) < 1e-15) break;
    }
    (*nodes)[i] = x;
    (*weights)[i] = 2.0 / ((1.0 - x * x) * dp * dp);
  }
}

namespace {

// ∫∫ integrand(m) over [0, 1]² of the visible-normal samples m of wi, by Gauss–Legendre quadrature at
// Mitsuba's node counts (32² for eta > 1, 128² otherwise). The integrand sees the visible-normal
// distribution it is sampled from.
template <class Integrand>
double visibleNormalQuadrature(const Microfacet& distr, const Vec3& wi, float eta, Integrand integrand) {
  const Microfacet vis(distr.type(), distr.alphaU(), distr.alphaV(), true);
  const int res = eta > 1.0f ? 32 : 128;
  std::vector<double> nodes, weights;
  gaussLegendre(res, &nodes, &weights);
  double accum = 0.0;
  for (int i = 0; i < res; ++i)
    for (int j = 0; j < res; ++j) {
      const Vec2 node(static_cast<float>(nodes[j] * 0.5 + 0.5), static_cast<float>(nodes[i] * 0.5 + 0.5));
      accum += integrand(vis, vis.sample(wi, node).first) * weights[i] * weights[j];
    }
  return accum * 0.25;  // the product weights sum to 4 on [−1, 1]²
}

}  // namespace

double microfacetReflectance(const Microfacet& distr, const Vec3& wi, float eta) {
  // Requires visible-normal sampling: then the estimator of the albedo is F·G1(wo).
  return visibleNormalQuadrature(distr, wi, eta, [&](const Microfacet& vis, const Vec3& m) -> double {
    const Vec3 wo = reflectAbout(wi, m);
    if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0;
    return fresnelDielectric(glm::dot(wi, m), eta).r * vis.smithG1(wo, m);
  });
}

double microfacetTransmittance(const Microfacet& distr, const Vec3& wi, float eta) {
  return visibleNormalQuadrature(distr, wi, eta, [&](const Microfacet& vis, const Vec3& m) -> double {
    const float cosIM = glm::dot(wi, m);
    const FresnelDielectric fr = fresnelDielectric(cosIM, eta);
    // Refraction about m: wt = m·(cos θi·ηti + cos θt) − wi·ηti.
    const Vec3 wt = m * (cosIM * fr.etaTi + fr.cosThetaT) - wi * fr.etaTi;
    if (wt.z * wi.z >= 0.0f) return 0.0;
    return vis.smithG1(wt, m) * (1.0f - fr.r);
  });
}

}  // namespace rc
