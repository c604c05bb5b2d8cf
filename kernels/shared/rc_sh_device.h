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

#ifndef RC_VEC /* SIMD width of the vector kernels (host: cl/device_tuning.h): 4, 8 or 16 */
#define RC_VEC 8
#endif
#define RC_CAT2(a, b) a##b
#define RC_CAT(a, b) RC_CAT2(a, b)
#define rc_vec RC_CAT(float, RC_VEC)
#define rc_vec_int RC_CAT(int, RC_VEC)
#define rc_vload RC_CAT(vload, RC_VEC)
#define rc_vstore RC_CAT(vstore, RC_VEC)

/* Sum of the lanes of an rc_vec. */
inline float rc_vec_sum(rc_vec v) {
#if RC_VEC == 16
  const float8 h8 = v.lo + v.hi;
  const float4 h = h8.lo + h8.hi;
#elif RC_VEC == 8
  const float4 h = v.lo + v.hi;
#else
  const float4 h = v;
#endif
  return (h.x + h.y) + (h.z + h.w);
}

/* The SH rotation, written once for an element type T and instantiated twice below (OpenCL C has
 * no templates): T = float rotates one item (interpolate), T = rc_vec rotates RC_VEC items side by
 * side, one per SIMD lane (sh_rotate: structure of arrays, so every operation is a vector one and
 * the x-90° table entries are shared by the lanes). MASK is the comparison result type of T, ANY
 * tests whether any lane of a MASK is set, S is the name suffix. */
#define RC_SCALAR_ANY(x) (x)
#define RC_ROTATION_FUNCTIONS(T, MASK, S, ANY)                                                              \
  /* Unit (cos, sin) of (x, y) in *c, *s; (1, 0) where it vanishes. */                                      \
  inline void rc_unit_cs##S(T x, T y, T* c, T* s) {                                                         \
    const T r = sqrt(x * x + y * y);                                                                        \
    const MASK ok = r > 0.0f;                                                                               \
    *c = ok ? x / r : (T)(1.0f);                                                                            \
    *s = ok ? y / r : (T)(0.0f);                                                                            \
  }                                                                                                         \
                                                                                                            \
  /* Rotation about z by the angle whose (cos, sin) is (c1, s1), in place: for each m > 0 the pair        \
   * (a, b) = (v[l,m], v[l,-m]) becomes (a·cos mα − b·sin mα, a·sin mα + b·cos mα). cos mα / sin mα come    \
   * from the angle-addition recurrence (error grows ~m·ε, m < 20). `channels` at stride RC_N2. */         \
  inline void rc_zrot##S(T* v, int channels, T c1, T s1) {                                                  \
    T cm = c1, sm = s1;                                                                                     \
    for (int m = 1; m < RC_ORDER; ++m) {                                                                    \
      for (int l = m; l < RC_ORDER; ++l)                                                                    \
        for (int c = 0; c < channels; ++c) {                                                                \
          const int ip = c * RC_N2 + l * (l + 1) + m, in = c * RC_N2 + l * (l + 1) - m;                     \
          const T a = v[ip], b = v[in];                                                                     \
          v[ip] = cm * a - sm * b;                                                                          \
          v[in] = sm * a + cm * b;                                                                          \
        }                                                                                                   \
      const T cn = cm * c1 - sm * s1;                                                                       \
      sm = sm * c1 + cm * s1;                                                                               \
      cm = cn;                                                                                              \
    }                                                                                                       \
  }                                                                                                         \
                                                                                                            \
  /* v (three channels) ← J·v, or Jᵀ·v with rowStart offset by RC_N2, band by band, except in the lanes   \
   * set in keep: J holds the band blocks of the SH rotation by +90° about x without their structural     \
   * zeros (host: rotation_tables.cpp, RcSparseEntry). Band 0 is 1. */                                    \
  inline void rc_apply_x90##S(T* v, __constant const int* rowStart, __constant const RcSparseEntry* J,     \
                              MASK keep) {                                                                  \
    T t0[2 * RC_ORDER - 1], t1[2 * RC_ORDER - 1], t2[2 * RC_ORDER - 1];                                     \
    for (int l = 1; l < RC_ORDER; ++l) {                                                                    \
      const int w = 2 * l + 1, first = l * l;                                                               \
      for (int i = 0; i < w; ++i) {                                                                         \
        T s0 = (T)(0.0f), s1 = (T)(0.0f), s2 = (T)(0.0f);                                                   \
        const int e1 = rowStart[first + i + 1];                                                             \
        for (int e = rowStart[first + i]; e < e1; ++e) {                                                    \
          const RcSparseEntry en = J[e];                                                                    \
          const T jv = (T)(en.value);                                                                       \
          s0 = fma(jv, v[en.column], s0);                                                                   \
          s1 = fma(jv, v[RC_N2 + en.column], s1);                                                           \
          s2 = fma(jv, v[2 * RC_N2 + en.column], s2);                                                       \
        }                                                                                                   \
        t0[i] = s0;                                                                                         \
        t1[i] = s1;                                                                                         \
        t2[i] = s2;                                                                                         \
      }                                                                                                     \
      for (int i = 0; i < w; ++i) {                                                                         \
        v[first + i] = keep ? v[first + i] : t0[i];                                                         \
        v[RC_N2 + first + i] = keep ? v[RC_N2 + first + i] : t1[i];                                         \
        v[2 * RC_N2 + first + i] = keep ? v[2 * RC_N2 + first + i] : t2[i];                                 \
      }                                                                                                     \
    }                                                                                                       \
  }                                                                                                         \
                                                                                                            \
  /* v (three channels, order RC_ORDER) ← rotate(v, R), R row-major proper rotation.                      \
   * zxzxz: R = Rz(α)·Ry(β)·Rz(γ) and Ry(β) = Rx(−90°)·Rz(β)·Rx(90°), so                                  \
   * D(R) = Dz(α)·Jᵀ·Dz(β)·J·Dz(γ). No trigonometric calls: cos/sin of the angles come from R.            \
   * Near the poles α and γ are individually ill-conditioned (from entries of size sin β), but            \
   * α+γ (β near 0) or α−γ (β near π) is not:                                                             \
   *   R00+R11 = (1+cos β)·cos(α+γ),  R10−R01 = (1+cos β)·sin(α+γ)                                        \
   *   R11−R00 = (1−cos β)·cos(α−γ),  −(R10+R01) = (1−cos β)·sin(α−γ)                                     \
   * so γ is derived from α and the well-conditioned sum/difference; an error in α then only              \
   * moves the result by O(error·sin β). Z-only rotations (incl. the identity, exactly) are one Dz(α+γ):  \
   * alone when every lane is one, else those lanes skip the x-90° steps and turn by 0 in the others. */  \
  inline void rc_rotate3##S(T* v, const T* R, __constant const int* rowStart, __constant const RcSparseEntry* J) { \
    const T sb2 = R[2] * R[2] + R[5] * R[5];                                                                \
    const MASK zOnly = sb2 <= 1e-14f && R[8] > 0.0f; /* R = Rz(σ) up to < 1e-7 rad of tilt */              \
    T sumC, sumS; /* α+γ */                                                                                 \
    rc_unit_cs##S(R[0] + R[4], R[3] - R[1], &sumC, &sumS);                                                  \
    if (!ANY(!zOnly)) {                                                                                     \
      if (ANY(sumS != 0.0f || sumC < 0.0f)) rc_zrot##S(v, 3, sumC, sumS);                                     \
      return;                                                                                               \
    }                                                                                                       \
    T ac, as, bc, bs, dc, ds;                                                                               \
    rc_unit_cs##S(R[2], R[5], &ac, &as);                                                                    \
    rc_unit_cs##S(R[8], sqrt(sb2), &bc, &bs);                                                               \
    rc_unit_cs##S(R[4] - R[0], -(R[3] + R[1]), &dc, &ds); /* α−γ */                                         \
    const MASK upper = R[8] >= 0.0f; /* γ = (α+γ) − α, else γ = α − (α−γ) */                               \
    T gc = upper ? sumC * ac + sumS * as : ac * dc + as * ds;                                               \
    T gs = upper ? sumS * ac - sumC * as : as * dc - ac * ds;                                               \
    gc = zOnly ? sumC : gc;                                                                                 \
    gs = zOnly ? sumS : gs;                                                                                 \
    bc = zOnly ? (T)(1.0f) : bc;                                                                            \
    bs = zOnly ? (T)(0.0f) : bs;                                                                            \
    ac = zOnly ? (T)(1.0f) : ac;                                                                            \
    as = zOnly ? (T)(0.0f) : as;                                                                            \
    rc_zrot##S(v, 3, gc, gs);                                                                                 \
    rc_apply_x90##S(v, rowStart, J, zOnly);                                                                 \
    rc_zrot##S(v, 3, bc, bs);                                                                                 \
    rc_apply_x90##S(v, rowStart + RC_N2, J, zOnly);                                                         \
    rc_zrot##S(v, 3, ac, as);                                                                                 \
  }

RC_ROTATION_FUNCTIONS(float, int, , RC_SCALAR_ANY)
RC_ROTATION_FUNCTIONS(rc_vec, rc_vec_int, _vec, any)

/* Unit (cos, sin) of the vector (x, y); (1, 0) when it vanishes. */
inline float2 rc_unit_angle(float x, float y) {
  float c, s;
  rc_unit_cs(x, y, &c, &s);
  return (float2)(c, s);
}

#endif /* RC_SH_DEVICE_H */
