#include "bsdf/merl_sampler.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/parallel.h"

namespace rc {

namespace {

constexpr double kHalfPi = 0.5 * kPiD;

// dω_h / (du dv) for θ_h = u²·π/2, φ_h = v·π (one half of the azimuths).
double halfVectorJacobian(double u, double thetaHalf) { return kPiD * kPiD * u * std::sin(thetaHalf); }

Vec3 rotateZ(const Vec3& v, double c, double s) {
  return Vec3(float(v.x * c - v.y * s), float(v.x * s + v.y * c), v.z);
}

}  // namespace

MerlSampler::MerlSampler(const Target& target, int thetaOBins, int uBins, int vBins)
    : thetaOBins_(thetaOBins), uBins_(uBins), vBins_(vBins) {
  if (thetaOBins < 1 || uBins < 1 || vBins < 1) throw Error("MerlSampler: bin counts must be positive");
  rows_.resize(thetaOBins);
  columns_.resize(size_t(thetaOBins) * uBins);
  parallelFor(size_t(thetaOBins), 1, [&](size_t begin, size_t end) {
    std::vector<double> cell(size_t(uBins) * vBins), rowMass(uBins);
    for (size_t b = begin; b < end; ++b) {
      // The bin's centre stands for every view in it.
      const double thetaO = (b + 0.5) / thetaOBins * kHalfPi;
      const Vec3 wo(float(std::sin(thetaO)), 0.0f, float(std::cos(thetaO)));
      for (int iu = 0; iu < uBins; ++iu) {
        for (int iv = 0; iv < vBins; ++iv) {
          double sum = 0.0;
          for (int su = 0; su < 2; ++su)
            for (int sv = 0; sv < 2; ++sv) {
              const double u = (iu + 0.25 + 0.5 * su) / uBins, v = (iv + 0.25 + 0.5 * sv) / vBins;
              const double th = u * u * kHalfPi, ph = v * kPiD;
              const Vec3 h(float(std::sin(th) * std::cos(ph)), float(std::sin(th) * std::sin(ph)), float(std::cos(th)));
              const float cosOH = glm::dot(wo, h);
              if (!(cosOH > 0.0f)) continue;
              const Vec3 wi = 2.0f * cosOH * h - wo;
              if (!(wi.z > 0.0f)) continue;
              const double g = target(wo, wi);
              if (g > 0.0 && std::isfinite(g)) sum += g * 4.0 * cosOH * halfVectorJacobian(u, th);
            }
          cell[size_t(iu) * vBins + iv] = sum;
        }
        rowMass[iu] = 0.0;
        for (int iv = 0; iv < vBins; ++iv) rowMass[iu] += cell[size_t(iu) * vBins + iv];
        columns_[b * uBins + iu] = Distribution1D(
            std::vector<double>(cell.begin() + size_t(iu) * vBins, cell.begin() + size_t(iu + 1) * vBins));
      }
      rows_[b] = Distribution1D(rowMass);
    }
  });
}

int MerlSampler::binOf(const Vec3& wo) const {
  const double thetaO = std::acos(std::clamp(double(wo.z), -1.0, 1.0));
  return std::min(thetaOBins_ - 1, std::max(0, int(thetaO / kHalfPi * thetaOBins_)));
}

std::optional<Vec3> MerlSampler::sample(const Vec3& wo, bool mirror, const Vec2& u2) const {
  if (!(wo.z > 0.0f)) return std::nullopt;
  const int b = binOf(wo);
  float ru = 0.0f, rv = 0.0f;
  const size_t iu = rows_[b].sample(u2.x, &ru);
  const size_t iv = columns_[size_t(b) * uBins_ + iu].sample(u2.y, &rv);
  const double u = (iu + ru) / uBins_, v = (iv + rv) / vBins_;
  const double th = u * u * kHalfPi, ph = (mirror ? -v : v) * kPiD;
  const Vec3 hLocal(float(std::sin(th) * std::cos(ph)), float(std::sin(th) * std::sin(ph)), float(std::cos(th)));
  const double rxy = std::hypot(double(wo.x), double(wo.y));
  const double c = rxy > 0.0 ? wo.x / rxy : 1.0, s = rxy > 0.0 ? wo.y / rxy : 0.0;
  const Vec3 h = rotateZ(hLocal, c, s);
  const float cosOH = glm::dot(wo, h);
  if (!(cosOH > 0.0f)) return std::nullopt;
  const Vec3 wi = glm::normalize(2.0f * cosOH * h - wo);
  if (!(wi.z > 0.0f)) return std::nullopt;
  return wi;
}

float MerlSampler::pdf(const Vec3& wo, const Vec3& wi) const {
  if (!(wo.z > 0.0f && wi.z > 0.0f)) return 0.0f;
  const Vec3 hw = glm::normalize(wo + wi);
  const double rxy = std::hypot(double(wo.x), double(wo.y));
  const double c = rxy > 0.0 ? wo.x / rxy : 1.0, s = rxy > 0.0 ? wo.y / rxy : 0.0;
  const Vec3 h = rotateZ(hw, c, -s);  // into the frame where ω_o has azimuth 0
  const double th = std::acos(std::clamp(double(h.z), -1.0, 1.0));
  const double u = std::sqrt(th / kHalfPi), v = std::fabs(std::atan2(double(h.y), double(h.x))) / kPiD;
  const int b = binOf(wo);
  const size_t iu = std::min(size_t(uBins_ - 1), size_t(u * uBins_));
  const size_t iv = std::min(size_t(vBins_ - 1), size_t(v * vBins_));
  const double puv = rows_[b].probability(iu) * columns_[size_t(b) * uBins_ + iu].probability(iv) * uBins_ * vBins_;
  if (!(puv > 0.0)) return 0.0f;
  // Both halves of φ_h share the tabulated half: the density per half is puv / 2.
  const double jac = std::max(halfVectorJacobian(u, th), 1e-12);
  const double cosOH = glm::dot(wo, hw);
  if (!(cosOH > 0.0)) return 0.0f;
  const double p = 0.5 * puv / jac / (4.0 * cosOH);
  return std::isfinite(p) ? float(std::min(p, 1e30)) : 0.0f;
}

}  // namespace rc
