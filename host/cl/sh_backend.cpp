// makeShBackend: "cpu" | "opencl" | "opencl:P:D" | "auto" (ARCHITECTURE.md §Kernels), RC_DEVICE when empty.
#include "cl/sh_backend.h"

#include <cstdlib>

#include "cl/cl_runtime.h"
#include "cl/fallback_backend.h"
#include "cl/opencl_backend.h"
#include "core/error.h"

namespace rc {

std::unique_ptr<ShBackend> makeShBackend(const std::string& deviceSpec, std::string* notice) {
  std::string spec = deviceSpec;
  if (spec.empty()) {
    const char* env = std::getenv("RC_DEVICE");
    spec = env && *env ? env : "auto";
  }
  const cl::DeviceSpec parsed = cl::parseDeviceSpec(spec);
  if (parsed.kind == cl::DeviceSpec::Scalar) return makeScalarBackend();
  if (parsed.kind != cl::DeviceSpec::Auto) {
    // Explicit OpenCL: any failure is the user's to see.
    try {
      return std::make_unique<OpenClBackend>(cl::selectDevice(parsed));
    } catch (const Error& e) {
      throw Error("--device " + spec + ": " + e.what());
    }
  }
  // auto: OpenCL if a device exists and really builds and runs our kernels, else scalar + notice.
  std::string reason;
  try {
    const std::vector<cl::DeviceInfo> devices = cl::enumerateDevices();
    if (devices.empty()) {
      reason = "no OpenCL platform found";
    } else {
      auto backend = std::make_unique<OpenClBackend>(cl::selectDevice(cl::DeviceSpec{cl::DeviceSpec::OpenClFirst}));
      backend->prepare(10);  // default glossy order: proves the compiler works on this device
      // A device that fails later (out of resources, lost) hands over to the scalar path.
      return std::make_unique<FallbackBackend>(std::move(backend));
    }
  } catch (const std::exception& e) {
    reason = std::string("OpenCL device unusable: ") + e.what();
  }
  auto scalar = makeScalarBackend();
  if (notice) *notice = reason + "; using " + scalar->deviceName();
  return scalar;
}

}  // namespace rc
