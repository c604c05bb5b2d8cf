// Evaluation of the real SH basis (ARCHITECTURE.md §Conventions) by the normalised recurrences:
//   P̄_l^m = K_l^m P_l^m / sin^m θ (a polynomial in z = cos θ, Condon–Shortley phase included)
//   P̄_0^0 = 1/√(4π),  P̄_m^m = −√((2m+1)/(2m)) P̄_{m−1}^{m−1},  P̄_{m+1}^m = √(2m+3) z P̄_m^m,
//   P̄_l^m = a_lm (z P̄_{l−1}^m − b_lm P̄_{l−2}^m),
//   a_lm = √((4l²−1)/(l²−m²)),  b_lm = √(((l−1)²−m²)/(4(l−1)²−1)).
// The normalisation K_l^m is folded into the recurrence, so no factorial appears (no overflow to
// order 20 and beyond), and sin^m θ cos mφ / sin^m θ sin mφ are Re/Im (x + iy)^m by complex
// multiplication: no atan2, no sqrt, exact at the poles.
#include <cmath>

#include "core/error.h"
#include "sh/sh_basis.h"

namespace rc::sh {
namespace {

constexpr int kMaxOrder = 20;

template <class T>
struct LegendreTables {
  T a[kMaxOrder][kMaxOrder] = {};  // [l][m], l ≥ m+2
  T b[kMaxOrder][kMaxOrder] = {};
  T diag[kMaxOrder] = {};          // −√((2m+1)/(2m)), m ≥ 1
  T sub[kMaxOrder] = {};           // √(2m+3)
  LegendreTables() {
    for (int m = 0; m < kMaxOrder; ++m) {
      if (m > 0) diag[m] = static_cast<T>(-std::sqrt((2.0 * m + 1.0) / (2.0 * m)));
      sub[m] = static_cast<T>(std::sqrt(2.0 * m + 3.0));
      for (int l = m + 2; l < kMaxOrder; ++l) {
        const double l2 = double(l) * l, m2 = double(m) * m, lm1 = double(l - 1) * (l - 1);
        a[l][m] = static_cast<T>(std::sqrt((4.0 * l2 - 1.0) / (l2 - m2)));
        b[l][m] = static_cast<T>(std::sqrt((lm1 - m2) / (4.0 * lm1 - 1.0)));
      }
    }
  }
};

template <class T>
const LegendreTables<T>& legendreTables() {
  static const LegendreTables<T> tables;
  return tables;
}

template <class T>
void evalBasisT(int order, T x, T y, T z, T* out) {
  if (order < 1 || order > kMaxOrder)
    throw Error("sh::evalBasis: order " + std::to_string(order) + " outside 1.." + std::to_string(kMaxOrder));
  const LegendreTables<T>& tb = legendreTables<T>();
  const T sqrt2 = static_cast<T>(1.41421356237309504880);
  T c = 1, s = 0;                                     // Re, Im (x + iy)^m
  T pmm = static_cast<T>(0.28209479177387814347);     // P̄_0^0 = 1/√(4π)
  for (int m = 0; m < order; ++m) {
    if (m > 0) {
      const T c1 = x * c - y * s;
      s = x * s + y * c;
      c = c1;
      pmm *= tb.diag[m];
    }
    const T cm = sqrt2 * c, sm = sqrt2 * s;
    auto put = [&](int l, T p) {
      const int centre = l * (l + 1);
      if (m == 0) {
        out[centre] = p;
      } else {
        out[centre + m] = p * cm;
        out[centre - m] = p * sm;
      }
    };
    put(m, pmm);
    if (m + 1 >= order) continue;
    T p2 = pmm, p1 = tb.sub[m] * z * pmm;
    put(m + 1, p1);
    for (int l = m + 2; l < order; ++l) {
      const T p = tb.a[l][m] * (z * p1 - tb.b[l][m] * p2);
      put(l, p);
      p2 = p1;
      p1 = p;
    }
  }
}

// rotate about z: f'(φ) = f(φ − α) ⇒ (c_m, c_−m) → (c_m cos mα − c_−m sin mα, c_m sin mα + c_−m cos mα).
// cos/sin mα by the angle-addition recurrence (error grows ~ m ε, negligible at m < 20).
template <class T>
void rotateZT(int order, T alpha, const T* in, T* out) {
  const T ca = std::cos(alpha), sa = std::sin(alpha);
  for (int l = 0; l < order; ++l) out[l * (l + 1)] = in[l * (l + 1)];
  T cm = 1, sm = 0;
  for (int m = 1; m < order; ++m) {
    const T c1 = cm * ca - sm * sa;
    sm = sm * ca + cm * sa;
    cm = c1;
    for (int l = m; l < order; ++l) {
      const int centre = l * (l + 1);
      const T cp = in[centre + m], cn = in[centre - m];
      out[centre + m] = cp * cm - cn * sm;
      out[centre - m] = cp * sm + cn * cm;
    }
  }
}

}  // namespace

void evalBasis(int order, double x, double y, double z, double* out) { evalBasisT<double>(order, x, y, z, out); }
void evalBasis(int order, float x, float y, float z, float* out) { evalBasisT<float>(order, x, y, z, out); }

void rotateZ(int order, double alpha, const double* in, double* out) { rotateZT<double>(order, alpha, in, out); }
void rotateZ(int order, float alpha, const float* in, float* out) { rotateZT<float>(order, alpha, in, out); }

}  // namespace rc::sh
