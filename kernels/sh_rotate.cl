/* sh_rotate: out_b = rotate(in_b, R_b) for RGB coefficient vectors (host/sh/batches.h
 * RotateBatch). One work-item rotates RC_VEC consecutive items side by side, one per SIMD lane:
 * the items are transposed into a structure of arrays (coefficient-major, lane-minor) in private
 * memory, each rotation is built from its own R (zxzxz, see shared/rc_sh_device.h) and applied
 * with vector operations only; every x-90° table entry is loaded once for three channels of
 * RC_VEC items. A last, partial pack fills its idle lanes with the identity. */
#include "shared/rc_types.h"
#ifndef RC_ORDER
#define RC_ORDER 10
#endif
#include "shared/rc_sh_device.h"

__kernel void rc_sh_rotate(const int count, __global const float* rotations, __global const float* in,
                           __global float* out, __constant const int* rowStart, __constant const RcSparseEntry* J) {
  const int first = get_global_id(0) * RC_VEC;
  if (first >= count) return;
  const int lanes = min(RC_VEC, count - first);
  rc_vec R[9], v[3 * RC_N2];
  float* r = (float*)R; /* r[k·RC_VEC + lane] */
  float* s = (float*)v;
  for (int j = 0; j < RC_VEC; ++j) {
    __global const float* Rj = rotations + 9 * (size_t)(first + j);
    for (int k = 0; k < 9; ++k) r[k * RC_VEC + j] = j < lanes ? Rj[k] : (k % 4 == 0 ? 1.0f : 0.0f);
  }
  for (int j = 0; j < lanes; ++j) {
    __global const float* src = in + (size_t)(first + j) * 3 * RC_N2;
    for (int i = 0; i < 3 * RC_N2; ++i) s[i * RC_VEC + j] = src[i];
  }
  for (int j = lanes; j < RC_VEC; ++j)
    for (int i = 0; i < 3 * RC_N2; ++i) s[i * RC_VEC + j] = 0.0f;
  rc_rotate3_vec(v, R, rowStart, J);
  for (int j = 0; j < lanes; ++j) {
    __global float* dst = out + (size_t)(first + j) * 3 * RC_N2;
    for (int i = 0; i < 3 * RC_N2; ++i) dst[i] = s[i * RC_VEC + j];
  }
}
