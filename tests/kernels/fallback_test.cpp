// FallbackBackend: a device that fails mid-render hands the failed call and every later one to the
// scalar path, with exactly one notice; results equal the scalar reference.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cl/fallback_backend.h"
#include "cl/kernel_cases.h"
#include "core/error.h"
#include "core/parallel.h"
#include "sh/reference.h"

namespace rc {
namespace {

// Stands in for a device that works for `okCalls` calls, then fails like CL_OUT_OF_RESOURCES.
class FlakyBackend : public ShBackend {
 public:
  explicit FlakyBackend(int okCalls) : ok_(okCalls) {}
  std::string deviceName() const override { return "flaky test device"; }
  bool isOpenCl() const override { return true; }
  int kernelThreads() const override { return 0; }
  void project(const ProjectBatch& b, ProjectResult& out) override { step(); ref::project(b, out); }
  void rotate(const RotateBatch& b, std::vector<float>& out) override { step(); ref::rotate(b, out); }
  void interpolate(const InterpolateBatch& b, std::vector<float>& out) override { step(); ref::interpolate(b, out); }
  void brdfDot(const BrdfDotBatch& b, std::vector<float>& out) override { step(); ref::brdfDot(b, out); }
  int calls = 0;

 private:
  int ok_;
  void step() {
    if (calls++ >= ok_) throw Error("clEnqueueNDRangeKernel failed: CL_OUT_OF_RESOURCES (test)");
  }
};

TEST(FallbackBackend, DeviceFailureMidRenderFinishesOnScalarWithOneNotice) {
  auto flaky = std::make_unique<FlakyBackend>(2);
  FlakyBackend* raw = flaky.get();
  std::vector<std::string> notices;
  FallbackBackend backend(std::move(flaky), [&](const std::string& n) { notices.push_back(n); });
  EXPECT_TRUE(backend.isOpenCl());
  EXPECT_EQ(backend.kernelThreads(), 0);  // the stand-in device's own threads are not host threads
  for (int call = 0; call < 5; ++call) {
    RotateBatch b = cases::makeRotateBatch(6, 17, 100u + call, true);
    std::vector<float> ref, got;
    ref::rotate(b, ref);
    backend.rotate(b, got);  // calls 0, 1 on the device; 2 fails there and is redone on the scalar path
    EXPECT_EQ(got, ref) << "call " << call;
  }
  EXPECT_EQ(raw->calls, 3);  // the device is not asked again after its failure
  ASSERT_EQ(notices.size(), 1u);
  EXPECT_NE(notices[0].find("CL_OUT_OF_RESOURCES"), std::string::npos);
  EXPECT_TRUE(backend.fellBack());
  EXPECT_FALSE(backend.isOpenCl());
  EXPECT_EQ(backend.kernelThreads(), threadCount());  // the scalar path runs on the parallelFor threads
  EXPECT_NE(backend.deviceName().find("after flaky test device failed"), std::string::npos);
  EXPECT_GT(backend.times().rotate_s, 0.0);  // the time of all five calls, device and scalar, is counted
}

}  // namespace
}  // namespace rc
