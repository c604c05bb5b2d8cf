#pragma once
// Per-device launch parameters of the kernels, chosen from what the device reports (as CLBlast
// keeps its tuning in per-device tables, not in environment variables). One place to add a row
// when a new device class needs other values.
#include "cl/cl_runtime.h"

namespace rc::cl {

struct DeviceTuning {
  // SIMD width w of the vector kernels (-D RC_VEC=w): the GEMM's output tile of sh_project and the
  // items rotated side by side per work-item in sh_rotate. 4, 8 or 16.
  int vectorWidth = 8;
  // Inputs and outputs wrap the caller's arrays (CL_MEM_USE_HOST_PTR) instead of being copied:
  // right where host memory is device memory.
  bool zeroCopy = false;
};

DeviceTuning tuningFor(const DeviceInfo& device);

}  // namespace rc::cl
