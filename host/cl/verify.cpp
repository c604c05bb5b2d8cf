#include "cl/verify.h"

#include <cstdio>
#include <string>
#include <vector>

#include "cl/cl_runtime.h"
#include "cl/kernel_cases.h"
#include "cl/sh_backend.h"
#include "core/error.h"
#include "sh/reference.h"

namespace rc {

namespace {

void row(std::ostream& out, const std::string& family, int order, const cases::Stats& st, bool& allPass) {
  char line[256];
  std::snprintf(line, sizeof line, "%-22s %5d %12.3e %12.3e %12.3e %9.3f  %s", family.c_str(), order, st.maxAbs,
                st.maxRel, st.tolAtWorst, st.worstRatio, st.pass() ? "PASS" : "FAIL");
  out << line << "\n";
  allPass = allPass && st.pass();
}

}  // namespace

int runVerify(const std::string& deviceSpec, int order, std::ostream& out) {
  std::string notice;
  std::unique_ptr<ShBackend> backend = makeShBackend(deviceSpec, &notice);
  if (!notice.empty()) out << "note: " << notice << "\n";
  out << "device: " << backend->deviceName() << "\n";
  std::vector<int> orders;
  if (order == 0) orders = {1, 2, 5, 10, 16};
  else if (order < 1 || order > kMaxKernelOrder)
    throw Error("verify: order " + std::to_string(order) + " outside 1.." + std::to_string(kMaxKernelOrder));
  else orders = {order};
  char header[256];
  std::snprintf(header, sizeof header, "%-22s %5s %12s %12s %12s %9s  %s", "family", "order", "max_abs", "max_rel",
                "tolerance", "err/tol", "result");
  out << header << "\n";
  bool allPass = true;
  for (int n : orders) {
    const uint32_t seed = 1000u + static_cast<uint32_t>(n);
    {  // sh_project + grad_accumulate: 24 records of 16×64 = 1024 samples, edge cases included
      ProjectBatch b = cases::makeProjectBatch(n, 16, 64, 24, seed, true, true);
      ProjectResult ref, got;
      ref::project(b, ref);
      backend->project(b, got);
      row(out, "sh_project", n, cases::compareProjectLambda(b, ref, got), allPass);
      row(out, "grad_accumulate", n, cases::compareProjectGradients(b, ref, got), allPass);
    }
    {
      RotateBatch b = cases::makeRotateBatch(n, 512, seed, true);
      std::vector<float> ref, got;
      ref::rotate(b, ref);
      backend->rotate(b, got);
      row(out, "sh_rotate", n, cases::compareRotate(b, ref, got), allPass);
    }
    for (int world = 0; world < 2; ++world) {
      InterpolateBatch b = cases::makeInterpolateBatch(n, 64, 256, seed + 7 * world, world != 0, true);
      std::vector<float> ref, got;
      ref::interpolate(b, ref);
      backend->interpolate(b, got);
      row(out, world ? "interpolate(world)" : "interpolate(record)", n, cases::compareInterpolate(b, ref, got), allPass);
    }
    {
      BrdfDotBatch b = cases::makeBrdfDotBatch(n, 2048, seed);
      std::vector<float> ref, got;
      ref::brdfDot(b, ref);
      backend->brdfDot(b, got);
      row(out, "brdf_dot", n, cases::compareBrdfDot(b, ref, got), allPass);
    }
  }
  out << (allPass ? "all kernels PASS" : "some kernels FAIL") << "\n";
  return allPass ? 0 : 1;
}

void listDevices(std::ostream& out) {
  const std::vector<cl::DeviceInfo> devices = cl::enumerateDevices();
  if (devices.empty()) {
    out << "no OpenCL platform/device found (the scalar CPU path, --device cpu, is always available)\n";
    return;
  }
  for (const cl::DeviceInfo& d : devices) {
    out << "opencl:" << d.platformIndex << ":" << d.deviceIndex << "  " << d.name << "  [" << d.type << ", "
        << d.computeUnits << " compute units, " << d.clockMHz << " MHz, " << (d.globalMem >> 20) << " MiB, max alloc "
        << (d.maxAlloc >> 20) << " MiB]  " << d.platformName << " / " << d.version << "\n";
  }
}

}  // namespace rc
