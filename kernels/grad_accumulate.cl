/* grad_accumulate: per-sample weights of the translational gradients ∂Λ/∂t, ∂Λ/∂b, exactly the
 * formula documented in host/sh/reference.h (Ward–Heckbert edges for equal-solid-angle cells,
 * each edge term shared half/half by its two cells). Writes rows 0..8 of the GEMM operand
 * A[b][s][row] (0..2 radiance, 3..5 wT per channel, 6..8 wB per channel); sh_project.cl's
 * rc_project_gemm9 + rc_project_finish then project them with the shared basis matrix. */
#include "shared/rc_types.h"
#ifndef RC_ORDER
#define RC_ORDER 10
#endif


/* Radiance of sample i (0 if any channel is NaN/Inf) and its inverse distance ρ (0 for a miss,
 * r clamped to ≥ minDistance so r → 0 never gives Inf). */
inline float3 rc_grad_sample(__global const float* radiance, __global const float* distance, size_t i,
                             float minDistance, float* rho) {
  const float3 L = (float3)(radiance[3 * i], radiance[3 * i + 1], radiance[3 * i + 2]);
  const float r = distance[i];
  *rho = (r > 0.0f && isfinite(r)) ? 1.0f / fmax(r, minDistance) : 0.0f;
  return (isfinite(L.x) && isfinite(L.y) && isfinite(L.z)) ? L : (float3)(0.0f);
}

/* geo (per pattern grid, from the host in double): [0..M] arc·c_j·s_j (elevation edge factor at
 * boundary j), [M+1 .. 2M] Δθ_j, then per azimuth column k: cos φ_k, sin φ_k (centre),
 * cos φ_{k−}, sin φ_{k−} (lower boundary), all at phi0 = 0. phiCS[b] = (cos phi0, sin phi0):
 * the record's turn is applied by angle addition, so no trigonometry runs per sample. */
__kernel void rc_grad_prep(const int M, const int N, const int B, const float minDistance, __global const float* geo,
                           __global const float* phiCS, __global const float* radiance, __global const float* distance,
                           __global float* A, __global int* dropped) {
  const int s = get_global_id(0), b = get_global_id(1);
  const int S = M * N;
  if (s >= S || b >= B) return;
  const int j = s / N, k = s - j * N;
  const size_t rec = (size_t)b * S;
  const size_t i = rec + s;
  if (!(isfinite(radiance[3 * i]) && isfinite(radiance[3 * i + 1]) && isfinite(radiance[3 * i + 2])))
    atomic_inc(dropped + b);

  float rho, rhoUp = 0.0f, rhoDown = 0.0f, rhoPrev, rhoNext;
  const float3 L = rc_grad_sample(radiance, distance, i, minDistance, &rho);

  /* Elevation edges: E_{j,k} with the cell above (j ≥ 1), E_{j+1,k} with the cell below (j+1 ≤ M−1).
   * E_{j,k} = 2 sin(π/N)·c_j s_j·max(ρ, ρ')·(L_{j,k} − L_{j−1,k}). */
  float3 E = (float3)(0.0f);
  if (j >= 1) {
    const float3 Lu = rc_grad_sample(radiance, distance, i - N, minDistance, &rhoUp);
    E += geo[j] * fmax(rho, rhoUp) * (L - Lu);
  }
  if (j + 1 <= M - 1) {
    const float3 Ld = rc_grad_sample(radiance, distance, i + N, minDistance, &rhoDown);
    E += geo[j + 1] * fmax(rho, rhoDown) * (Ld - L);
  }
  /* Azimuth edges: A_{j,k} with k−1 and A_{j,k+1} with k+1 (both wrap modulo N),
   * A = Δθ_j·max(ρ, ρ')·(L_right − L_left). */
  const float dTheta = geo[M + 1 + j];
  const int kPrev = k == 0 ? N - 1 : k - 1, kNext = k == N - 1 ? 0 : k + 1;
  const float3 Lp = rc_grad_sample(radiance, distance, rec + j * N + kPrev, minDistance, &rhoPrev);
  const float3 Ln = rc_grad_sample(radiance, distance, rec + j * N + kNext, minDistance, &rhoNext);
  const float3 Aprev = dTheta * fmax(rho, rhoPrev) * (L - Lp);
  const float3 Anext = dTheta * fmax(rho, rhoNext) * (Ln - L);

  const float c0 = phiCS[2 * b], s0 = phiCS[2 * b + 1];
  __global const float* col = geo + 2 * M + 1;
  const float cm = col[4 * k], sm = col[4 * k + 1], cl = col[4 * k + 2], sl = col[4 * k + 3];
  const float ch = col[4 * kNext + 2], sh = col[4 * kNext + 3]; /* φ_{(k+1)−} (k = N−1 wraps by 2π) */
  const float cMid = cm * c0 - sm * s0, sMid = sm * c0 + cm * s0;
  const float cLo = cl * c0 - sl * s0, sLo = sl * c0 + cl * s0;
  const float cHi = ch * c0 - sh * s0, sHi = sh * c0 + ch * s0;
  const float3 wT = 0.5f * (E * cMid - (Aprev * sLo + Anext * sHi));
  const float3 wB = 0.5f * (E * sMid + (Aprev * cLo + Anext * cHi));

  __global float* a = A + i * 9;
  a[0] = L.x;
  a[1] = L.y;
  a[2] = L.z;
  a[3] = wT.x;
  a[4] = wT.y;
  a[5] = wT.z;
  a[6] = wB.x;
  a[7] = wB.y;
  a[8] = wB.z;
}
