#pragma once
// The batched SH math as the renderer sees it: one interface, two implementations.
//  * ScalarBackend: the scalar references (host/sh/reference.h) under parallelFor.
//  * OpenClBackend: kernels/*.cl on one OpenCL device, specialised on order with -D options.
// The renderer never cares which one it holds, except to print it in the statistics.
#include <memory>
#include <string>

#include "sh/batches.h"

namespace rc {

struct KernelTimes {  // accumulated wall time inside each family (host-observed, incl. transfers)
  double project_s = 0, rotate_s = 0, interpolate_s = 0, brdfDot_s = 0;
  // OpenCL programs (one per SH order) this backend built, and how many of them came from the
  // disk cache of program binaries instead of the compiler.
  int programs = 0, programsFromBinaryCache = 0;
};

class ShBackend {
 public:
  virtual ~ShBackend() = default;
  virtual std::string deviceName() const = 0;  // e.g. "cpu (scalar, 2 threads)" or "OpenCL: pthread-... (PoCL)"
  virtual bool isOpenCl() const = 0;
  // Host threads the kernels run on: the scalar backend's parallelFor threads, a CPU OpenCL
  // device's compute units (PoCL runs one thread per unit), 0 for a GPU (not host threads).
  virtual int kernelThreads() const = 0;

  virtual void project(const ProjectBatch& batch, ProjectResult& out) = 0;
  virtual void rotate(const RotateBatch& batch, std::vector<float>& out) = 0;
  virtual void interpolate(const InterpolateBatch& batch, std::vector<float>& out) = 0;
  virtual void brdfDot(const BrdfDotBatch& batch, std::vector<float>& out) = 0;

  const KernelTimes& times() const { return times_; }

 protected:
  KernelTimes times_;
};

// deviceSpec: "cpu" (scalar), "opencl" (first GPU, else first device), "opencl:P:D", or "auto"
// (= opencl if any device works, else cpu with a one-line notice on `notice`).
// Explicit "opencl..." with no usable device throws rc::Error with the reason.
// The environment variable RC_DEVICE supplies the spec when the caller passes "".
std::unique_ptr<ShBackend> makeShBackend(const std::string& deviceSpec, std::string* notice = nullptr);
std::unique_ptr<ShBackend> makeScalarBackend();

}  // namespace rc
