// OpenCL runtime: device specs, error reporting, build logs, struct layout on the device, and the
// backend factory (scalar, explicit OpenCL, auto, RC_DEVICE).
#include <cstddef>
#include <cstdlib>
#include <functional>
#include <string>

#include "cl/cl_runtime.h"
#include "cl/kernel_cases.h"
#include "cl/sh_backend.h"
#include "sh/reference.h"
#include "kernel_test_util.h"
#include "rc_types.h"

namespace rc {
namespace {

std::string messageOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(DeviceSpec, ParsesTheDocumentedForms) {
  EXPECT_EQ(cl::parseDeviceSpec("cpu").kind, cl::DeviceSpec::Scalar);
  EXPECT_EQ(cl::parseDeviceSpec("auto").kind, cl::DeviceSpec::Auto);
  EXPECT_EQ(cl::parseDeviceSpec("opencl").kind, cl::DeviceSpec::OpenClFirst);
  const cl::DeviceSpec s = cl::parseDeviceSpec("opencl:1:2");
  EXPECT_EQ(s.kind, cl::DeviceSpec::OpenClIndexed);
  EXPECT_EQ(s.platform, 1);
  EXPECT_EQ(s.device, 2);
  for (const char* bad : {"gpu", "opencl:", "opencl:1", "opencl:1:x", "opencl:-1:0", "opencl:0:0:0"}) {
    const std::string m = messageOf([&] { cl::parseDeviceSpec(bad); });
    EXPECT_NE(m.find("invalid device"), std::string::npos) << bad << ": " << m;
  }
}

TEST(DeviceSpec, MissingDeviceGivesAClearError) {
  const std::string m = messageOf([] { makeShBackend("opencl:9:9"); });
  ASSERT_FALSE(m.empty());
  // Either "no platform at all" or "opencl:9:9 does not exist; available: ..."
  EXPECT_TRUE(m.find("opencl:9:9") != std::string::npos) << m;
  EXPECT_TRUE(m.find("does not exist") != std::string::npos || m.find("no OpenCL platform") != std::string::npos) << m;
}

TEST(ClError, CarriesCallNameAndLocation) {
  const std::string m = messageOf([] { RC_CL_CHECK(clReleaseMemObject(nullptr)); });
  EXPECT_NE(m.find("clReleaseMemObject(nullptr)"), std::string::npos) << m;
  EXPECT_NE(m.find("CL_INVALID_MEM_OBJECT"), std::string::npos) << m;
  EXPECT_NE(m.find("runtime_test.cpp:"), std::string::npos) << m;
  EXPECT_STREQ(cl::errorName(CL_OUT_OF_RESOURCES), "CL_OUT_OF_RESOURCES");
  EXPECT_STREQ(cl::errorName(-12345), "unknown OpenCL error");
}

TEST(KernelSource, EmbeddedFilesAssembleWithIncludesInlined) {
  const std::string src = cl::assembleSource("sh_rotate.cl");
  EXPECT_NE(src.find("typedef struct RcContribution"), std::string::npos);  // rc_types.h inlined
  EXPECT_NE(src.find("rc_rotate3"), std::string::npos);                     // rc_sh_device.h inlined
  EXPECT_EQ(src.find("#include \"shared/"), std::string::npos);
  EXPECT_NE(src.find("#line 1 \"shared/rc_types.h\""), std::string::npos);
  EXPECT_THROW(cl::assembleSource("no_such_kernel.cl"), Error);
}

TEST(KernelSource, KernelDirOverrideReadsFromDisk) {
  setenv("RC_KERNEL_DIR", RC_SOURCE_DIR "/kernels", 1);
  const std::string src = cl::assembleSource("brdf_dot.cl");
  EXPECT_THROW(cl::assembleSource("missing.cl"), Error);
  unsetenv("RC_KERNEL_DIR");
  EXPECT_NE(src.find("rc_brdf_dot"), std::string::npos);
}

TEST(Build, BrokenSourceThrowsWithTheBuildLog) {
  RC_KERNEL_BACKEND(backend);
  auto ctx = cl::Context::forDevice(backend->device());
  const std::string src = cl::assembleText("__kernel void broken(__global float* x) { x[0] = undefined_symbol_xyz; }",
                                           "broken.cl");
  const std::string m = messageOf([&] { cl::buildProgram(ctx->context(), ctx->info().device, {src}, "", "broken.cl"); });
  EXPECT_NE(m.find("build log"), std::string::npos) << m;
  EXPECT_NE(m.find("undefined_symbol_xyz"), std::string::npos) << m;
  EXPECT_NE(m.find("broken.cl"), std::string::npos) << m;
}

TEST(Layout, SharedStructsMatchOnTheDevice) {
  RC_KERNEL_BACKEND(backend);
  auto ctx = cl::Context::forDevice(backend->device());
  const std::string src = cl::assembleText(R"(
#include "shared/rc_types.h"
#define RC_OFF(s, f) (int)((__private char*)&s.f - (__private char*)&s)
__kernel void rc_layout(__global int* out) {
  RcContribution c; RcBrdfTable t; RcSparseEntry e;
  out[0] = sizeof(RcContribution); out[1] = RC_OFF(c, record); out[2] = RC_OFF(c, weight);
  out[3] = RC_OFF(c, dt); out[4] = RC_OFF(c, db);
  out[5] = sizeof(RcBrdfTable); out[6] = RC_OFF(t, kind); out[7] = RC_OFF(t, order);
  out[8] = RC_OFF(t, res); out[9] = RC_OFF(t, offset);
  out[10] = RC_TABLE_ISOTROPIC_1D; out[11] = RC_TABLE_ANISOTROPIC_2D;
  out[12] = sizeof(RcSparseEntry); out[13] = RC_OFF(e, column); out[14] = RC_OFF(e, value);
})", "layout.cl");
  cl_program prog = cl::buildProgram(ctx->context(), ctx->info().device, {src}, "-cl-std=CL1.2", "layout.cl");
  {
    cl::Kernel k(prog, "rc_layout");
    cl::Buffer out(ctx->context(), CL_MEM_WRITE_ONLY, 15 * sizeof(cl_int));
    k.arg(0, out);
    const size_t one = 1;
    std::lock_guard<std::mutex> lock(ctx->queueMutex());
    RC_CL_CHECK(clEnqueueNDRangeKernel(ctx->queue(), k.get(), 1, nullptr, &one, &one, 0, nullptr, nullptr));
    int dev[15];
    RC_CL_CHECK(clEnqueueReadBuffer(ctx->queue(), out.get(), CL_TRUE, 0, sizeof dev, dev, 0, nullptr, nullptr));
    const int host[15] = {int(sizeof(RcContribution)), int(offsetof(RcContribution, record)),
                          int(offsetof(RcContribution, weight)), int(offsetof(RcContribution, dt)),
                          int(offsetof(RcContribution, db)), int(sizeof(RcBrdfTable)), int(offsetof(RcBrdfTable, kind)),
                          int(offsetof(RcBrdfTable, order)), int(offsetof(RcBrdfTable, res)),
                          int(offsetof(RcBrdfTable, offset)), RC_TABLE_ISOTROPIC_1D, RC_TABLE_ANISOTROPIC_2D,
                          int(sizeof(RcSparseEntry)), int(offsetof(RcSparseEntry, column)),
                          int(offsetof(RcSparseEntry, value))};
    for (int i = 0; i < 15; ++i) EXPECT_EQ(dev[i], host[i]) << "field " << i;
  }
  clReleaseProgram(prog);
}

TEST(Factory, CpuIsScalarAndRcDeviceIsHonoured) {
  auto cpu = makeShBackend("cpu");
  EXPECT_FALSE(cpu->isOpenCl());
  EXPECT_NE(cpu->deviceName().find("scalar"), std::string::npos);
  setenv("RC_DEVICE", "cpu", 1);
  auto env = makeShBackend("");
  unsetenv("RC_DEVICE");
  EXPECT_FALSE(env->isOpenCl());
  EXPECT_THROW(makeShBackend("fpga"), Error);
}

TEST(Factory, AutoPicksOpenClWhenAvailableElseScalarWithNotice) {
  std::string notice;
  auto b = makeShBackend("auto", &notice);
  if (cl::enumerateDevices().empty()) {
    EXPECT_FALSE(b->isOpenCl());
    EXPECT_NE(notice.find("no OpenCL platform"), std::string::npos) << notice;
  } else {
    EXPECT_TRUE(b->isOpenCl()) << notice;
    EXPECT_TRUE(notice.empty());
    EXPECT_NE(b->deviceName().find("OpenCL"), std::string::npos);
  }
}

TEST(Factory, ScalarBackendRunsTheReferencesAndCountsTime) {
  auto cpu = makeScalarBackend();
  RotateBatch b = cases::makeRotateBatch(4, 300, 3u, true);
  std::vector<float> ref, got;
  ref::rotate(b, ref);
  cpu->rotate(b, got);
  EXPECT_EQ(got, ref);  // same code, split over threads: bit-identical
  EXPECT_GT(cpu->times().rotate_s, 0.0);
  ProjectBatch p = cases::makeProjectBatch(3, 4, 16, 5, 2u, true, true);
  ProjectResult pr, pg;
  ref::project(p, pr);
  cpu->project(p, pg);
  EXPECT_EQ(pg.lambda, pr.lambda);
  EXPECT_EQ(pg.gradT, pr.gradT);
  EXPECT_EQ(pg.dropped, pr.dropped);
}

TEST(Backend, KernelTimesAccumulate) {
  RC_KERNEL_BACKEND(backend);
  const double before = backend->times().brdfDot_s;
  BrdfDotBatch b = cases::makeBrdfDotBatch(4, 50, 1u);
  std::vector<float> out;
  backend->brdfDot(b, out);
  EXPECT_GT(backend->times().brdfDot_s, before);
  EXPECT_TRUE(backend->isOpenCl());
}

}  // namespace
}  // namespace rc
