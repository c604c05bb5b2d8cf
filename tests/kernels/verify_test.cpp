// `rcache verify` logic (host/cl/verify.cpp) and `rcache devices`.
#include <sstream>

#include "cl/verify.h"
#include "kernel_test_util.h"

namespace rc {
namespace {

TEST(Verify, AllFamiliesPassAtOrder5) {
  RC_KERNEL_BACKEND(backend);
  (void)backend;
  std::ostringstream out;
  const int rc = runVerify("opencl", 5, out);
  std::cout << out.str();
  EXPECT_EQ(rc, 0);
  for (const char* family : {"sh_project", "grad_accumulate", "sh_rotate", "interpolate(record)", "interpolate(world)", "brdf_dot"})
    EXPECT_NE(out.str().find(family), std::string::npos) << family;
  EXPECT_EQ(out.str().find("FAIL"), std::string::npos);
}

TEST(Verify, ScalarBackendAgreesWithReferenceTrivially) {
  std::ostringstream out;
  EXPECT_EQ(runVerify("cpu", 2, out), 0) << out.str();
  EXPECT_NE(out.str().find("cpu (scalar"), std::string::npos);
}

TEST(Verify, BadOrderThrows) {
  std::ostringstream out;
  EXPECT_THROW(runVerify("cpu", 17, out), Error);
}

TEST(Devices, ListsEveryDeviceOrSaysNone) {
  std::ostringstream out;
  listDevices(out);
  const auto devices = cl::enumerateDevices();
  if (devices.empty()) EXPECT_NE(out.str().find("no OpenCL"), std::string::npos);
  else EXPECT_NE(out.str().find(devices.front().name), std::string::npos);
}

}  // namespace
}  // namespace rc
