/* sh_rotate: out_b = rotate(in_b, R_b) for RGB coefficient vectors (host/sh/batches.h
 * RotateBatch). One work-item per vector; the rotation is built per item (zxzxz, see
 * shared/rc_sh_device.h) and applied to the three channels at once so the J table entries are
 * loaded once per three FMAs. */
#include "shared/rc_types.h"
#ifndef RC_ORDER
#define RC_ORDER 10
#endif
#include "shared/rc_sh_device.h"

__kernel void rc_sh_rotate(const int count, __global const float* rotations, __global const float* in,
                           __global float* out, __constant const int* rowStart, __constant const RcSparseEntry* J) {
  const int b = get_global_id(0);
  if (b >= count) return;
  float R[9];
  for (int k = 0; k < 9; ++k) R[k] = rotations[9 * b + k];
  float v[3 * RC_N2];
  __global const float* src = in + (size_t)b * 3 * RC_N2;
  for (int i = 0; i < 3 * RC_N2; ++i) v[i] = src[i];
  rc_rotate3(v, R, rowStart, J);
  __global float* dst = out + (size_t)b * 3 * RC_N2;
  for (int i = 0; i < 3 * RC_N2; ++i) dst[i] = v[i];
}
