// The scalar path (no OpenCL): the references of host/sh run per item range under parallelFor.
#include <algorithm>

#include "cl/sh_backend.h"
#include "core/parallel.h"
#include "core/timing.h"
#include "sh/reference.h"

namespace rc {

namespace {

// Chunks of ~8 per thread balance the load; the Range functions re-validate the batch per call,
// so chunks must not be tiny.
size_t chunkFor(int items, size_t minimum) {
  const size_t per = static_cast<size_t>(items) / (8 * static_cast<size_t>(threadCount())) + 1;
  return std::max(per, minimum);
}

class ScalarBackend final : public ShBackend {
 public:
  std::string deviceName() const override {
    return "cpu (scalar, " + std::to_string(threadCount()) + " threads)";
  }
  bool isOpenCl() const override { return false; }
  int kernelThreads() const override { return threadCount(); }

  void project(const ProjectBatch& b, ProjectResult& out) override {
    const auto t0 = SteadyClock::now();
    if (b.records <= 0 || b.order < 1) {
      ref::project(b, out);  // validates; empty result
    } else {
      const size_t n = 3ull * b.order * b.order * b.records;
      out.lambda.assign(n, 0.0f);
      out.gradT.assign(b.gradients ? n : 0, 0.0f);
      out.gradB.assign(b.gradients ? n : 0, 0.0f);
      out.dropped.assign(b.records, 0);
      parallelFor(b.records, chunkFor(b.records, 1), [&](size_t begin, size_t end) {
        ref::projectRange(b, out, static_cast<int>(begin), static_cast<int>(end));
      });
    }
    times_.project_s += secondsSince(t0);
  }

  void rotate(const RotateBatch& b, std::vector<float>& out) override {
    const auto t0 = SteadyClock::now();
    if (b.count <= 0 || b.order < 1) {
      ref::rotate(b, out);
    } else {
      out.assign(3ull * b.order * b.order * b.count, 0.0f);
      parallelFor(b.count, chunkFor(b.count, 64), [&](size_t begin, size_t end) {
        ref::rotateRange(b, out, static_cast<int>(begin), static_cast<int>(end));
      });
    }
    times_.rotate_s += secondsSince(t0);
  }

  void interpolate(const InterpolateBatch& b, std::vector<float>& out) override {
    const auto t0 = SteadyClock::now();
    if (b.points <= 0 || b.order < 1) {
      ref::interpolate(b, out);
    } else {
      out.assign(3ull * b.order * b.order * b.points, 0.0f);
      parallelFor(b.points, chunkFor(b.points, 64), [&](size_t begin, size_t end) {
        ref::interpolateRange(b, out, static_cast<int>(begin), static_cast<int>(end));
      });
    }
    times_.interpolate_s += secondsSince(t0);
  }

  void brdfDot(const BrdfDotBatch& b, std::vector<float>& out) override {
    const auto t0 = SteadyClock::now();
    if (b.points <= 0 || b.order < 1) {
      ref::brdfDot(b, out);
    } else {
      out.assign(3ull * b.points, 0.0f);
      parallelFor(b.points, chunkFor(b.points, 256), [&](size_t begin, size_t end) {
        ref::brdfDotRange(b, out, static_cast<int>(begin), static_cast<int>(end));
      });
    }
    times_.brdfDot_s += secondsSince(t0);
  }
};

}  // namespace

std::unique_ptr<ShBackend> makeScalarBackend() { return std::make_unique<ScalarBackend>(); }

}  // namespace rc
