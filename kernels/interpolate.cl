/* interpolate: Λ(p) = Σ w_c·Rot_c(Λ_r + dt·∂Λ_r/∂t + db·∂Λ_r/∂b) / Σ w_c (host/sh/batches.h
 * InterpolateBatch). One work-item per shading point. Per-record mode rotates every contribution
 * from the record's frame into p's; world-frame mode sums in world frame and rotates once
 * (rotation is linear and the weights are scalars, ARCHITECTURE.md §Kernels). */
#include "shared/rc_types.h"
#ifndef RC_ORDER
#define RC_ORDER 10
#endif
#include "shared/rc_sh_device.h"

__kernel void rc_interpolate(const int points, const int worldFrame, const int gradients,
                             __global const float* lambda, __global const float* gradT,
                             __global const float* gradB, __global const float* recordFrames,
                             __global const float* pointFrames, __global const int* offsets,
                             __global const RcContribution* entries, __constant const float* J,
                             __global float* out) {
  const int p = get_global_id(0);
  if (p >= points) return;
  float acc[3 * RC_N2];
  for (int i = 0; i < 3 * RC_N2; ++i) acc[i] = 0.0f;
  float Fp[9];
  for (int k = 0; k < 9; ++k) Fp[k] = pointFrames[9 * p + k];
  float wsum = 0.0f;
  const int e0 = offsets[p], e1 = offsets[p + 1];
  for (int e = e0; e < e1; ++e) {
    const RcContribution c = entries[e];
    const size_t base = (size_t)c.record * 3 * RC_N2;
    if (worldFrame) {
      if (gradients) {
        for (int i = 0; i < 3 * RC_N2; ++i)
          acc[i] = fma(c.weight, fma(c.db, gradB[base + i], fma(c.dt, gradT[base + i], lambda[base + i])), acc[i]);
      } else {
        for (int i = 0; i < 3 * RC_N2; ++i) acc[i] = fma(c.weight, lambda[base + i], acc[i]);
      }
    } else {
      float v[3 * RC_N2];
      if (gradients) {
        for (int i = 0; i < 3 * RC_N2; ++i)
          v[i] = fma(c.db, gradB[base + i], fma(c.dt, gradT[base + i], lambda[base + i]));
      } else {
        for (int i = 0; i < 3 * RC_N2; ++i) v[i] = lambda[base + i];
      }
      /* Rot(a,b) = e_p,a · e_r,b with frames stored as rows t, b, n in world coordinates. */
      float R[9];
      __global const float* Fr = recordFrames + 9 * (size_t)c.record;
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
          R[3 * a + b] = Fp[3 * a] * Fr[3 * b] + Fp[3 * a + 1] * Fr[3 * b + 1] + Fp[3 * a + 2] * Fr[3 * b + 2];
      rc_rotate3(v, R, J);
      for (int i = 0; i < 3 * RC_N2; ++i) acc[i] = fma(c.weight, v[i], acc[i]);
    }
    wsum += c.weight;
  }
  __global float* dst = out + (size_t)p * 3 * RC_N2;
  if (!(wsum > 0.0f)) {
    for (int i = 0; i < 3 * RC_N2; ++i) dst[i] = 0.0f;
    return;
  }
  const float inv = 1.0f / wsum;
  for (int i = 0; i < 3 * RC_N2; ++i) acc[i] *= inv;
  if (worldFrame) rc_rotate3(acc, Fp, J); /* world → p: Rot(a,b) = e_p,a · world_b = Fp[3a+b] */
  for (int i = 0; i < 3 * RC_N2; ++i) dst[i] = acc[i];
}
