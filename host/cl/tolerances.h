#pragma once
// The one tolerance table for kernel-vs-reference comparisons (tests/kernels and `rcache verify`).
// Kernels compute in float32, references accumulate in double, so every bound is
// (number of rounding steps) · ε · (a magnitude the inputs give), ε = 2⁻²⁴ (unit roundoff), using
// the classic bound |fl(Σ_k a_k b_k) − Σ_k a_k b_k| ≤ γ_K Σ_k |a_k b_k|, γ_K ≈ K·ε. They are
// deterministic worst-case bounds, not fitted to observed errors: a real bug (wrong sign, wrong
// cell, wrong convention) shows up as an O(1) relative error, orders of magnitude above them.
#include <cmath>

namespace rc::tol {

constexpr double kEps = 5.9604644775390625e-8;  // 2⁻²⁴

// Bound on |y_l^m| over the sphere for bands < order: √((2l+1)/(2π)) (the real basis carries √2).
inline double shMax(int order) { return std::sqrt((2.0 * order - 1.0) / (2.0 * 3.14159265358979323846)); }

// sh_project, Λ: an S-term sum of L_s·y_i(ω_s) (fma chain: γ_S), basis from an order-long
// recurrence (≈ 4 roundings per band → 4n·ε relative to shMax), the z-rotation by phi0 (2n
// roundings incl. the cos mφ recurrence) and the final scale: S + 6n + 8 steps, times
// magnitude = (2π/S)·Σ_s |L_c,s| · shMax(n).
inline double projectSteps(long long samples, int order) { return double(samples) + 6.0 * order + 8.0; }

// grad_accumulate, ∂Λ/∂t and ∂Λ/∂b: the same projection of per-cell weights wT_s, wB_s; each
// weight is ≤ 4 edge terms of ≈ 8 roundings (angles, sin/cos, ρ, L difference), so the weights
// themselves are good to 32ε: S + 6n + 40 steps, times
// magnitude = shMax(n) · Σ_edges |edge coefficient|·max(ρ, ρ')·(|L| + |L'|), which bounds
// Σ_s (|wT_s| + |wB_s|) (edge coefficient 2 sin(π/N)·c_j s_j or Δθ_j, see host/sh/reference.h).
inline double gradSteps(long long samples, int order) { return double(samples) + 6.0 * order + 40.0; }

// sh_rotate, band l: Dz(γ)·Jᵀ·Dz(β)·J·Dz(α). Each J product is a (2l+1)-term dot with a row of
// unit norm (≤ (2l+1)ε‖x_l‖), each Dz costs ≤ (2m+2)ε‖x_l‖ (cos mα by recurrence), the float
// J table adds ε/2·√(2l+1), and the Euler (cos, sin) pairs taken from a float R are good to
// ≈ 4ε each, i.e. ≈ 4lε of rotation error: about 14l + 10 steps, rounded up to 16(l+1),
// times magnitude = ‖x_l‖₂ (that band of that channel).
inline double rotateSteps(int l) { return 16.0 * (l + 1); }

// interpolate, band l: per contribution v = Λ + dt·∂Λ/∂t + db·∂Λ/∂b (2 roundings), one
// rotation (rotateSteps; in per-record mode R = F_p·F_rᵀ is formed in float, +6ε), a K-term
// weighted sum (γ_K) and the division by Σw (2ε): rotateSteps(l) + K + 12 steps, times
// magnitude = Σ_k w_k (‖Λ_l‖ + |dt|‖∂Λ/∂t_l‖ + |db|‖∂Λ/∂b_l‖) / Σ_k w_k.
inline double interpolateSteps(int l, int contributions) { return rotateSteps(l) + contributions + 12.0; }

// brdf_dot: n²-term dot product (γ_{n²}), lerp of the table (3ε), the z-rotation folded in
// (2n for cos mφ by recurrence + 4 per pair) and the lookup coordinate tan(θ/2) computed in
// float (its error ≈ 2ε moves the lerp weight by 2ε·(T−1), i.e. up to 2(T−1)ε of a table
// step): n² + 6n + 8 + 2T steps, times magnitude = Σ_i |Λ_c,i| · max_t |F_c,i(t)|.
inline double brdfDotSteps(int order, int res) { return double(order) * order + 6.0 * order + 8.0 + 2.0 * res; }

// Absolute floor for all families: outputs that are exactly 0 in both (missing coefficients,
// ω_o below the horizon, points without contributions) must still be exactly 0 up to denormals.
constexpr double kAbsFloor = 1e-30;

}  // namespace rc::tol
