#include "cl/device_tuning.h"

namespace rc::cl {

DeviceTuning tuningFor(const DeviceInfo& device) {
  cl_uint preferred = 0;
  RC_CL_CHECK(clGetDeviceInfo(device.device, CL_DEVICE_PREFERRED_VECTOR_WIDTH_FLOAT, sizeof(preferred), &preferred,
                              nullptr));
  DeviceTuning t;
  // CPUs: their native SIMD width (16 with AVX-512). GPUs report 1 (their SIMD runs across
  // work-items): 8 keeps the padding of the GEMM tiles small.
  t.vectorWidth = preferred >= 16 ? 16 : 8;
  t.zeroCopy = device.type == "CPU";
  return t;
}

}  // namespace rc::cl
