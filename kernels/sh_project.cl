/* sh_project: Λ_c,i = (2π/(M·N)) Σ_s L_c,s·y_i(ω_s) for a batch of records sharing one stratified
 * pattern (host/sh/batches.h ProjectBatch). Because the pattern is shared and each record only
 * turns it about z by phi0, the basis matrix Y[s][i] (pattern at phi0 = 0) is computed once per
 * batch and the projection is a GEMM, C = A·Y, with A[b][s][row] the per-sample row weights
 * (rows 0..2: radiance; rows 3..8: gradient-weighted radiance from grad_accumulate.cl). The
 * record's azimuth phi0 is applied afterwards as a z-rotation of each row (rc_project_finish).
 *
 * Kernels, in launch order: rc_sh_basis (once per pattern), rc_project_prep or rc_grad_prep,
 * rc_project_gemm3 / rc_project_gemm9, rc_project_finish. */
#include "shared/rc_types.h"
#ifndef RC_ORDER
#define RC_ORDER 10
#endif
#include "shared/rc_sh_device.h"

#define RC_NP (((RC_N2 + RC_VEC - 1) / RC_VEC) * RC_VEC) /* padded row length of Y and C */
#define RC_TWO_PI 6.283185307179586f

/* Direction of pattern cell s (phi0 = 0): cos θ = 1 − (j+ξ)/M, φ = 2π(k+ζ)/N. */
inline float3 rc_cell_direction(__global const float* pattern, int s, int M, int N) {
  const int j = s / N, k = s - j * N;
  const float z = 1.0f - ((float)j + pattern[2 * s]) / (float)M;
  const float phi = RC_TWO_PI * ((float)k + pattern[2 * s + 1]) / (float)N;
  const float st = sqrt(fmax(0.0f, 1.0f - z * z));
  float cp;
  const float sp = sincos(phi, &cp);
  return (float3)(st * cp, st * sp, z);
}

/* y[0..RC_N2) at unit direction d: fully normalised Legendre N_l^m by the stable three-term
 * recurrence (no factorials, fine in float to order 20), Condon–Shortley phase on the diagonal. */
inline void rc_sh_eval(float3 d, __global float* y) {
  const float st = sqrt(fmax(0.0f, 1.0f - d.z * d.z));
  const float2 ph = rc_unit_angle(d.x, d.y);
  float nmm = 0.28209479177387814f; /* 1/√(4π) */
  float cm = 1.0f, sm = 0.0f;        /* cos mφ, sin mφ */
  for (int m = 0; m < RC_ORDER; ++m) {
    if (m > 0) {
      nmm *= -sqrt((2.0f * m + 1.0f) / (2.0f * m)) * st;
      const float cn = cm * ph.x - sm * ph.y;
      sm = sm * ph.x + cm * ph.y;
      cm = cn;
    }
    const float cpos = m ? 1.41421356237f * cm : 1.0f, cneg = 1.41421356237f * sm;
    float p2 = 0.0f, p1 = nmm;
    for (int l = m; l < RC_ORDER; ++l) {
      float p;
      if (l == m) {
        p = nmm;
      } else if (l == m + 1) {
        p = sqrt(2.0f * m + 3.0f) * d.z * nmm;
        p2 = p1;
        p1 = p;
      } else {
        const float a = sqrt((4.0f * l * l - 1.0f) / (float)(l * l - m * m));
        const float b = sqrt((float)((l - 1) * (l - 1) - m * m) / (4.0f * (l - 1) * (l - 1) - 1.0f));
        p = a * (d.z * p1 - b * p2);
        p2 = p1;
        p1 = p;
      }
      y[l * (l + 1) + m] = cpos * p;
      if (m > 0) y[l * (l + 1) - m] = cneg * p;
    }
  }
}

/* Y[s][0..RC_NP): basis at the pattern's cell directions (phi0 = 0), zero padding. */
__kernel void rc_sh_basis(const int S, const int M, const int N, __global const float* pattern, __global float* Y) {
  const int s = get_global_id(0);
  if (s >= S) return;
  __global float* y = Y + (size_t)s * RC_NP;
  rc_sh_eval(rc_cell_direction(pattern, s, M, N), y);
  for (int i = RC_N2; i < RC_NP; ++i) y[i] = 0.0f;
}

/* A[b][s][0..3) = radiance, or 0 for a sample with a NaN/Inf channel (counted in dropped[b]). */
__kernel void rc_project_prep(const int S, const int B, __global const float* radiance, __global float* A,
                              __global int* dropped) {
  const int s = get_global_id(0), b = get_global_id(1);
  if (s >= S || b >= B) return;
  const size_t i = (size_t)b * S + s;
  float r = radiance[3 * i], g = radiance[3 * i + 1], bl = radiance[3 * i + 2];
  if (!(isfinite(r) && isfinite(g) && isfinite(bl))) {
    atomic_inc(dropped + b);
    r = g = bl = 0.0f;
  }
  A[3 * i] = r;
  A[3 * i + 1] = g;
  A[3 * i + 2] = bl;
}

/* C[b][row][chunk·VEC ..] = Σ_s A[b][s][row]·Y[s][chunk·VEC ..]. One work-item owns a
 * ROWS × VEC register tile: per sample one vector load of Y and ROWS broadcast FMAs. Work-items
 * of one record are adjacent in dimension 0, so that record's A rows stay in cache. */
#define RC_GEMM(NAME, ROWS)                                                                           \
  __kernel void NAME(const int S, const int B, __global const float* A, __global const float* Y,      \
                     __global float* C) {                                                             \
    const int chunk = get_global_id(0), b = get_global_id(1);                                         \
    if (chunk * RC_VEC >= RC_NP || b >= B) return;                                                    \
    __global const float* a = A + (size_t)b * S * ROWS;                                               \
    __global const float* y = Y + chunk * RC_VEC;                                                     \
    rc_vec acc[ROWS];                                                                                 \
    for (int r = 0; r < ROWS; ++r) acc[r] = (rc_vec)(0.0f);                                           \
    for (int s = 0; s < S; ++s) {                                                                     \
      const rc_vec yv = rc_vload(0, y + (size_t)s * RC_NP);                                           \
      for (int r = 0; r < ROWS; ++r) acc[r] = fma((rc_vec)(a[(size_t)s * ROWS + r]), yv, acc[r]);      \
    }                                                                                                 \
    for (int r = 0; r < ROWS; ++r) rc_vstore(acc[r], 0, C + ((size_t)b * ROWS + r) * RC_NP + chunk * RC_VEC); \
  }
RC_GEMM(rc_project_gemm3, 3)
RC_GEMM(rc_project_gemm9, 9)

/* Row (b, row) of C: scale radiance rows by the cell solid angle 2π/(M·N), turn by phi0[b] about z (the record
 * saw the pattern turned by phi0), and scatter into lambda / gradT / gradB [B][3][n2]. */
__kernel void rc_project_finish(const int B, const int rows, const float scale, __global const float* phi0,
                                __global const float* C, __global float* lambda, __global float* gradT,
                                __global float* gradB) {
  const int row = get_global_id(0), b = get_global_id(1);
  if (row >= rows || b >= B) return;
  float v[RC_N2];
  __global const float* c = C + ((size_t)b * rows + row) * RC_NP;
  const int channel = row % 3, which = row / 3;
  const float sc = which == 0 ? scale : 1.0f; /* gradient weights already carry their solid angles */
  for (int i = 0; i < RC_N2; ++i) v[i] = c[i] * sc;
  float cp;
  const float sp = sincos(phi0[b], &cp);
  rc_zrot(v, 1, cp, sp);
  __global float* dst = which == 0 ? lambda : which == 1 ? gradT : gradB;
  dst += ((size_t)b * 3 + channel) * RC_N2;
  for (int i = 0; i < RC_N2; ++i) dst[i] = v[i];
}
