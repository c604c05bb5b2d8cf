/* brdf_dot: L_o,c(p) = Σ_i Λ_c,i(p)·F_c,i(ω_o) (host/sh/batches.h BrdfDotBatch). One work-item
 * per point. Isotropic 1-D tables: linear lookup in x = tan(θ_o/2), then the z-rotation by φ_o is
 * folded into the dot product: per m > 0 only two partial sums P_m, Q_m are formed, and
 * L = Σ_l Λ_l0 G_l0 + Σ_m (cos mφ·P_m + sin mφ·Q_m), so the trigonometry costs O(n), not O(n²)
 * (measured faster than looking up a contiguous vector, turning it and dotting it with vector
 * operations, bench/RESULTS.md). 2-D tables: the bilinear lookup fused into the dot, RC_VEC
 * contiguous coefficients per vector operation. */
#include "shared/rc_types.h"
#ifndef RC_ORDER
#define RC_ORDER 10
#endif
#include "shared/rc_sh_device.h"

__kernel void rc_brdf_dot(const int points, __global const float* lambda, __global const float* wo,
                          __global const int* material, __global const RcBrdfTable* tables, const int tableCount,
                          __global const float* tableData, __global float* out) {
  const int p = get_global_id(0);
  if (p >= points) return;
  const float x = wo[3 * p], y = wo[3 * p + 1], z = wo[3 * p + 2];
  const int mat = material[p];
  float result[3] = {0.0f, 0.0f, 0.0f};
  if (z > 0.0f && mat >= 0 && mat < tableCount) {
    const RcBrdfTable tab = tables[mat];
    const int nt = tab.order, nt2 = nt * nt;
    const int n = min(nt, RC_ORDER);
    __global const float* lam = lambda + (size_t)p * 3 * RC_N2;
    if (tab.kind == RC_TABLE_ISOTROPIC_1D) {
      const float rho = sqrt(x * x + y * y);
      const float xt = rho / (1.0f + z); /* tan(θ/2) */
      const int T = tab.res;
      int i0 = 0;
      float f = 0.0f;
      if (T > 1) {
        const float u = clamp(xt, 0.0f, 1.0f) * (float)(T - 1);
        i0 = min((int)u, T - 2);
        f = u - (float)i0;
      }
      __global const float* F0 = tableData + tab.offset + (size_t)i0 * 3 * nt2;
      __global const float* F1 = T > 1 ? F0 + 3 * nt2 : F0;
      const float2 ph = rc_unit_angle(x, y);
      for (int c = 0; c < 3; ++c) {
        __global const float* a = F0 + c * nt2;
        __global const float* b = F1 + c * nt2;
        __global const float* L = lam + c * RC_N2;
        float sum = 0.0f;
        for (int l = 0; l < n; ++l) {
          const float g = fma(f, b[l * (l + 1)] - a[l * (l + 1)], a[l * (l + 1)]);
          sum = fma(L[l * (l + 1)], g, sum);
        }
        float cm = ph.x, sm = ph.y;
        for (int m = 1; m < n; ++m) {
          float P = 0.0f, Q = 0.0f;
          for (int l = m; l < n; ++l) {
            const int tp = l * (l + 1) + m, tn = l * (l + 1) - m;
            const float gp = fma(f, b[tp] - a[tp], a[tp]);
            const float gn = fma(f, b[tn] - a[tn], a[tn]);
            const float lp = L[tp], ln = L[tn];
            P = fma(lp, gp, fma(ln, gn, P));
            Q = fma(ln, gp, fma(-lp, gn, Q));
          }
          sum = fma(cm, P, fma(sm, Q, sum));
          const float cn = cm * ph.x - sm * ph.y;
          sm = sm * ph.x + cm * ph.y;
          cm = cn;
        }
        result[c] = sum;
      }
    } else if (tab.kind == RC_TABLE_ANISOTROPIC_2D) {
      const int S = tab.res;
      const float px = x / (1.0f + z), py = y / (1.0f + z);
      float u = (px + 1.0f) * 0.5f * (float)(S - 1), v = (py + 1.0f) * 0.5f * (float)(S - 1);
      u = clamp(u, 0.0f, (float)(S - 1));
      v = clamp(v, 0.0f, (float)(S - 1));
      const int ix = min((int)u, max(S - 2, 0)), iy = min((int)v, max(S - 2, 0));
      const float fx = S > 1 ? u - (float)ix : 0.0f, fy = S > 1 ? v - (float)iy : 0.0f;
      const int ix1 = min(ix + 1, S - 1), iy1 = min(iy + 1, S - 1);
      __global const float* base = tableData + tab.offset;
      __global const float* F00 = base + ((size_t)iy * S + ix) * 3 * nt2;
      __global const float* F01 = base + ((size_t)iy * S + ix1) * 3 * nt2;
      __global const float* F10 = base + ((size_t)iy1 * S + ix) * 3 * nt2;
      __global const float* F11 = base + ((size_t)iy1 * S + ix1) * 3 * nt2;
      const float w00 = (1.0f - fx) * (1.0f - fy), w01 = fx * (1.0f - fy), w10 = (1.0f - fx) * fy, w11 = fx * fy;
      /* Bands 0..n−1 are the contiguous indices 0..n²−1: RC_VEC of them per vector operation. */
      const int nn = n * n;
      for (int c = 0; c < 3; ++c) {
        __global const float* L = lam + c * RC_N2;
        __global const float* f00 = F00 + c * nt2;
        __global const float* f01 = F01 + c * nt2;
        __global const float* f10 = F10 + c * nt2;
        __global const float* f11 = F11 + c * nt2;
        rc_vec acc = (rc_vec)(0.0f);
        int i = 0;
        for (; i + RC_VEC <= nn; i += RC_VEC) {
          const rc_vec g = w00 * rc_vload(0, f00 + i) + w01 * rc_vload(0, f01 + i) + w10 * rc_vload(0, f10 + i) +
                           w11 * rc_vload(0, f11 + i);
          acc = fma(rc_vload(0, L + i), g, acc);
        }
        float sum = rc_vec_sum(acc);
        for (; i < nn; ++i) sum = fma(L[i], w00 * f00[i] + w01 * f01[i] + w10 * f10[i] + w11 * f11[i], sum);
        result[c] = sum;
      }
    }
  }
  out[3 * p] = result[0];
  out[3 * p + 1] = result[1];
  out[3 * p + 2] = result[2];
}
