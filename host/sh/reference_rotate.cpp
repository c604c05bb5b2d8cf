// Scalar reference of sh_rotate (batches.h): out_b = rotate(in_b, R_b), double arithmetic,
// identity and z-only rotations through the fast paths of sh::rotateChannels.
#include <cmath>

#include "sh/reference.h"
#include "sh/reference_checks.h"
#include "sh/sh_basis.h"

namespace rc::ref {
namespace {

void validate(const char* fn, const RotateBatch& b) {
  detail::checkOrder(fn, b.order);
  detail::checkCount(fn, "count", b.count);
  detail::checkSize(fn, "rotations", b.rotations.size(), 9LL * b.count);
  detail::checkSize(fn, "coeffs", b.coeffs.size(), 3LL * b.order * b.order * b.count);
}

// A float rotation matrix is orthonormal to ~1e-7; 1e-3 only rejects what is not a rotation at
// all (a scale, a reflection, garbage), which would otherwise produce silently wrong SH.
void checkRotation(const char* fn, const double R[9], int item) {
  double err = 0;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      const double d = R[3 * r] * R[3 * c] + R[3 * r + 1] * R[3 * c + 1] + R[3 * r + 2] * R[3 * c + 2];
      err = std::fmax(err, std::fabs(d - (r == c ? 1.0 : 0.0)));
    }
  const double det = R[0] * (R[4] * R[8] - R[5] * R[7]) - R[1] * (R[3] * R[8] - R[5] * R[6]) +
                     R[2] * (R[3] * R[7] - R[4] * R[6]);
  if (!(err <= 1e-3) || !(det > 0))
    throw Error(std::string("ref::") + fn + ": rotation " + std::to_string(item) +
                " is not a proper rotation (|RRᵀ−I| = " + std::to_string(err) + ", det = " + std::to_string(det) + ")");
}

}  // namespace

void rotateRange(const RotateBatch& batch, std::vector<float>& out, int begin, int end) {
  validate("rotateRange", batch);
  const int n2 = batch.order * batch.order;
  detail::checkSize("rotateRange", "out", out.size(), 3LL * n2 * batch.count);
  detail::checkRange("rotateRange", begin, end, batch.count);
  std::vector<double> in(3 * n2), res(3 * n2);
  for (int b = begin; b < end; ++b) {
    double R[9];
    for (int i = 0; i < 9; ++i) R[i] = batch.rotations[9LL * b + i];
    checkRotation("rotateRange", R, b);
    const float* src = batch.coeffs.data() + 3LL * n2 * b;
    for (int i = 0; i < 3 * n2; ++i) in[i] = src[i];
    sh::rotateChannels(batch.order, R, 3, in.data(), res.data());
    float* dst = out.data() + 3LL * n2 * b;
    for (int i = 0; i < 3 * n2; ++i) dst[i] = static_cast<float>(res[i]);
  }
}

void rotate(const RotateBatch& batch, std::vector<float>& out) {
  validate("rotate", batch);
  out.assign(3ULL * batch.order * batch.order * batch.count, 0.0f);
  rotateRange(batch, out, 0, batch.count);
}

}  // namespace rc::ref
