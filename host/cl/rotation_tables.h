#pragma once
// Host-side tables the rotation kernels need, computed here in double independently of the
// scalar reference (host/sh) so that kernel-vs-reference tests compare two separate derivations.
#include <vector>

#include "rc_types.h"

namespace rc::cl {

// Real orthonormal SH with Condon–Shortley phase (ARCHITECTURE.md §Conventions), double, order ≤ 20: out[n²].
void shEvalDouble(int order, double x, double y, double z, double* out);

// Band blocks of the SH rotation matrix for the +90° rotation about x (rotate(f, R) = f∘R⁻¹),
// concatenated: band l is a (2l+1)×(2l+1) row-major block starting at l(4l²−1)/3.
// Computed by Gauss–Legendre × uniform-φ quadrature, exact for these band-limited products.
// Cached per order; returned as float for the device.
const std::vector<float>& xRotation90Table(int order);

// The same blocks without their structural zeros (about three quarters of the entries: the
// rotation commutes with x → −x and with Rx(180°), so each row only meets one parity class of
// its band), in CSR form for the kernels: rows 0 .. n²−1 are J, rows n² .. 2n²−1 are Jᵀ;
// row i's entries are entries[rowStart[i] .. rowStart[i+1]). Cached per order.
struct SparseRotation90 {
  std::vector<rc_int> rowStart;        // 2·n² + 1
  std::vector<RcSparseEntry> entries;  // column = flat SH index
};
const SparseRotation90& xRotation90Sparse(int order);

inline int bandBlockOffset(int l) { return l * (4 * l * l - 1) / 3; }

}  // namespace rc::cl
