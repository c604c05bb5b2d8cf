#pragma once
// Helpers shared by the BSDF tests: building BSDFs from parameter lists, direction helpers, and the
// chi-square goodness-of-fit machinery (Mitsuba's chi2 test, simplified to a (cosθ, φ) grid).
#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bsdf/bsdf_factory.h"
#include "core/rng.h"

namespace rc::test {

struct Param {
  std::string name;
  Property value;
};
inline Param num(const std::string& n, double v) {
  Property p;
  p.type = Property::Type::Float;
  p.number = v;
  return {n, p};
}
inline Param str(const std::string& n, const std::string& s) {
  Property p;
  p.type = Property::Type::String;
  p.text = s;
  return {n, p};
}
inline Param rgb(const std::string& n, float r, float g, float b) {
  Property p;
  p.type = Property::Type::Rgb;
  p.vec = Vec3(r, g, b);
  return {n, p};
}
inline Param boolean(const std::string& n, bool v) {
  Property p;
  p.type = Property::Type::Boolean;
  p.boolean = v;
  return {n, p};
}

inline BsdfPtr make(const std::string& type, const std::vector<Param>& params = {},
                    const std::vector<BsdfPtr>& nested = {}) {
  Properties props;
  props.pluginType = type;
  for (const Param& p : params) props.set(p.name, p.value);
  return createBsdf(props, nested);
}

// Unit direction from cosθ and φ.
inline Vec3 dirFrom(double cosTheta, double phi) {
  const double s = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
  return Vec3(static_cast<float>(s * std::cos(phi)), static_cast<float>(s * std::sin(phi)),
              static_cast<float>(cosTheta));
}

inline Vec3 uniformSphere(Rng& rng) {
  const double z = 1.0 - 2.0 * rng.nextDouble(), phi = 2.0 * kPiD * rng.nextDouble();
  return dirFrom(z, phi);
}

// Gauss–Legendre nodes/weights on [−1, 1].
inline void gaussLegendre(int n, std::vector<double>* x, std::vector<double>* w) {
  x->resize(n);
  w->resize(n);
  for (int i = 0; i < n; ++i) {
    double t = std::cos(kPiD * (i + 0.75) / (n + 0.5)), dp = 1.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = t;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * t * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (t * p1 - p0) / (t * t - 1.0);
      const double dx = p1 / dp;
      t -= dx;
      if (std::fabs(dx) < 1e-15) break;
    }
    (*x)[i] = t;
    (*w)[i] = 2.0 / ((1.0 - t * t) * dp * dp);
  }
}

// ∫ g(ω) dω over the rectangle [z0,z1]×[φ0,φ1] of the (cosθ, φ) parameterization (dω = dz dφ),
// with `sub`² sub-cells of an `order`-point Gauss–Legendre rule each.
template <typename G>
double integrateCell(const G& g, double z0, double z1, double p0, double p1, int sub = 4, int order = 5) {
  static thread_local std::vector<double> x, w;
  if (static_cast<int>(x.size()) != order) gaussLegendre(order, &x, &w);
  double sum = 0.0;
  const double dz = (z1 - z0) / sub, dp = (p1 - p0) / sub;
  for (int a = 0; a < sub; ++a)
    for (int b = 0; b < sub; ++b) {
      const double za = z0 + a * dz, pb = p0 + b * dp;
      for (int i = 0; i < order; ++i)
        for (int j = 0; j < order; ++j) {
          const double z = za + (x[i] + 1.0) * 0.5 * dz, phi = pb + (x[j] + 1.0) * 0.5 * dp;
          sum += w[i] * w[j] * g(dirFrom(z, phi));
        }
    }
  return sum * 0.25 * dz * dp;
}

// ∫ pdf over the whole sphere.
template <typename G>
double integrateSphere(const G& g, int zCells = 64, int phiCells = 64) {
  double sum = 0.0;
  for (int i = 0; i < zCells; ++i)
    for (int j = 0; j < phiCells; ++j)
      sum += integrateCell(g, -1.0 + 2.0 * i / zCells, -1.0 + 2.0 * (i + 1) / zCells, 2.0 * kPiD * j / phiCells,
                           2.0 * kPiD * (j + 1) / phiCells, 1, 5);
  return sum;
}

// Regularized upper incomplete gamma Q(a, x) (Numerical Recipes: series for x < a+1, else
// Lentz continued fraction), used for the chi-square tail probability Q(dof/2, χ²/2).
inline double gammaQ(double a, double x) {
  if (x <= 0.0) return 1.0;
  const double lnPre = -x + a * std::log(x) - std::lgamma(a);
  if (x < a + 1.0) {
    double ap = a, sum = 1.0 / a, del = sum;
    for (int n = 0; n < 10000; ++n) {
      ap += 1.0;
      del *= x / ap;
      sum += del;
      if (std::fabs(del) < std::fabs(sum) * 1e-15) break;
    }
    return 1.0 - sum * std::exp(lnPre);
  }
  const double tiny = 1e-300;
  double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
  for (int i = 1; i < 10000; ++i) {
    const double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::fabs(d) < tiny) d = tiny;
    c = b + an / c;
    if (std::fabs(c) < tiny) c = tiny;
    d = 1.0 / d;
    const double del = d * c;
    h *= del;
    if (std::fabs(del - 1.0) < 1e-15) break;
  }
  return std::exp(lnPre) * h;
}

struct Chi2Result {
  double statistic = 0.0, pValue = 1.0;
  int dof = 0;
  bool observedWhereImpossible = false;  // samples fell where the pdf integrates to exactly 0
  double expectedTotal = 0.0;
  long observedTotal = 0;
};

// Pearson's test on cells with their expected counts (Mitsuba's chi2: cells with expected < 5 are
// pooled, lowest first, until the pool reaches 5).
inline Chi2Result chi2Test(const std::vector<double>& observed, const std::vector<double>& expected) {
  Chi2Result r;
  std::vector<size_t> idx(observed.size());
  std::iota(idx.begin(), idx.end(), 0);
  std::sort(idx.begin(), idx.end(), [&](size_t a, size_t b) { return expected[a] < expected[b]; });
  double pooledObs = 0.0, pooledExp = 0.0;
  int cells = 0;
  for (size_t i : idx) {
    r.expectedTotal += expected[i];
    r.observedTotal += static_cast<long>(observed[i]);
    if (expected[i] == 0.0) {
      if (observed[i] > 0.0) r.observedWhereImpossible = true;
      continue;
    }
    if (expected[i] < 5.0 || (pooledExp > 0.0 && pooledExp < 5.0)) {
      pooledObs += observed[i];
      pooledExp += expected[i];
      continue;
    }
    const double d = observed[i] - expected[i];
    r.statistic += d * d / expected[i];
    ++cells;
  }
  if (pooledExp > 0.0) {
    const double d = pooledObs - pooledExp;
    r.statistic += d * d / pooledExp;
    ++cells;
  }
  r.dof = std::max(cells - 1, 1);
  r.pValue = gammaQ(0.5 * r.dof, 0.5 * r.statistic);
  return r;
}

// Samples `n` directions from bsdf.sample(wo, ·) (delta and failed samples are not binned) and
// integrates pdf(wo, ·) over a (cosθ ∈ [−1,1]) × (φ ∈ [0, 2π)) grid.
inline Chi2Result chi2ForBsdf(const Bsdf& bsdf, const Vec3& wo, uint64_t seed, int n = 100000, int zBins = 20,
                              int phiBins = 40) {
  std::vector<double> observed(zBins * phiBins, 0.0), expected(zBins * phiBins, 0.0);
  Rng rng(seed, 7);
  for (int k = 0; k < n; ++k) {
    const float u1 = rng.nextFloat();
    const Vec2 u2(rng.nextFloat(), rng.nextFloat());
    const auto s = bsdf.sample(wo, u1, u2);
    if (!s || (s->lobe & kLobeDelta)) continue;
    const double z = glm::clamp(static_cast<double>(s->wi.z), -1.0, 1.0);
    double phi = std::atan2(static_cast<double>(s->wi.y), static_cast<double>(s->wi.x));
    if (phi < 0.0) phi += 2.0 * kPiD;
    const int iz = std::min(zBins - 1, static_cast<int>((z + 1.0) * 0.5 * zBins));
    const int ip = std::min(phiBins - 1, static_cast<int>(phi / (2.0 * kPiD) * phiBins));
    observed[iz * phiBins + ip] += 1.0;
  }
  auto pdf = [&](const Vec3& wi) { return static_cast<double>(bsdf.pdf(wo, wi)); };
  for (int iz = 0; iz < zBins; ++iz)
    for (int ip = 0; ip < phiBins; ++ip)
      expected[iz * phiBins + ip] =
          n * integrateCell(pdf, -1.0 + 2.0 * iz / zBins, -1.0 + 2.0 * (iz + 1) / zBins, 2.0 * kPiD * ip / phiBins,
                            2.0 * kPiD * (ip + 1) / phiBins);
  return chi2Test(observed, expected);
}

// A pass-through surface (null, mask's transmitted share, polarizer): no density or value for any
// pair of directions, and every sample goes straight through (wi = −wo) with `weight`, η 1, delta.
inline void expectPassThrough(const Bsdf& b, Color weight, uint64_t seed, int n) {
  EXPECT_EQ(b.lobes(), uint32_t(kLobeDelta | kLobeTransmission));
  Rng rng(seed);
  for (int k = 0; k < n; ++k) {
    const Vec3 wo = uniformSphere(rng), wi = uniformSphere(rng);
    EXPECT_EQ(b.eval(wo, wi), Color(0.0f));
    EXPECT_EQ(b.pdf(wo, wi), 0.0f);
    const auto s = b.sample(wo, rng.nextFloat(), Vec2(rng.nextFloat(), rng.nextFloat()));
    ASSERT_TRUE(s);
    EXPECT_EQ(s->wi, -wo);
    for (int ch = 0; ch < 3; ++ch) EXPECT_FLOAT_EQ(s->weight[ch], weight[ch]);
    EXPECT_EQ(s->eta, 1.0f);
    EXPECT_TRUE(s->lobe & kLobeDelta);
  }
}

}  // namespace rc::test
