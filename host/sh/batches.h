#pragma once
// Batched inputs/outputs of the four kernel families (ARCHITECTURE.md §Kernels). These layouts are the contract
// shared by the scalar references (host/sh/reference.h), the OpenCL kernels (kernels/*.cl) and
// the renderer. All arrays are flat, row-major, float32; "[B][3][n2]" means index
// (b*3 + channel)*n2 + i with i = l(l+1)+m the SH flat index and n2 = order*order.
// SH basis: real, orthonormal, Condon–Shortley phase (ARCHITECTURE.md §Conventions). Directions are in the local
// frame (t, b, n) of the record or shading point: x = t, y = b, z = n; θ from z, φ from x.
#include <cstdint>
#include <vector>

#include "rc_types.h"

namespace rc {

constexpr int kMaxKernelOrder = 16;  // kernels: orders 1..16
constexpr int kMaxReferenceOrder = 20;  // scalar reference: orders 1..20

// ---- sh_project + grad_accumulate ---------------------------------------------------------
// One record = M×N hemisphere cells, equal solid angle. Cell (j,k), j in [0,M) (elevation),
// k in [0,N) (azimuth), sample index s = j*N + k. Direction of cell (j,k) of record b:
//   cos θ = 1 − (j + ξ_s)/M,  φ = 2π(k + ζ_s)/N + phi0[b]
// where (ξ_s, ζ_s) = pattern[2s], pattern[2s+1] ∈ [0,1) is shared by the whole batch (so the
// basis matrix is shared: the projection is a GEMM) and phi0[b] turns the pattern per record.
// Λ_c,i = (2π/(M·N)) Σ_s L_c,s · y_i(ω_s).
// Gradients ∂Λ/∂t, ∂Λ/∂b: translational gradient of Λ along the record's own t and b axes, per
// the seed's formula for equal-solid-angle cells (see reference.h for the exact expression).
// Samples whose radiance is NaN/Inf (any channel) count as L = 0 for every term and are counted
// in dropped[b]. Distances: r ≤ 0 or non-finite means "no hit" (treated as +∞: a miss does not
// change with translation); finite r is clamped to at least minDistance (r → 0 never gives Inf).
struct ProjectBatch {
  int order = 10;
  int M = 0, N = 0;          // cells; M·N samples per record
  int records = 0;           // B
  float minDistance = 1e-4f; // clamp for r → 0
  bool gradients = true;     // compute gradT/gradB (else they are left empty)
  std::vector<float> pattern;   // [M*N][2]
  std::vector<float> phi0;      // [B]
  std::vector<float> radiance;  // [B][M*N][3]
  std::vector<float> distance;  // [B][M*N]
};
struct ProjectResult {
  std::vector<float> lambda;  // [B][3][n2]
  std::vector<float> gradT;   // [B][3][n2]  ∂Λ/∂t (per unit length along t)
  std::vector<float> gradB;   // [B][3][n2]
  std::vector<int32_t> dropped;  // [B] NaN/Inf samples dropped
};

// ---- sh_rotate ----------------------------------------------------------------------------
// out_b = rotate(in_b, R_b): the coefficients of f'(ω) = f(R⁻¹ω) (f turned by R). R_b is a
// proper rotation, row-major 3×3: rotations[9b + 3r + c] = R(r,c).
struct RotateBatch {
  int order = 10;
  int count = 0;                 // B
  std::vector<float> rotations;  // [B][9]
  std::vector<float> coeffs;     // [B][3][n2]
};

// ---- interpolate --------------------------------------------------------------------------
// For shading point p with contributions C_p (CSR: entries[offsets[p]..offsets[p+1])):
//   Λ(p) = Σ_{c∈C_p} w_c · Rot_c(Λ_r + dt·∂Λ_r/∂t + db·∂Λ_r/∂b) / Σ w_c
// Per-record mode (worldFrame = false): Λ_r and gradients are in record r's local frame
//   (recordFrames[9r..] = rows t_r, b_r, n_r in world coordinates) and Rot_c rotates from r's
//   frame into p's frame (pointFrames[9p..] = rows t_p, b_p, n_p): Rot = R with R(a,b) = e_p,a · e_r,b.
// World-frame mode (worldFrame = true): Λ_r and gradients are already expressed in the world
//   frame (rotated once at record creation); the weighted sum is formed in world frame and
//   rotated once into p's frame. Both modes give the same result up to float rounding.
// A point with no contributions or Σw = 0 gets Λ = 0.
struct InterpolateBatch {
  int order = 10;
  bool worldFrame = true;
  bool gradients = true;
  int records = 0;                     // R
  std::vector<float> lambda;           // [R][3][n2]
  std::vector<float> gradT, gradB;     // [R][3][n2] (may be empty if !gradients)
  std::vector<float> recordFrames;     // [R][9] (used only when !worldFrame)
  int points = 0;                      // P
  std::vector<float> pointFrames;      // [P][9]
  std::vector<int32_t> offsets;        // [P+1]
  std::vector<RcContribution> entries; // [offsets[P]]
};

// ---- brdf_dot -----------------------------------------------------------------------------
// L_o,c(p) = Σ_i Λ_c,i(p) · F_c,i(ω_o) where F is the material's BRDF×cos table, looked up at ω_o
// (local frame of p, ω_o.z may be ≤ 0 → result 0):
//  * RC_TABLE_ISOTROPIC_1D: table[T][3][n2] sampled at ω_o in the xz-plane (φ_o = 0) at parabolic
//    radius x_t = t/(T−1), i.e. θ_t = 2·atan(x_t); the lookup is linear in x = tan(θ_o/2), and the
//    looked-up vector is z-rotated by φ_o (rotate() by the rotation about z through angle φ_o).
//  * RC_TABLE_ANISOTROPIC_2D: table[S][S][3][n2] over the parabolic map (x, y) = (ω.x, ω.y)/(1+ω.z),
//    grid x_i = −1 + 2i/(S−1) (index [iy][ix]); bilinear. Grid nodes outside the unit disk hold the
//    value at the horizon direction of the same azimuth.
// The table's order may be lower than the batch order: missing coefficients are zero.
struct BrdfDotBatch {
  int order = 10;                  // order of lambda
  int points = 0;                  // P
  std::vector<float> lambda;       // [P][3][n2]
  std::vector<float> wo;           // [P][3] local frame, unit length
  std::vector<int32_t> material;   // [P] index into tables
  std::vector<RcBrdfTable> tables; // per material
  std::vector<float> tableData;    // flat storage referenced by RcBrdfTable::offset
};

}  // namespace rc
