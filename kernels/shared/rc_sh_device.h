/* Device-side SH helpers shared by the kernel families (OpenCL C only; inlined by the host's
 * program assembler). Conventions are ARCHITECTURE.md §Conventions: real orthonormal SH, Condon–Shortley phase,
 * flat index i = l(l+1)+m, rotate(f, R) = coefficients of f(R⁻¹ω).
 * Needs RC_ORDER (compile-time SH order) defined before inclusion. */
#ifndef RC_SH_DEVICE_H
#define RC_SH_DEVICE_H

#ifndef RC_ORDER
#define RC_ORDER 10
#endif
#define RC_N2 (RC_ORDER * RC_ORDER)

/* Rotation about z by the angle whose (cos, sin) is (c1, s1), in place: for each m > 0 the pair
 * (a, b) = (v[l,m], v[l,-m]) becomes (a·cos mα − b·sin mα, a·sin mα + b·cos mα).
 * cos mα / sin mα come from the angle-addition recurrence (error grows ~m·ε, m < 16). */
inline void rc_zrot(float* v, float c1, float s1) {
  float cm = c1, sm = s1;
  for (int m = 1; m < RC_ORDER; ++m) {
    for (int l = m; l < RC_ORDER; ++l) {
      const int ip = l * (l + 1) + m, in = l * (l + 1) - m;
      const float a = v[ip], b = v[in];
      v[ip] = cm * a - sm * b;
      v[in] = sm * a + cm * b;
    }
    const float cn = cm * c1 - sm * s1;
    sm = sm * c1 + cm * s1;
    cm = cn;
  }
}

inline void rc_zrot3(float* v, float c1, float s1) {
  rc_zrot(v, c1, s1);
  rc_zrot(v + RC_N2, c1, s1);
  rc_zrot(v + 2 * RC_N2, c1, s1);
}

/* v (three channels) ← J·v (transpose = 0) or Jᵀ·v (transpose = 1), band by band, where J holds
 * the band blocks of the SH rotation by +90° about x (host: rotation_tables.cpp). Band 0 is 1. */
inline void rc_apply_x90(float* v, __constant const float* J, int transpose) {
  float t0[2 * RC_ORDER - 1], t1[2 * RC_ORDER - 1], t2[2 * RC_ORDER - 1];
  for (int l = 1; l < RC_ORDER; ++l) {
    const int w = 2 * l + 1, base = l * (4 * l * l - 1) / 3, first = l * l;
    const int rs = transpose ? 1 : w, cs = transpose ? w : 1; /* row / column strides into J */
    for (int i = 0; i < w; ++i) {
      float s0 = 0.0f, s1 = 0.0f, s2 = 0.0f;
      for (int j = 0; j < w; ++j) {
        const float jv = J[base + i * rs + j * cs];
        s0 = fma(jv, v[first + j], s0);
        s1 = fma(jv, v[RC_N2 + first + j], s1);
        s2 = fma(jv, v[2 * RC_N2 + first + j], s2);
      }
      t0[i] = s0;
      t1[i] = s1;
      t2[i] = s2;
    }
    for (int i = 0; i < w; ++i) {
      v[first + i] = t0[i];
      v[RC_N2 + first + i] = t1[i];
      v[2 * RC_N2 + first + i] = t2[i];
    }
  }
}

/* Unit (cos, sin) of the vector (x, y); (1, 0) when it vanishes. */
inline float2 rc_unit_angle(float x, float y) {
  const float r = sqrt(x * x + y * y);
  return r > 0.0f ? (float2)(x / r, y / r) : (float2)(1.0f, 0.0f);
}

/* v (three channels, order RC_ORDER) ← rotate(v, R), R row-major proper rotation.
 * zxzxz: R = Rz(α)·Ry(β)·Rz(γ) and Ry(β) = Rx(−90°)·Rz(β)·Rx(90°), so
 * D(R) = Dz(α)·Jᵀ·Dz(β)·J·Dz(γ). No trigonometric calls: cos/sin of the angles come from R.
 * Near the poles α and γ are individually ill-conditioned (from entries of size sin β), but
 * α+γ (β near 0) or α−γ (β near π) is not:
 *   R00+R11 = (1+cos β)·cos(α+γ),  R10−R01 = (1+cos β)·sin(α+γ)
 *   R11−R00 = (1−cos β)·cos(α−γ),  −(R10+R01) = (1−cos β)·sin(α−γ)
 * so γ is derived from α and the well-conditioned sum/difference; an error in α then only
 * moves the result by O(error·sin β). Fast path: z-only rotations (incl. identity), one Dz. */
inline void rc_rotate3(float* v, const float* R, __constant const float* J) {
  const float sb2 = R[2] * R[2] + R[5] * R[5];
  if (sb2 <= 1e-14f && R[8] > 0.0f) { /* R = Rz(σ) up to < 1e-7 rad of tilt */
    const float2 a = rc_unit_angle(R[0] + R[4], R[3] - R[1]);
    if (a.y != 0.0f || a.x < 0.0f) rc_zrot3(v, a.x, a.y);
    return;
  }
  const float sb = sqrt(sb2);
  const float2 alpha = rc_unit_angle(R[2], R[5]);
  const float2 beta = rc_unit_angle(R[8], sb);
  float2 gamma;
  if (R[8] >= 0.0f) { /* γ = (α+γ) − α */
    const float2 sum = rc_unit_angle(R[0] + R[4], R[3] - R[1]);
    gamma = (float2)(sum.x * alpha.x + sum.y * alpha.y, sum.y * alpha.x - sum.x * alpha.y);
  } else { /* γ = α − (α−γ) */
    const float2 dif = rc_unit_angle(R[4] - R[0], -(R[3] + R[1]));
    gamma = (float2)(alpha.x * dif.x + alpha.y * dif.y, alpha.y * dif.x - alpha.x * dif.y);
  }
  rc_zrot3(v, gamma.x, gamma.y);
  rc_apply_x90(v, J, 0);
  rc_zrot3(v, beta.x, beta.y);
  rc_apply_x90(v, J, 1);
  rc_zrot3(v, alpha.x, alpha.y);
}

#endif /* RC_SH_DEVICE_H */
