#pragma once
// Real orthonormal spherical harmonics (ARCHITECTURE.md §Conventions): Condon–Shortley phase, flat index
// i = l(l+1)+m, order n = bands 0..n-1 (n² values). Stable recurrences, orders 1..20, in float
// and double. Direction given as a unit vector (x, y, z) in the local frame (θ from z, φ from x).
#include <vector>

namespace rc::sh {

constexpr int coeffCount(int order) { return order * order; }
constexpr int index(int l, int m) { return l * (l + 1) + m; }

// out[0 .. order²) = y_i(x, y, z). Throws rc::Error if order is outside 1..20.
void evalBasis(int order, double x, double y, double z, double* out);
void evalBasis(int order, float x, float y, float z, float* out);

// The clamped cosine max(cos θ, 0) convolved band by band, Â_l for l = 0..2 (π, 2π/3, π/4;
// Ramamoorthi & Hanrahan 2001): the irradiance of bands 0..2 is E(n) = Σ Â_l L_lm y_lm(n). Its
// bands 4, 6, ... (Â_4 = π/24) are what an order-3 irradiance leaves out.
constexpr float kClampedCosineBand[3] = {3.14159265f, 2.09439510f, 0.785398163f};

// Rotation matrix for real SH (block diagonal, band l is (2l+1)×(2l+1)), built from a 3×3
// proper rotation R (row-major): rotate(f) has coefficients of f'(ω) = f(R⁻¹ω).
// Stored as the concatenation of the band blocks, band l block row-major: total Σ(2l+1)² values.
void rotationMatrix(int order, const double R[9], std::vector<double>& bands);
void applyRotation(int order, const std::vector<double>& bands, const double* in, double* out);
// Fast path: rotation about z by angle alpha (same direction convention).
void rotateZ(int order, double alpha, const double* in, double* out);

// ---- additions (sh area): float fast path for the CPU renderer, and rotation classification ----
// Number of values in the block-diagonal rotation matrix of `order`: Σ_{l<order} (2l+1)².
constexpr int rotationMatrixSize(int order) { return order * (2 * order - 1) * (2 * order + 1) / 3; }
// Float build/apply (same convention and layout as the double versions); `bands` holds
// rotationMatrixSize(order) floats. No allocation: suitable per shading point.
void rotationMatrix(int order, const float R[9], float* bands);
void applyRotation(int order, const float* bands, const float* in, float* out);
void rotateZ(int order, float alpha, const float* in, float* out);
// True when R is the identity / a rotation about z within `tol` (max abs entry difference);
// for z-rotations alpha receives the angle (R = Rz(alpha)).
bool isIdentityRotation(const double R[9], double tol);
bool isZRotation(const double R[9], double tol, double& alpha);
// rotate(f) for any 3×3 rotation, picking the fast path: identity → copy, z-only → rotateZ,
// else Ivanic–Ruedenberg. `channels` vectors of order² values each, stored back to back.
// in and out may not alias. Tolerance: 1e-7 (below float resolution of the entries of R).
void rotateChannels(int order, const double R[9], int channels, const double* in, double* out);
void rotateChannels(int order, const float R[9], int channels, const float* in, float* out);

}  // namespace rc::sh
