// interpolate kernel vs rc::ref::interpolate, both modes; the two modes agree with each other.
#include "cl/kernel_cases.h"
#include "kernel_test_util.h"
#include "sh/reference.h"

namespace rc {
namespace {

struct InterpCase { int order; bool world; bool gradients; };
class InterpolateCases : public ::testing::TestWithParam<InterpCase> {};

TEST_P(InterpolateCases, MatchesReference) {
  RC_KERNEL_BACKEND(backend);
  const InterpCase c = GetParam();
  InterpolateBatch b = cases::makeInterpolateBatch(c.order, 24, 120, 31u + c.order, c.world, c.gradients);
  std::vector<float> ref, got;
  ref::interpolate(b, ref);
  backend->interpolate(b, got);
  ASSERT_EQ(got.size(), ref.size());
  RC_EXPECT_WITHIN_TOLERANCE(cases::compareInterpolate(b, ref, got));
  // points without contributions are exactly zero
  const int n2 = c.order * c.order;
  for (int p = 0; p < b.points; ++p)
    if (b.offsets[p] == b.offsets[p + 1])
      for (int i = 0; i < 3 * n2; ++i) ASSERT_EQ(got[3 * n2 * p + i], 0.0f);
}

INSTANTIATE_TEST_SUITE_P(Kernels, InterpolateCases,
                         ::testing::Values(InterpCase{1, false, true}, InterpCase{2, true, true},
                                           InterpCase{5, false, true}, InterpCase{5, true, false},
                                           InterpCase{10, false, true}, InterpCase{10, true, true},
                                           InterpCase{16, false, false}, InterpCase{16, true, true}));

TEST(InterpolateKernel, WorldFrameEqualsPerRecordRotation) {
  // Σ w_i R_{p←i} Λ_i = R_{p←world} Σ w_i R_{world←i} Λ_i: express the records in world frame
  // (rotate by R_{world←i} = F_iᵀ with the sh_rotate kernel), then both modes must agree.
  RC_KERNEL_BACKEND(backend);
  const int order = 6, n2 = 36;
  InterpolateBatch local = cases::makeInterpolateBatch(order, 16, 80, 5u, false, false);
  RotateBatch toWorld;
  toWorld.order = order;
  toWorld.count = local.records;
  toWorld.coeffs = local.lambda;
  toWorld.rotations.resize(9 * local.records);
  for (int r = 0; r < local.records; ++r)
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 3; ++c) toWorld.rotations[9 * r + 3 * a + c] = local.recordFrames[9 * r + 3 * c + a];
  InterpolateBatch world = local;
  world.worldFrame = true;
  backend->rotate(toWorld, world.lambda);
  std::vector<float> a, b;
  backend->interpolate(local, a);
  backend->interpolate(world, b);
  double maxErr = 0;
  for (size_t k = 0; k < a.size(); ++k) maxErr = std::max(maxErr, double(std::fabs(a[k] - b[k])));
  // Coefficients are O(1), bands ≤ 6: three rotations of ≤ rotateSteps(5)·ε·‖x_l‖ each.
  EXPECT_LT(maxErr, 3 * 96 * 5.96e-8 * std::sqrt(11.0) * 2);
  EXPECT_GT(a.size(), 0u);
  (void)n2;
}

TEST(InterpolateKernel, BadRecordIndexThrows) {
  RC_KERNEL_BACKEND(backend);
  InterpolateBatch b = cases::makeInterpolateBatch(3, 4, 10, 1u, true, true);
  ASSERT_FALSE(b.entries.empty());
  b.entries[0].record = 4;
  std::vector<float> out;
  EXPECT_THROW(backend->interpolate(b, out), Error);
}

}  // namespace
}  // namespace rc
