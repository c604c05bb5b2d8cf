/* interpolate: Λ(p) = Σ w_c·Rot_c(Λ_r + dt·∂Λ_r/∂t + db·∂Λ_r/∂b) / Σ w_c (host/sh/batches.h
 * InterpolateBatch). World-frame mode (rc_interpolate_world) sums in world frame and rotates once
 * (rotation is linear and the weights are scalars, ARCHITECTURE.md §Kernels): one work-item sums
 * RC_VEC points into the lanes of a structure of arrays and rotates them side by side, as sh_rotate
 * does. Per-record mode (rc_interpolate_record) rotates every contribution from its record's frame
 * into p's: one work-item per point. */
#include "shared/rc_types.h"
#ifndef RC_ORDER
#define RC_ORDER 10
#endif
#include "shared/rc_sh_device.h"

/* Contribution c's coefficient vector, Λ_r (+ dt·∂Λ/∂t + db·∂Λ/∂b), coefficient i. */
inline float rc_contribution(const RcContribution c, int gradients, __global const float* lambda,
                             __global const float* gradT, __global const float* gradB, size_t i) {
  const size_t k = (size_t)c.record * 3 * RC_N2 + i;
  return gradients ? fma(c.db, gradB[k], fma(c.dt, gradT[k], lambda[k])) : lambda[k];
}

__kernel void rc_interpolate_world(const int points, const int gradients, __global const float* lambda,
                                   __global const float* gradT, __global const float* gradB,
                                   __global const float* pointFrames, __global const int* offsets,
                                   __global const RcContribution* entries, __constant const int* rowStart,
                                   __constant const RcSparseEntry* J, __global float* out) {
  const int first = get_global_id(0) * RC_VEC;
  if (first >= points) return;
  const int lanes = min(RC_VEC, points - first);
  rc_vec acc[3 * RC_N2], F[9];
  float* a = (float*)acc; /* a[i·RC_VEC + lane] */
  float* f = (float*)F;
  for (int i = 0; i < 3 * RC_N2; ++i) acc[i] = (rc_vec)(0.0f);
  for (int j = 0; j < RC_VEC; ++j) {
    const int p = first + j;
    for (int k = 0; k < 9; ++k) f[k * RC_VEC + j] = j < lanes ? pointFrames[9 * p + k] : (k % 4 == 0 ? 1.0f : 0.0f);
    if (j >= lanes) continue;
    float wsum = 0.0f;
    for (int e = offsets[p]; e < offsets[p + 1]; ++e) {
      const RcContribution c = entries[e];
      for (int i = 0; i < 3 * RC_N2; ++i)
        a[i * RC_VEC + j] = fma(c.weight, rc_contribution(c, gradients, lambda, gradT, gradB, i), a[i * RC_VEC + j]);
      wsum += c.weight;
    }
    const float inv = 1.0f / wsum;
    for (int i = 0; i < 3 * RC_N2; ++i) a[i * RC_VEC + j] = wsum > 0.0f ? a[i * RC_VEC + j] * inv : 0.0f;
  }
  rc_rotate3_vec(acc, F, rowStart, J); /* world → p: Rot(a,b) = e_p,a · world_b = Fp[3a+b] */
  for (int j = 0; j < lanes; ++j) {
    __global float* dst = out + (size_t)(first + j) * 3 * RC_N2;
    for (int i = 0; i < 3 * RC_N2; ++i) dst[i] = a[i * RC_VEC + j];
  }
}

__kernel void rc_interpolate_record(const int points, const int gradients, __global const float* lambda,
                                    __global const float* gradT, __global const float* gradB,
                                    __global const float* recordFrames, __global const float* pointFrames,
                                    __global const int* offsets, __global const RcContribution* entries,
                                    __constant const int* rowStart, __constant const RcSparseEntry* J,
                                    __global float* out) {
  const int p = get_global_id(0);
  if (p >= points) return;
  float acc[3 * RC_N2];
  for (int i = 0; i < 3 * RC_N2; ++i) acc[i] = 0.0f;
  float Fp[9];
  for (int k = 0; k < 9; ++k) Fp[k] = pointFrames[9 * p + k];
  float wsum = 0.0f;
  for (int e = offsets[p]; e < offsets[p + 1]; ++e) {
    const RcContribution c = entries[e];
    float v[3 * RC_N2];
    for (int i = 0; i < 3 * RC_N2; ++i) v[i] = rc_contribution(c, gradients, lambda, gradT, gradB, i);
    /* Rot(a,b) = e_p,a · e_r,b with frames stored as rows t, b, n in world coordinates. */
    float R[9];
    __global const float* Fr = recordFrames + 9 * (size_t)c.record;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        R[3 * a + b] = Fp[3 * a] * Fr[3 * b] + Fp[3 * a + 1] * Fr[3 * b + 1] + Fp[3 * a + 2] * Fr[3 * b + 2];
    rc_rotate3(v, R, rowStart, J);
    for (int i = 0; i < 3 * RC_N2; ++i) acc[i] = fma(c.weight, v[i], acc[i]);
    wsum += c.weight;
  }
  __global float* dst = out + (size_t)p * 3 * RC_N2;
  const float inv = 1.0f / wsum;
  for (int i = 0; i < 3 * RC_N2; ++i) dst[i] = wsum > 0.0f ? acc[i] * inv : 0.0f; /* no contributions: 0 */
}
