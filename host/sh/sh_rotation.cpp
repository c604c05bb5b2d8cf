// SH rotation matrices by the Ivanic–Ruedenberg recurrence (J. Phys. Chem. 100, 6342, 1996;
// erratum J. Phys. Chem. A 102, 9099, 1998 — the corrected V terms at m = ±1, the √(1+δ) factors,
// and the sign in the b = −l case of P).
//
// Band l is built from band l−1 and band 1:
//   R^l_mn = u_mn U_mn + v_mn V_mn + w_mn W_mn, and u, v, w factor as ũ_m·g_n, ṽ_m·g_n, w̃_m·g_n:
//   g_n = 1/√((l+n)(l−n)) for |n| < l, 1/√(2l(2l−1)) for |n| = l,
//   ũ_m = √((l+m)(l−m)),  ṽ_m = ½√((1+δ_m0)(l+|m|−1)(l+|m|))(1−2δ_m0),  w̃_m = −½√((l−|m|−1)(l−|m|))(1−δ_m0).
// The P terms of one column n only need Q_i[a] = P(i, l, a, n) for i ∈ {−1,0,1}:
//   |n| < l: Q_i[a] = R¹_i0 R^{l−1}_{a,n}
//   n = l:   Q_i[a] = R¹_i1 R^{l−1}_{a,l−1} − R¹_{i,−1} R^{l−1}_{a,−l+1}
//   n = −l:  Q_i[a] = R¹_i1 R^{l−1}_{a,−l+1} + R¹_{i,−1} R^{l−1}_{a,l−1}
// so each column costs 3(2l−1) products for Q plus a few per row: O(l²) per band, no branches
// in the inner loops.
//
// Basis: the recurrence is written for real SH without the Condon–Shortley phase, but it is
// covariant under the similarity S = diag((−1)^m) (P → (−1)^{i+a+b} P, every term of U, V, W of
// row m column n picks up (−1)^{m+n}). So seeding it with the band-1 block of OUR basis,
// y_1^{−1,0,1} ∝ (−y, z, −x), directly yields our matrices. Band 1 of rotate(f) = f∘R⁻¹:
//   R¹_mn = (−1)^{m+n} R[p(m)][p(n)],  p(−1) = y, p(0) = z, p(1) = x.
#include <cmath>
#include <cstring>

#include "core/error.h"
#include "sh/sh_basis.h"

namespace rc::sh {
namespace {

constexpr int kMaxOrder = 20;

template <class T>
struct RotationTables {
  // Per band l (2..19), per m (index m+l) and n (index n+l).
  T u[kMaxOrder][2 * kMaxOrder - 1] = {};
  T v[kMaxOrder][2 * kMaxOrder - 1] = {};
  T w[kMaxOrder][2 * kMaxOrder - 1] = {};
  T g[kMaxOrder][2 * kMaxOrder - 1] = {};
  RotationTables() {
    for (int l = 2; l < kMaxOrder; ++l) {
      for (int m = -l; m <= l; ++m) {
        const int am = std::abs(m);
        const double d = (m == 0) ? 1.0 : 0.0;
        u[l][m + l] = static_cast<T>(std::sqrt(double(l + m) * (l - m)));
        double vv = 0.5 * std::sqrt((1.0 + d) * (l + am - 1.0) * (l + am)) * (1.0 - 2.0 * d);
        // Fold the √(1+δ_{|m|,1}) of V at m = ±1 into the coefficient.
        if (am == 1) vv *= std::sqrt(2.0);
        v[l][m + l] = static_cast<T>(vv);
        w[l][m + l] = static_cast<T>(am >= l - 1 ? 0.0 : -0.5 * std::sqrt((l - am - 1.0) * (l - am)) * (1.0 - d));
        const double denom = (am == l) ? 2.0 * l * (2.0 * l - 1.0) : double(l + m) * (l - m);
        g[l][m + l] = static_cast<T>(1.0 / std::sqrt(denom));
      }
    }
  }
};

template <class T>
const RotationTables<T>& rotationTables() {
  static const RotationTables<T> tables;
  return tables;
}

void checkOrder(int order, const char* what) {
  if (order < 1 || order > kMaxOrder)
    throw Error(std::string("sh::") + what + ": order " + std::to_string(order) + " outside 1.." +
                std::to_string(kMaxOrder));
}

template <class T>
void buildT(int order, const T* R, T* bands) {
  bands[0] = 1;
  if (order < 2) return;
  // Band 1 (3×3, index m+1), our basis: rows/cols (y, z, x) with (−1)^{m+n}.
  T* r1 = bands + 1;
  static const int p[3] = {1, 2, 0};
  for (int m = 0; m < 3; ++m)
    for (int n = 0; n < 3; ++n) {
      const T sign = ((m == 1) != (n == 1)) ? T(-1) : T(1);
      r1[3 * m + n] = sign * R[3 * p[m] + p[n]];
    }
  const RotationTables<T>& tb = rotationTables<T>();
  const T* prev = r1;
  T* cur = r1 + 9;
  T q[3][2 * kMaxOrder];  // Q_{−1}, Q_0, Q_1 at a + l − 1
  for (int l = 2; l < order; ++l) {
    const int wp = 2 * l - 1, wc = 2 * l + 1;  // widths of band l−1 and l
    const T* uu = tb.u[l] + l;                 // centred at m = 0
    const T* vv = tb.v[l] + l;
    const T* ww = tb.w[l] + l;
    for (int n = -l; n <= l; ++n) {
      // Q_i[a] for this column.
      if (n > -l && n < l) {
        for (int a = 0; a < wp; ++a) {
          const T pv = prev[a * wp + (n + l - 1)];
          q[0][a] = r1[0 * 3 + 1] * pv;
          q[1][a] = r1[1 * 3 + 1] * pv;
          q[2][a] = r1[2 * 3 + 1] * pv;
        }
      } else {
        const int hi = wp - 1;  // column l−1 of band l−1, lo = column −l+1 = 0
        for (int a = 0; a < wp; ++a) {
          const T ph = prev[a * wp + hi], pl = prev[a * wp];
          for (int i = 0; i < 3; ++i) {
            const T r1p = r1[i * 3 + 2], r1m = r1[i * 3 + 0];
            q[i][a] = (n == l) ? r1p * ph - r1m * pl : r1p * pl + r1m * ph;
          }
        }
      }
      const T* qm = q[0] + (l - 1);  // Q_{−1}, centred
      const T* q0 = q[1] + (l - 1);
      const T* qp = q[2] + (l - 1);
      const T gn = tb.g[l][n + l];
      T* col = cur + (n + l);
      // m = 0 (w̃ = 0 by the (1 − δ_m0) factor).
      col[l * wc] = gn * (uu[0] * q0[0] + vv[0] * (qp[1] + qm[-1]));
      // m = ±1 (V has a single term, √2 folded into ṽ).
      {
        T U = (1 <= l - 1) ? q0[1] : T(0);
        T W = (1 <= l - 2) ? qp[2] + qm[-2] : T(0);
        col[(l + 1) * wc] = gn * (uu[1] * U + vv[1] * qp[0] + ww[1] * W);
        U = q0[-1];
        W = (1 <= l - 2) ? qp[-2] - qm[2] : T(0);
        col[(l - 1) * wc] = gn * (uu[-1] * U + vv[-1] * qm[0] + ww[-1] * W);
      }
      // 2 ≤ |m| ≤ l−2: all three terms.
      for (int m = 2; m <= l - 2; ++m) {
        col[(l + m) * wc] = gn * (uu[m] * q0[m] + vv[m] * (qp[m - 1] - qm[-m + 1]) + ww[m] * (qp[m + 1] + qm[-m - 1]));
        col[(l - m) * wc] =
            gn * (uu[-m] * q0[-m] + vv[-m] * (qp[-m + 1] + qm[m - 1]) + ww[-m] * (qp[-m - 1] - qm[m + 1]));
      }
      // |m| = l−1 (≥ 2): U and V; |m| = l: V only.
      for (int m = (l - 1 >= 2 ? l - 1 : l); m <= l; ++m) {
        const T Up = (m <= l - 1) ? uu[m] * q0[m] : T(0);
        const T Un = (m <= l - 1) ? uu[-m] * q0[-m] : T(0);
        col[(l + m) * wc] = gn * (Up + vv[m] * (qp[m - 1] - qm[-m + 1]));
        col[(l - m) * wc] = gn * (Un + vv[-m] * (qp[-m + 1] + qm[m - 1]));
      }
    }
    prev = cur;
    cur += wc * wc;
  }
}

template <class T>
void applyT(int order, const T* bands, const T* in, T* out) {
  out[0] = bands[0] * in[0];
  const T* blk = bands + 1;
  for (int l = 1; l < order; ++l) {
    const int w = 2 * l + 1, base = l * l;
    const T* x = in + base;
    for (int m = 0; m < w; ++m) {
      const T* row = blk + m * w;
      T acc = 0;
      for (int n = 0; n < w; ++n) acc += row[n] * x[n];
      out[base + m] = acc;
    }
    blk += w * w;
  }
}

// Three channels (stride n2) per pass over the matrix: the matrix is read once for RGB.
template <class T>
void apply3T(int order, const T* bands, const T* in, T* out) {
  const int n2 = order * order;
  for (int c = 0; c < 3; ++c) out[c * n2] = bands[0] * in[c * n2];
  const T* blk = bands + 1;
  for (int l = 1; l < order; ++l) {
    const int w = 2 * l + 1, base = l * l;
    const T* x0 = in + base;
    const T* x1 = x0 + n2;
    const T* x2 = x1 + n2;
    for (int m = 0; m < w; ++m) {
      const T* row = blk + m * w;
      T a0 = 0, a1 = 0, a2 = 0;
      for (int n = 0; n < w; ++n) {
        a0 += row[n] * x0[n];
        a1 += row[n] * x1[n];
        a2 += row[n] * x2[n];
      }
      out[base + m] = a0;
      out[n2 + base + m] = a1;
      out[2 * n2 + base + m] = a2;
    }
    blk += w * w;
  }
}

template <class T>
void applyChannels(int order, const T* bands, int channels, const T* in, T* out) {
  const int n2 = order * order;
  int c = 0;
  for (; c + 3 <= channels; c += 3) apply3T<T>(order, bands, in + c * n2, out + c * n2);
  for (; c < channels; ++c) applyT<T>(order, bands, in + c * n2, out + c * n2);
}

template <class T>
bool isIdentityT(const T* R, double tol) {
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      if (!(std::fabs(double(R[3 * r + c]) - (r == c ? 1.0 : 0.0)) <= tol)) return false;
  return true;
}

template <class T>
bool isZT(const T* R, double tol, double& alpha) {
  if (!(std::fabs(double(R[2]) ) <= tol && std::fabs(double(R[5])) <= tol && std::fabs(double(R[6])) <= tol &&
        std::fabs(double(R[7])) <= tol && std::fabs(double(R[8]) - 1.0) <= tol))
    return false;
  alpha = std::atan2(double(R[3]), double(R[0]));  // R = Rz(α): R(1,0) = sin α, R(0,0) = cos α
  return true;
}

constexpr double kFastPathTol = 1e-7;

}  // namespace

void rotationMatrix(int order, const double R[9], std::vector<double>& bands) {
  checkOrder(order, "rotationMatrix");
  bands.resize(rotationMatrixSize(order));
  buildT<double>(order, R, bands.data());
}
void applyRotation(int order, const std::vector<double>& bands, const double* in, double* out) {
  checkOrder(order, "applyRotation");
  if (static_cast<int>(bands.size()) < rotationMatrixSize(order))
    throw Error("sh::applyRotation: matrix built for a lower order than " + std::to_string(order));
  applyT<double>(order, bands.data(), in, out);
}
void rotationMatrix(int order, const float R[9], float* bands) {
  checkOrder(order, "rotationMatrix");
  buildT<float>(order, R, bands);
}
void applyRotation(int order, const float* bands, const float* in, float* out) {
  applyT<float>(order, bands, in, out);
}

bool isIdentityRotation(const double R[9], double tol) { return isIdentityT(R, tol); }
bool isZRotation(const double R[9], double tol, double& alpha) { return isZT(R, tol, alpha); }

void rotateChannels(int order, const double R[9], int channels, const double* in, double* out) {
  checkOrder(order, "rotateChannels");
  const int n2 = order * order;
  double alpha = 0;
  if (isIdentityT(R, kFastPathTol)) {
    std::memcpy(out, in, sizeof(double) * n2 * channels);
  } else if (isZT(R, kFastPathTol, alpha)) {
    for (int c = 0; c < channels; ++c) rotateZ(order, alpha, in + c * n2, out + c * n2);
  } else {
    double bands[rotationMatrixSize(kMaxOrder)];
    buildT<double>(order, R, bands);
    applyChannels<double>(order, bands, channels, in, out);
  }
}

void rotateChannels(int order, const float R[9], int channels, const float* in, float* out) {
  checkOrder(order, "rotateChannels");
  const int n2 = order * order;
  double alpha = 0;
  if (isIdentityT(R, kFastPathTol)) {
    std::memcpy(out, in, sizeof(float) * n2 * channels);
  } else if (isZT(R, kFastPathTol, alpha)) {
    for (int c = 0; c < channels; ++c) rotateZ(order, static_cast<float>(alpha), in + c * n2, out + c * n2);
  } else {
    float bands[rotationMatrixSize(kMaxOrder)];
    buildT<float>(order, R, bands);
    applyChannels<float>(order, bands, channels, in, out);
  }
}

}  // namespace rc::sh
