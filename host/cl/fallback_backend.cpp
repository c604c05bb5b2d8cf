#include "cl/fallback_backend.h"

#include <chrono>
#include <iostream>

#include "core/error.h"

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
void FallbackBackend::run(Call&& call, double& seconds, long long& items, long long count) {
  const auto t0 = std::chrono::steady_clock::now();
  if (!fellBack_) {
    try {
      call(*primary_);
      times_.programs = primary_->times().programs;
      times_.programsFromBinaryCache = primary_->times().programsFromBinaryCache;
      seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      items += count;
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
  seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  items += count;
}

void FallbackBackend::project(const ProjectBatch& batch, ProjectResult& out) {
  run([&](ShBackend& b) { b.project(batch, out); }, times_.project_s, times_.projectItems, batch.records);
}
void FallbackBackend::rotate(const RotateBatch& batch, std::vector<float>& out) {
  run([&](ShBackend& b) { b.rotate(batch, out); }, times_.rotate_s, times_.rotateItems, batch.count);
}
void FallbackBackend::interpolate(const InterpolateBatch& batch, std::vector<float>& out) {
  run([&](ShBackend& b) { b.interpolate(batch, out); }, times_.interpolate_s, times_.interpolateItems,
      batch.points);
}
void FallbackBackend::brdfDot(const BrdfDotBatch& batch, std::vector<float>& out) {
  run([&](ShBackend& b) { b.brdfDot(batch, out); }, times_.brdfDot_s, times_.brdfDotItems,
      batch.points);
}

}  // namespace rc
