#include "cl/rotation_tables.h"

#include <cmath>
#include <map>
#include <mutex>

#include "core/error.h"

namespace rc::cl {

void shEvalDouble(int order, double x, double y, double z, double* out) {
  if (order < 1 || order > 20) throw Error("shEvalDouble: order " + std::to_string(order) + " outside 1..20");
  // Fully normalised associated Legendre N_l^m = K_l^m P_l^m by the stable three-term recurrence
  // (no factorials), Condon–Shortley phase in the diagonal step.
  const double s = std::sqrt(std::fmax(0.0, 1.0 - z * z));
  const double phi = std::atan2(y, x);
  const double kSqrt2 = std::sqrt(2.0);
  double nmm = 1.0 / std::sqrt(4.0 * 3.14159265358979323846);
  for (int m = 0; m < order; ++m) {
    if (m > 0) nmm *= -std::sqrt((2.0 * m + 1.0) / (2.0 * m)) * s;
    double p2 = 0, p1 = nmm;  // N_{l-2}^m, N_{l-1}^m
    const double c = m ? kSqrt2 * std::cos(m * phi) : 1.0, sn = kSqrt2 * std::sin(m * phi);
    for (int l = m; l < order; ++l) {
      double p;
      if (l == m) p = nmm;
      else if (l == m + 1) p = std::sqrt(2.0 * m + 3.0) * z * nmm;
      else {
        const double a = std::sqrt((4.0 * l * l - 1.0) / (double(l) * l - double(m) * m));
        const double b = std::sqrt(((l - 1.0) * (l - 1.0) - double(m) * m) / (4.0 * (l - 1.0) * (l - 1.0) - 1.0));
        p = a * (z * p1 - b * p2);
      }
      if (l > m) { p2 = p1; p1 = p; }
      out[l * (l + 1) + m] = c * p;
      if (m > 0) out[l * (l + 1) - m] = sn * p;
    }
  }
}

namespace {

void gaussLegendre(int n, std::vector<double>& nodes, std::vector<double>& weights) {
  nodes.resize(n);
  weights.resize(n);
  for (int i = 0; i < n; ++i) {
    double x = std::cos(3.14159265358979323846 * (i + 0.75) / (n + 0.5));
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double pk = ((2.0 * k - 1) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = pk;
      }
      const double dp = n * (x * p1 - p0) / (x * x - 1);
      const double dx = p1 / dp;
      x -= dx;
      if (std::fabs(dx) < 1e-16) {
        nodes[i] = x;
        weights[i] = 2.0 / ((1 - x * x) * dp * dp);
        break;
      }
      nodes[i] = x;
      weights[i] = 2.0 / ((1 - x * x) * dp * dp);
    }
  }
}

}  // namespace

const std::vector<float>& xRotation90Table(int order) {
  static std::mutex mutex;
  static std::map<int, std::vector<float>> cache;
  std::lock_guard<std::mutex> lock(mutex);
  auto it = cache.find(order);
  if (it != cache.end()) return it->second;
  const int n2 = order * order;
  // D_ij = ∫ y_i(ω) y_j(R⁻¹ω) dω, R = Rx(+90°): R⁻¹(x,y,z) = (x, z, −y). Degree ≤ 2(order−1)
  // in z and in φ-frequency: order+1 Gauss nodes and 2·order+1 azimuths integrate exactly.
  std::vector<double> gz, gw;
  gaussLegendre(order + 1, gz, gw);
  const int nphi = 2 * order + 1;
  std::vector<double> D(static_cast<size_t>(n2) * n2, 0.0), a(n2), b(n2);
  for (size_t g = 0; g < gz.size(); ++g) {
    const double z = gz[g], s = std::sqrt(1 - z * z);
    for (int k = 0; k < nphi; ++k) {
      const double phi = 2 * 3.14159265358979323846 * k / nphi;
      const double x = s * std::cos(phi), y = s * std::sin(phi);
      const double w = gw[g] * 2 * 3.14159265358979323846 / nphi;
      shEvalDouble(order, x, y, z, a.data());
      shEvalDouble(order, x, z, -y, b.data());
      for (int l = 0; l < order; ++l)
        for (int i = l * l; i < (l + 1) * (l + 1); ++i)
          for (int j = l * l; j < (l + 1) * (l + 1); ++j) D[static_cast<size_t>(i) * n2 + j] += w * a[i] * b[j];
    }
  }
  std::vector<float> table(bandBlockOffset(order));
  for (int l = 0; l < order; ++l) {
    const int w = 2 * l + 1, base = bandBlockOffset(l);
    for (int r = 0; r < w; ++r)
      for (int c = 0; c < w; ++c) {
        double v = D[static_cast<size_t>(l * l + r) * n2 + (l * l + c)];
        if (std::fabs(v) < 1e-13) v = 0;  // exact zeros of the structure, not quadrature noise
        table[base + r * w + c] = static_cast<float>(v);
      }
  }
  return cache.emplace(order, std::move(table)).first->second;
}

const SparseRotation90& xRotation90Sparse(int order) {
  static std::mutex mutex;
  static std::map<int, SparseRotation90> cache;
  const std::vector<float>& dense = xRotation90Table(order);
  std::lock_guard<std::mutex> lock(mutex);
  auto it = cache.find(order);
  if (it != cache.end()) return it->second;
  SparseRotation90 s;
  for (int transpose = 0; transpose < 2; ++transpose)
    for (int l = 0; l < order; ++l) {
      const int w = 2 * l + 1, base = bandBlockOffset(l);
      for (int r = 0; r < w; ++r) {
        s.rowStart.push_back(static_cast<rc_int>(s.entries.size()));
        for (int c = 0; c < w; ++c) {
          const float v = transpose ? dense[base + c * w + r] : dense[base + r * w + c];
          if (v != 0.0f) s.entries.push_back(RcSparseEntry{l * l + c, v});
        }
      }
    }
  s.rowStart.push_back(static_cast<rc_int>(s.entries.size()));
  return cache.emplace(order, std::move(s)).first->second;
}

}  // namespace rc::cl
