#pragma once
// ShBackend on one OpenCL device: kernels/*.cl built once per SH order into one program
// (-D RC_ORDER=n -D RC_VEC=w, w from cl/device_tuning.h), batches split so every buffer fits CL_DEVICE_MAX_MEM_ALLOC_SIZE.
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "cl/cl_runtime.h"
#include "cl/device_tuning.h"
#include "cl/sh_backend.h"

namespace rc {

class OpenClBackend final : public ShBackend {
 public:
  explicit OpenClBackend(const cl::DeviceInfo& device);
  ~OpenClBackend() override;

  std::string deviceName() const override;
  bool isOpenCl() const override { return true; }
  int kernelThreads() const override;
  void project(const ProjectBatch& batch, ProjectResult& out) override;
  void rotate(const RotateBatch& batch, std::vector<float>& out) override;
  void interpolate(const InterpolateBatch& batch, std::vector<float>& out) override;
  void brdfDot(const BrdfDotBatch& batch, std::vector<float>& out) override;

  // Builds (or fetches from the process-wide cache) the program of one order; throws rc::Error
  // with the build log on failure. Used by "auto" to test that the device really works.
  void prepare(int order);
  const cl::DeviceInfo& device() const { return ctx_->info(); }
  // Largest buffer this backend allocates (min of the device's max allocation and a soft cap);
  // tests lower it to exercise batch splitting.
  void setMaxBufferBytes(size_t bytes) { maxBuffer_ = bytes; }
  size_t maxBufferBytes() const { return maxBuffer_; }

 private:
  struct OrderState;
  class Call;
  OrderState& state(int order);
  void ensureBasis(Call& call, const ProjectBatch& batch);
  // Work-items of a kernel that takes vectorWidth items per work-item, one per SIMD lane.
  size_t packs(long long items) const { return static_cast<size_t>((items + tuning_.vectorWidth - 1) / tuning_.vectorWidth); }
  void projectChunk(Call& call, const ProjectBatch& batch, long long first, long long count, ProjectResult& out);

  std::shared_ptr<cl::Context> ctx_;
  cl::DeviceTuning tuning_;
  std::map<int, std::unique_ptr<OrderState>> states_;
  size_t maxBuffer_ = 0;
  std::mutex mutex_;
};

}  // namespace rc
