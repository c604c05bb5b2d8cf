#include "cl/fallback_backend.h"

#include <iostream>

#include "core/error.h"
#include "core/timing.h"

namespace rc {

FallbackBackend::FallbackBackend(std::unique_ptr<ShBackend> primary, std::function<void(const std::string&)> notice)
    : primary_(std::move(primary)), notice_(std::move(notice)) {
  if (!primary_) throw Error("FallbackBackend: no primary backend");
}

std::string FallbackBackend::deviceName() const {
  if (!fellBack_) return primary_->deviceName();
  return scalar_->deviceName() + " (after " + primary_->deviceName() + " failed: " + reason_ + ")";
}

template <class Call>
void FallbackBackend::run(Call&& call, double& seconds) {
  const auto t0 = SteadyClock::now();
  if (!fellBack_) {
    try {
      call(*primary_);
      times_.programs = primary_->times().programs;
      times_.programsFromBinaryCache = primary_->times().programsFromBinaryCache;
      seconds += secondsSince(t0);
      return;
    } catch (const Error& e) {
      fellBack_ = true;
      reason_ = e.what();
      scalar_ = makeScalarBackend();
      const std::string text = "OpenCL device failed during rendering (" + reason_ + "); continuing on " +
                               scalar_->deviceName();
      if (notice_) notice_(text);
      else std::cerr << "notice: " << text << "\n";
    }
  }
  call(*scalar_);
  seconds += secondsSince(t0);
}

void FallbackBackend::project(const ProjectBatch& batch, ProjectResult& out) {
  run([&](ShBackend& b) { b.project(batch, out); }, times_.project_s);
}
void FallbackBackend::rotate(const RotateBatch& batch, std::vector<float>& out) {
  run([&](ShBackend& b) { b.rotate(batch, out); }, times_.rotate_s);
}
void FallbackBackend::interpolate(const InterpolateBatch& batch, std::vector<float>& out) {
  run([&](ShBackend& b) { b.interpolate(batch, out); }, times_.interpolate_s);
}
void FallbackBackend::brdfDot(const BrdfDotBatch& batch, std::vector<float>& out) {
  run([&](ShBackend& b) { b.brdfDot(batch, out); }, times_.brdfDot_s);
}

}  // namespace rc
