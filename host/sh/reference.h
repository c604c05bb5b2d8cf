#pragma once
// Scalar references of the kernel families (ARCHITECTURE.md §Kernels): plain C++, double accumulation, no code
// shared with kernels/*.cl. Same contracts as the kernels (host/sh/batches.h). These also serve
// as the renderer's CPU path (run per item under parallelFor by the scalar backend).
#include <vector>

#include "sh/batches.h"

namespace rc::ref {

// ---- Translational gradient of project() (grad_accumulate), exact definition -------------------
// Derivation (Ward–Heckbert 1992 applied to the SH projection, equal-solid-angle cells): each
// cell (j,k) sees a patch of constant radiance L_jk at distance r_jk. Moving p by δ·d (d in the
// tangent plane) moves the image of a point at distance r by dω = −(δ/r)(d − (d·ω)ω), so the
// edges between neighbouring cells' contents sweep thin bands: Λ_i changes by
// (radiance gained − radiance lost) × (swept solid angle) × y_i on the edge.
//  * elevation edge between (j−1,k) and (j,k) at θ_{j−}: dθ = −(δ/r) cos θ (d·û(φ)); band area
//    sin θ |dθ| dφ; integrating û(φ) over the cell's arc [φ_{k−}, φ_{k+1−}] gives 2 sin(π/N) û_k
//    exactly (the seed's 2π/N is its small-angle limit).
//  * azimuth edge between (j,k−1) and (j,k) at φ_{k−}: dφ = −(δ/r)(d·v̂_k)/sin θ; band area
//    sin θ |dφ| dθ, so the sin θ cancels and the cell's angular height Δθ_j remains (the seed's
//    1/(M sin θ_jk) is its first-order approximation, singular in the pole cell j = 0).
//  * the edge moves with the nearer surface: 1/min(r, r').
// Notation (M, N, phi0 = φ0 of the record; s = j*N + k; channel c implicit):
//   c_j = 1 − j/M, s_j = sqrt(1 − c_j²)          elevation boundaries j = 0..M (θ_{0−} = pole)
//   Δθ_j = acos(c_{j+1}) − acos(c_j)              angular height of row j = 0..M−1
//   φ_{k−} = 2πk/N + φ0 (boundaries), φ_k = 2π(k + ½)/N + φ0 (cell centres), k = 0..N−1
//   û_k = (cos φ_k, sin φ_k),  v̂_k = (−sin φ_{k−}, cos φ_{k−})        in (t, b) coordinates
//   ρ_s = 0 for a miss (r ≤ 0 or non-finite), else 1 / max(r_s, minDistance)
//   L_s = radiance of channel c, 0 when the sample is dropped (any channel NaN/Inf)
// Edge terms (k ± 1 wrap modulo N; every k has an azimuth edge, including k = 0 against N−1):
//   E_{j,k} = 2 sin(π/N) · c_j s_j · max(ρ_{j,k}, ρ_{j−1,k}) · (L_{j,k} − L_{j−1,k})   j = 1..M−1
//   E_{0,k} = E_{M,k} = 0      (pole: zero-length edge; horizon: c_M = 0, nothing below counts)
//   A_{j,k} = Δθ_j · max(ρ_{j,k}, ρ_{j,k−1}) · (L_{j,k} − L_{j,k−1})                 j = 0..M−1
// Gradient = Σ_edges (term · direction · y_i on the edge). y_i on an edge is taken as the mean of
// its two cells' sample values (trapezoid: second order; the seed puts the whole edge on one
// cell, a first-order bias of half a cell). So every edge term goes half to each adjacent cell,
// giving per-cell scalar weights and then the same projection as Λ (no 2π/(MN) factor):
//   wT_{j,k} = ½(E_{j,k} + E_{j+1,k}) cos φ_k − ½(A_{j,k} sin φ_{k−} + A_{j,k+1} sin φ_{(k+1)−})
//   wB_{j,k} = ½(E_{j,k} + E_{j+1,k}) sin φ_k + ½(A_{j,k} cos φ_{k−} + A_{j,k+1} cos φ_{(k+1)−})
//   ∂Λ_c,i/∂t = Σ_s wT_s y_i(ω_s),   ∂Λ_c,i/∂b = Σ_s wB_s y_i(ω_s)
// (φ_{(k+1)−} for k = N−1 is φ_{0−} + 2π: same sin/cos.) Misses have ρ = 0, so an edge between
// two misses contributes nothing and an edge next to a miss moves with the hit's distance.
// Verified against central finite differences of Λ at displaced points (tests/sh).

// Outputs are resized by the callee. Each function validates the batch (sizes, order range
// 1..kMaxReferenceOrder) and throws rc::Error with a precise message on a malformed batch.
void project(const ProjectBatch& batch, ProjectResult& out);
void rotate(const RotateBatch& batch, std::vector<float>& out);             // [B][3][n2]
void interpolate(const InterpolateBatch& batch, std::vector<float>& out);   // [P][3][n2]
void brdfDot(const BrdfDotBatch& batch, std::vector<float>& out);           // [P][3]

// Item-range versions used by the multi-threaded scalar backend: process records/points
// [begin, end) only; `out` must already have the full size.
void projectRange(const ProjectBatch& batch, ProjectResult& out, int begin, int end);
void rotateRange(const RotateBatch& batch, std::vector<float>& out, int begin, int end);
void interpolateRange(const InterpolateBatch& batch, std::vector<float>& out, int begin, int end);
void brdfDotRange(const BrdfDotBatch& batch, std::vector<float>& out, int begin, int end);

}  // namespace rc::ref
