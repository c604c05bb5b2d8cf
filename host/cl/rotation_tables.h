#pragma once
// Host-side tables the rotation kernels need, computed here in double independently of the
// scalar reference (host/sh) so that kernel-vs-reference tests compare two separate derivations.
#include <vector>

namespace rc::cl {

// Real orthonormal SH with Condon–Shortley phase (ARCHITECTURE.md §Conventions), double, order ≤ 20: out[n²].
void shEvalDouble(int order, double x, double y, double z, double* out);

// Band blocks of the SH rotation matrix for the +90° rotation about x (rotate(f, R) = f∘R⁻¹),
// concatenated: band l is a (2l+1)×(2l+1) row-major block starting at l(4l²−1)/3.
// Computed by Gauss–Legendre × uniform-φ quadrature, exact for these band-limited products.
// Cached per order; returned as float for the device.
const std::vector<float>& xRotation90Table(int order);

inline int bandBlockOffset(int l) { return l * (4 * l * l - 1) / 3; }

}  // namespace rc::cl
