#pragma once
// Shared by the kernel tests: one OpenCL backend per process (programs compile once), and the
// skip/fail policy: without a device the tests skip, unless RC_REQUIRE_OPENCL=1 (CI), where
// "no OpenCL device" is a failure.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <memory>
#include <string>

#include "cl/cl_runtime.h"
#include "cl/opencl_backend.h"
#include "core/error.h"

namespace rc::test {

inline bool requireOpenCl() {
  const char* v = std::getenv("RC_REQUIRE_OPENCL");
  return v && std::string(v) == "1";
}

// nullptr (with the reason in *why) when no device is usable.
inline OpenClBackend* sharedBackend(std::string* why) {
  static std::unique_ptr<OpenClBackend> backend;
  static std::string reason;
  static bool tried = false;
  if (!tried) {
    tried = true;
    try {
      const auto devices = cl::enumerateDevices();
      if (devices.empty()) reason = "no OpenCL platform/device";
      else backend = std::make_unique<OpenClBackend>(cl::selectDevice(cl::DeviceSpec{cl::DeviceSpec::OpenClFirst}));
    } catch (const std::exception& e) {
      reason = e.what();
    }
  }
  if (why) *why = reason;
  return backend.get();
}

}  // namespace rc::test

// Binds `name` to the shared backend or skips/fails the test.
#define RC_KERNEL_BACKEND(name)                                                              \
  std::string rcWhy_;                                                                        \
  ::rc::OpenClBackend* name = ::rc::test::sharedBackend(&rcWhy_);                            \
  if (!name) {                                                                               \
    if (::rc::test::requireOpenCl()) FAIL() << "RC_REQUIRE_OPENCL=1 but " << rcWhy_;         \
    GTEST_SKIP() << "no OpenCL device: " << rcWhy_;                                          \
  }

// Prints the comparison and asserts it passed.
#define RC_EXPECT_WITHIN_TOLERANCE(stats)                                                                    \
  EXPECT_TRUE((stats).pass()) << "max abs " << (stats).maxAbs << ", max rel " << (stats).maxRel               \
                              << ", worst err/tol " << (stats).worstRatio << " (tol " << (stats).tolAtWorst   \
                              << "), " << (stats).compared << " values" << ((stats).nonFinite ? ", non-finite output" : "")
