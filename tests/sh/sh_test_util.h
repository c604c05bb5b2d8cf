#pragma once
// Helpers for the SH tests: Gauss–Legendre × uniform-φ quadrature (exact for products of SH up
// to a band limit), random rotations, direction/rotation utilities. Test-only, double precision.
#include <array>
#include <cmath>
#include <vector>

#include "core/rng.h"
#include "sh/sh_basis.h"

namespace rc::shtest {

constexpr double kPi = 3.14159265358979323846;

using Mat3 = std::array<double, 9>;  // row-major

// Gauss–Legendre nodes/weights on [−1, 1] by Newton iteration on P_n (converges to ~1e-16).
inline void gaussLegendre(int n, std::vector<double>& x, std::vector<double>& w) {
  x.resize(n);
  w.resize(n);
  for (int i = 0; i < n; ++i) {
    double z = std::cos(kPi * (i + 0.75) / (n + 0.5)), dp = 0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = z;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1) * z * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (z * p1 - p0) / (z * z - 1);
      const double dz = p1 / dp;
      z -= dz;
      if (std::fabs(dz) < 1e-16) break;
    }
    x[i] = z;
    w[i] = 2.0 / ((1 - z * z) * dp * dp);
  }
}

// Quadrature on the sphere: nodes (unit directions) and weights; exact for f·g with f, g band
// limited to `order` (polynomial degree ≤ 2(order−1) in z, trig degree ≤ 2(order−1) in φ):
// Gauss–Legendre with Q = order + 1 points (exact to degree 2Q−1) × uniform φ with P = 2·order+1
// points (a trig polynomial of degree < P is integrated exactly).
struct SphereQuadrature {
  std::vector<std::array<double, 3>> dirs;
  std::vector<double> weights;
  explicit SphereQuadrature(int order) {
    std::vector<double> gx, gw;
    gaussLegendre(order + 1, gx, gw);
    const int P = 2 * order + 1;
    for (size_t i = 0; i < gx.size(); ++i) {
      const double z = gx[i], s = std::sqrt(std::fmax(0.0, 1 - z * z));
      for (int k = 0; k < P; ++k) {
        const double phi = 2 * kPi * (k + 0.3) / P;
        dirs.push_back({s * std::cos(phi), s * std::sin(phi), z});
        weights.push_back(gw[i] * 2 * kPi / P);
      }
    }
  }
};

inline Mat3 matMul(const Mat3& a, const Mat3& b) {
  Mat3 c{};
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k)
      for (int col = 0; col < 3; ++col) c[3 * r + col] += a[3 * r + k] * b[3 * k + col];
  return c;
}
inline Mat3 transpose(const Mat3& a) {
  return {a[0], a[3], a[6], a[1], a[4], a[7], a[2], a[5], a[8]};
}
inline std::array<double, 3> apply(const Mat3& R, const std::array<double, 3>& v) {
  return {R[0] * v[0] + R[1] * v[1] + R[2] * v[2], R[3] * v[0] + R[4] * v[1] + R[5] * v[2],
          R[6] * v[0] + R[7] * v[1] + R[8] * v[2]};
}

// Rotation by angle about a unit axis (Rodrigues).
inline Mat3 axisAngle(std::array<double, 3> a, double angle) {
  const double len = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  for (double& c : a) c /= len;
  const double c = std::cos(angle), s = std::sin(angle), t = 1 - c;
  return {t * a[0] * a[0] + c,        t * a[0] * a[1] - s * a[2], t * a[0] * a[2] + s * a[1],
          t * a[0] * a[1] + s * a[2], t * a[1] * a[1] + c,        t * a[1] * a[2] - s * a[0],
          t * a[0] * a[2] - s * a[1], t * a[1] * a[2] + s * a[0], t * a[2] * a[2] + c};
}

// Uniform random rotation from a uniform unit quaternion (Shoemake).
inline Mat3 randomRotation(Rng& rng) {
  const double u1 = rng.nextDouble(), u2 = rng.nextDouble(), u3 = rng.nextDouble();
  const double a = std::sqrt(1 - u1), b = std::sqrt(u1);
  const double w = a * std::sin(2 * kPi * u2), x = a * std::cos(2 * kPi * u2);
  const double y = b * std::sin(2 * kPi * u3), z = b * std::cos(2 * kPi * u3);
  return {1 - 2 * (y * y + z * z), 2 * (x * y - w * z),     2 * (x * z + w * y),
          2 * (x * y + w * z),     1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
          2 * (x * z - w * y),     2 * (y * z + w * x),     1 - 2 * (x * x + y * y)};
}

inline std::array<double, 3> randomDirection(Rng& rng) {
  const double z = 1 - 2 * rng.nextDouble(), phi = 2 * kPi * rng.nextDouble();
  const double s = std::sqrt(std::fmax(0.0, 1 - z * z));
  return {s * std::cos(phi), s * std::sin(phi), z};
}

inline std::vector<double> randomCoeffs(Rng& rng, int count) {
  std::vector<double> c(count);
  for (double& v : c) v = 2 * rng.nextDouble() - 1;
  return c;
}

inline double evalFunction(int order, const std::vector<double>& c, const std::array<double, 3>& d) {
  std::vector<double> y(order * order);
  sh::evalBasis(order, d[0], d[1], d[2], y.data());
  double s = 0;
  for (int i = 0; i < order * order; ++i) s += c[i] * y[i];
  return s;
}

inline double norm(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x * x;
  return std::sqrt(s);
}

}  // namespace rc::shtest
