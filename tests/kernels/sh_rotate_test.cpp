// sh_rotate kernel vs rc::ref::rotate.
#include "cl/kernel_cases.h"
#include "kernel_test_util.h"
#include "sh/reference.h"

namespace rc {
namespace {

class RotateOrders : public ::testing::TestWithParam<int> {};

TEST_P(RotateOrders, MatchesReferenceWithEdgeRotations) {
  RC_KERNEL_BACKEND(backend);
  const int order = GetParam();
  // identity, z-only, 180°, near-pole, near-identity, float-composed, then random rotations
  RotateBatch b = cases::makeRotateBatch(order, 200, 11u + order, true);
  std::vector<float> ref, got;
  ref::rotate(b, ref);
  backend->rotate(b, got);
  ASSERT_EQ(got.size(), ref.size());
  RC_EXPECT_WITHIN_TOLERANCE(cases::compareRotate(b, ref, got));
}

INSTANTIATE_TEST_SUITE_P(Kernels, RotateOrders, ::testing::Values(1, 2, 5, 10, 16));

TEST(RotateKernel, IdentityIsExact) {
  RC_KERNEL_BACKEND(backend);
  RotateBatch b = cases::makeRotateBatch(10, 1, 2u, true);  // item 0 is the identity
  std::vector<float> got;
  backend->rotate(b, got);
  EXPECT_EQ(got, b.coeffs);
}

TEST(RotateKernel, RotationThenInverseIsIdentity) {
  RC_KERNEL_BACKEND(backend);
  RotateBatch b = cases::makeRotateBatch(10, 64, 4u, false);
  std::vector<float> once, back;
  backend->rotate(b, once);
  RotateBatch inv = b;
  inv.coeffs = once;
  for (int i = 0; i < b.count; ++i)
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) inv.rotations[9 * i + 3 * r + c] = b.rotations[9 * i + 3 * c + r];
  backend->rotate(inv, back);
  double maxErr = 0;
  for (size_t k = 0; k < back.size(); ++k) maxErr = std::max(maxErr, double(std::fabs(back[k] - b.coeffs[k])));
  EXPECT_LT(maxErr, 2 * 16.0 * 10 * 5.96e-8 * 3);  // two rotations, rotateSteps(9)·ε·‖x_l‖ with ‖x_l‖ ≤ √19
}

}  // namespace
}  // namespace rc
