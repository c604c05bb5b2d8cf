// sh_project + grad_accumulate kernels vs rc::ref::project (tolerances: host/cl/tolerances.h).
#include <cmath>

#include "cl/kernel_cases.h"
#include "kernel_test_util.h"
#include "sh/reference.h"

namespace rc {
namespace {

class ProjectOrders : public ::testing::TestWithParam<int> {};

TEST_P(ProjectOrders, MatchesReferenceWithEdgeCases) {
  RC_KERNEL_BACKEND(backend);
  const int order = GetParam();
  // 12×48 cells (N = 4M), 6 records, NaN/Inf samples, misses, r → 0, constant radiance.
  ProjectBatch b = cases::makeProjectBatch(order, 12, 48, 6, 77u + order, true, true);
  ProjectResult ref, got;
  ref::project(b, ref);
  backend->project(b, got);
  ASSERT_EQ(got.lambda.size(), ref.lambda.size());
  ASSERT_EQ(got.gradT.size(), ref.gradT.size());
  EXPECT_GT(ref.dropped[0], 0);  // the edge record really has NaN/Inf samples
  EXPECT_EQ(got.dropped, ref.dropped);
  const cases::Stats lam = cases::compareProjectLambda(b, ref, got);
  RC_EXPECT_WITHIN_TOLERANCE(lam);
  const cases::Stats grad = cases::compareProjectGradients(b, ref, got);
  RC_EXPECT_WITHIN_TOLERANCE(grad);
  for (float v : got.gradT) ASSERT_TRUE(std::isfinite(v));  // r → 0 is clamped, never Inf
  for (float v : got.gradB) ASSERT_TRUE(std::isfinite(v));
}

INSTANTIATE_TEST_SUITE_P(Kernels, ProjectOrders, ::testing::Values(1, 2, 5, 10, 16));

TEST(ProjectKernel, ConstantRadianceGivesTwoPiY00AndZeroGradient) {
  RC_KERNEL_BACKEND(backend);
  ProjectBatch b = cases::makeProjectBatch(5, 8, 32, 4, 5u, true, true);  // record 2 is L ≡ 1
  ProjectResult got;
  backend->project(b, got);
  const int n2 = 25;
  const float expected = static_cast<float>(2 * 3.14159265358979323846 * 0.28209479177387814);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(got.lambda[(2 * 3 + c) * n2], expected, 1e-5f);
    for (int i = 0; i < n2; ++i) {
      EXPECT_EQ(got.gradT[(2 * 3 + c) * n2 + i], 0.0f);  // no radiance difference across any edge
      EXPECT_EQ(got.gradB[(2 * 3 + c) * n2 + i], 0.0f);
    }
  }
}

TEST(ProjectKernel, WithoutGradientsAndOddGrids) {
  RC_KERNEL_BACKEND(backend);
  for (int grid : {1, 3}) {  // 1×1 and 3×7 cells: wrap-around and tiny grids
    ProjectBatch b = cases::makeProjectBatch(10, grid, grid == 1 ? 1 : 7, 3, 9u, grid == 3, false);
    ProjectResult ref, got;
    ref::project(b, ref);
    backend->project(b, got);
    EXPECT_EQ(got.gradT.empty(), !b.gradients);
    RC_EXPECT_WITHIN_TOLERANCE(cases::compareProjectLambda(b, ref, got));
    if (b.gradients) RC_EXPECT_WITHIN_TOLERANCE(cases::compareProjectGradients(b, ref, got));
  }
}

TEST(ProjectKernel, BatchSplittingGivesTheSameResult) {
  RC_KERNEL_BACKEND(backend);
  ProjectBatch b = cases::makeProjectBatch(5, 8, 32, 7, 3u, true, false);
  ProjectResult whole, split;
  backend->project(b, whole);
  const size_t saved = backend->maxBufferBytes();
  backend->setMaxBufferBytes(2 * 8 * 32 * 9 * sizeof(float));  // two records per launch
  backend->project(b, split);
  backend->setMaxBufferBytes(saved);
  EXPECT_EQ(whole.lambda, split.lambda);
  EXPECT_EQ(whole.gradT, split.gradT);
  EXPECT_EQ(whole.gradB, split.gradB);
}

TEST(ProjectKernel, MalformedBatchThrows) {
  RC_KERNEL_BACKEND(backend);
  ProjectBatch b = cases::makeProjectBatch(5, 4, 16, 2, 1u, true, false);
  b.radiance.pop_back();
  ProjectResult out;
  EXPECT_THROW(backend->project(b, out), Error);
  b = cases::makeProjectBatch(17, 4, 16, 2, 1u, true, false);
  EXPECT_THROW(backend->project(b, out), Error);  // kernels support orders 1..16
}

}  // namespace
}  // namespace rc
