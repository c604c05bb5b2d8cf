// brdf_dot kernel vs rc::ref::brdfDot.
#include "cl/kernel_cases.h"
#include "kernel_test_util.h"
#include "sh/reference.h"

namespace rc {
namespace {

class BrdfDotOrders : public ::testing::TestWithParam<int> {};

TEST_P(BrdfDotOrders, MatchesReference) {
  RC_KERNEL_BACKEND(backend);
  const int order = GetParam();
  // isotropic table at the batch order, one of another order, an anisotropic 2-D table;
  // ω_o = normal, grazing, on and below the horizon, random.
  BrdfDotBatch b = cases::makeBrdfDotBatch(order, 600, 41u + order);
  std::vector<float> ref, got;
  ref::brdfDot(b, ref);
  backend->brdfDot(b, got);
  ASSERT_EQ(got.size(), ref.size());
  RC_EXPECT_WITHIN_TOLERANCE(cases::compareBrdfDot(b, ref, got));
  for (int p = 0; p < b.points; ++p)
    if (!(b.wo[3 * p + 2] > 0.0f))
      for (int c = 0; c < 3; ++c) ASSERT_EQ(got[3 * p + c], 0.0f);
}

INSTANTIATE_TEST_SUITE_P(Kernels, BrdfDotOrders, ::testing::Values(1, 2, 5, 10, 16));

TEST(BrdfDotKernel, BadMaterialThrows) {
  RC_KERNEL_BACKEND(backend);
  BrdfDotBatch b = cases::makeBrdfDotBatch(3, 8, 1u);
  b.material[5] = 3;
  std::vector<float> out;
  EXPECT_THROW(backend->brdfDot(b, out), Error);
}

}  // namespace
}  // namespace rc
