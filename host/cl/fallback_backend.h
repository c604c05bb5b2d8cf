#pragma once
// A backend that runs on the OpenCL device and, if the device fails at run time (out of resources,
// lost device, a failed enqueue), says so once and finishes the render on the scalar references
// instead of aborting it: a render that can finish should not be lost to a device limit. Used for the default device choice only: an explicit --device opencl keeps failing
// loudly. The failed call is redone on the scalar path, so no batch is lost.
#include <functional>
#include <memory>
#include <string>

#include "cl/sh_backend.h"

namespace rc {

class FallbackBackend : public ShBackend {
 public:
  // notice(text) is called once, when the primary backend fails; empty → one line on stderr.
  FallbackBackend(std::unique_ptr<ShBackend> primary, std::function<void(const std::string&)> notice = {});

  std::string deviceName() const override;
  bool isOpenCl() const override { return !fellBack_ && primary_->isOpenCl(); }
  int kernelThreads() const override { return fellBack_ ? scalar_->kernelThreads() : primary_->kernelThreads(); }
  bool fellBack() const { return fellBack_; }

  void project(const ProjectBatch& batch, ProjectResult& out) override;
  void rotate(const RotateBatch& batch, std::vector<float>& out) override;
  void interpolate(const InterpolateBatch& batch, std::vector<float>& out) override;
  void brdfDot(const BrdfDotBatch& batch, std::vector<float>& out) override;

 private:
  std::unique_ptr<ShBackend> primary_, scalar_;
  std::function<void(const std::string&)> notice_;
  bool fellBack_ = false;
  std::string reason_;

  // Runs call(primary) unless fallen back; on rc::Error switches to the scalar backend (once) and
  // runs call(scalar). Adds the elapsed time to `seconds`.
  template <class Call>
  void run(Call&& call, double& seconds);
};

}  // namespace rc
