#include "cl/cl_runtime.h"

#include <CL/cl_ext.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "cl/embedded_kernels.h"
#include "cl/program_binary_cache.h"
#include "core/error.h"

namespace rc::cl {

namespace {

std::atomic<bool> gPlatformsQueried{false};

std::string platformString(cl_platform_id p, cl_platform_info what) {
  size_t n = 0;
  RC_CL_CHECK(clGetPlatformInfo(p, what, 0, nullptr, &n));
  std::string s(n, '\0');
  RC_CL_CHECK(clGetPlatformInfo(p, what, n, s.data(), nullptr));
  while (!s.empty() && s.back() == '\0') s.pop_back();
  return s;
}

std::string deviceString(cl_device_id d, cl_device_info what) {
  size_t n = 0;
  RC_CL_CHECK(clGetDeviceInfo(d, what, 0, nullptr, &n));
  std::string s(n, '\0');
  RC_CL_CHECK(clGetDeviceInfo(d, what, n, s.data(), nullptr));
  while (!s.empty() && s.back() == '\0') s.pop_back();
  return s;
}

template <class T>
T deviceValue(cl_device_id d, cl_device_info what) {
  T v{};
  RC_CL_CHECK(clGetDeviceInfo(d, what, sizeof(T), &v, nullptr));
  return v;
}

std::string typeName(cl_device_type t) {
  if (t & CL_DEVICE_TYPE_GPU) return "GPU";
  if (t & CL_DEVICE_TYPE_CPU) return "CPU";
  if (t & CL_DEVICE_TYPE_ACCELERATOR) return "accelerator";
  return "other";
}

bool readFile(const std::string& path, std::string& out) {
  std::ifstream f(path, std::ios::binary);
  if (!f) return false;
  std::ostringstream ss;
  ss << f.rdbuf();
  out = ss.str();
  return true;
}

// Raw text of one kernel file, with a leading #line so diagnostics name the real file.
std::string rawSource(const std::string& name) {
  if (const char* dir = std::getenv("RC_KERNEL_DIR"); dir && *dir) {
    std::string text;
    const std::string path = std::string(dir) + "/" + name;
    if (!readFile(path, text)) throw Error("RC_KERNEL_DIR is set but kernel file '" + path + "' cannot be read");
    return "#line 1 \"" + name + "\"\n" + text;
  }
  const char* text = embeddedKernelSource(name);
  if (!text) throw Error("kernel source '" + name + "' is not embedded in this binary");
  return text;
}

void assemble(const std::string& name, std::set<std::string>& seen, std::string& out, const std::string* text = nullptr) {
  if (!seen.insert(name).second) return;  // each header once (they have guards anyway)
  std::istringstream in(text ? "#line 1 \"" + name + "\"\n" + *text : rawSource(name));
  std::string line;
  int lineNo = 0;  // line number in the real file of the line just read (after the #line 1)
  bool first = true;
  while (std::getline(in, line)) {
    if (first && line.rfind("#line 1 ", 0) == 0) {  // our own marker: keep, do not count
      out += line + "\n";
      first = false;
      continue;
    }
    first = false;
    ++lineNo;
    size_t p = line.find_first_not_of(" \t");
    if (p != std::string::npos && line.compare(p, 8, "#include") == 0) {
      const size_t q1 = line.find('"', p), q2 = q1 == std::string::npos ? q1 : line.find('"', q1 + 1);
      if (q1 != std::string::npos && q2 != std::string::npos) {
        assemble(line.substr(q1 + 1, q2 - q1 - 1), seen, out);
        out += "#line " + std::to_string(lineNo + 1) + " \"" + name + "\"\n";
        continue;
      }
    }
    out += line + "\n";
  }
}

}  // namespace

std::string DeviceInfo::label() const {
  return name + " (" + platformName + ", platform " + std::to_string(platformIndex) + " device " +
         std::to_string(deviceIndex) + ")";
}

bool limitCpuDeviceThreads(int threads) {
  if (gPlatformsQueried) return false;
  if (threads > 0) setenv("POCL_MAX_PTHREAD_COUNT", std::to_string(threads).c_str(), /*overwrite=*/0);
  return true;
}

std::vector<DeviceInfo> enumerateDevices() {
  gPlatformsQueried = true;
  cl_uint np = 0;
  cl_int err = clGetPlatformIDs(0, nullptr, &np);
  if (err == CL_PLATFORM_NOT_FOUND_KHR || np == 0) return {};
  RC_CL_CHECK_ERR(err, "clGetPlatformIDs(0, nullptr, &np)");
  std::vector<cl_platform_id> platforms(np);
  RC_CL_CHECK(clGetPlatformIDs(np, platforms.data(), nullptr));
  std::vector<DeviceInfo> out;
  for (cl_uint p = 0; p < np; ++p) {
    cl_uint nd = 0;
    err = clGetDeviceIDs(platforms[p], CL_DEVICE_TYPE_ALL, 0, nullptr, &nd);
    if (err == CL_DEVICE_NOT_FOUND || nd == 0) continue;
    RC_CL_CHECK_ERR(err, "clGetDeviceIDs(platform, CL_DEVICE_TYPE_ALL, 0, nullptr, &nd)");
    std::vector<cl_device_id> devices(nd);
    RC_CL_CHECK(clGetDeviceIDs(platforms[p], CL_DEVICE_TYPE_ALL, nd, devices.data(), nullptr));
    for (cl_uint d = 0; d < nd; ++d) {
      DeviceInfo info;
      info.platformIndex = static_cast<int>(p);
      info.deviceIndex = static_cast<int>(d);
      info.platform = platforms[p];
      info.device = devices[d];
      info.platformName = platformString(platforms[p], CL_PLATFORM_NAME);
      info.platformVersion = platformString(platforms[p], CL_PLATFORM_VERSION);
      info.name = deviceString(devices[d], CL_DEVICE_NAME);
      info.vendor = deviceString(devices[d], CL_DEVICE_VENDOR);
      info.version = deviceString(devices[d], CL_DEVICE_VERSION);
      info.driver = deviceString(devices[d], CL_DRIVER_VERSION);
      info.type = typeName(deviceValue<cl_device_type>(devices[d], CL_DEVICE_TYPE));
      info.computeUnits = static_cast<int>(deviceValue<cl_uint>(devices[d], CL_DEVICE_MAX_COMPUTE_UNITS));
      info.clockMHz = deviceValue<cl_uint>(devices[d], CL_DEVICE_MAX_CLOCK_FREQUENCY);
      info.maxAlloc = deviceValue<cl_ulong>(devices[d], CL_DEVICE_MAX_MEM_ALLOC_SIZE);
      info.globalMem = deviceValue<cl_ulong>(devices[d], CL_DEVICE_GLOBAL_MEM_SIZE);
      info.localMem = deviceValue<cl_ulong>(devices[d], CL_DEVICE_LOCAL_MEM_SIZE);
      info.maxWorkGroup = deviceValue<size_t>(devices[d], CL_DEVICE_MAX_WORK_GROUP_SIZE);
      out.push_back(info);
    }
  }
  return out;
}

DeviceSpec parseDeviceSpec(const std::string& spec) {
  DeviceSpec s;
  if (spec == "cpu") { s.kind = DeviceSpec::Scalar; return s; }
  if (spec == "auto" || spec.empty()) { s.kind = DeviceSpec::Auto; return s; }
  if (spec == "opencl") { s.kind = DeviceSpec::OpenClFirst; return s; }
  if (spec.rfind("opencl:", 0) == 0) {
    int p = -1, d = -1;
    char tail = 0;
    if (std::sscanf(spec.c_str() + 7, "%d:%d%c", &p, &d, &tail) == 2 && p >= 0 && d >= 0) {
      s.kind = DeviceSpec::OpenClIndexed;
      s.platform = p;
      s.device = d;
      return s;
    }
  }
  throw Error("invalid device '" + spec + "': expected cpu, opencl, opencl:P:D (e.g. opencl:0:0) or auto");
}

DeviceInfo selectDevice(const DeviceSpec& spec) {
  const std::vector<DeviceInfo> all = enumerateDevices();
  if (all.empty()) throw Error("no OpenCL platform/device found (is an ICD such as pocl-opencl-icd installed?)");
  if (spec.kind == DeviceSpec::OpenClIndexed) {
    for (const DeviceInfo& d : all)
      if (d.platformIndex == spec.platform && d.deviceIndex == spec.device) return d;
    std::string have;
    for (const DeviceInfo& d : all)
      have += (have.empty() ? "" : ", ") + std::to_string(d.platformIndex) + ":" + std::to_string(d.deviceIndex) + " = " + d.name;
    throw Error("OpenCL device opencl:" + std::to_string(spec.platform) + ":" + std::to_string(spec.device) +
                " does not exist; available: " + have);
  }
  for (const DeviceInfo& d : all)
    if (d.type == "GPU") return d;
  return all.front();
}

std::string assembleSource(const std::string& name) {
  std::set<std::string> seen;
  std::string out;
  assemble(name, seen, out);
  return out;
}

std::string assembleText(const std::string& text, const std::string& name) {
  std::set<std::string> seen;
  std::string out;
  assemble(name, seen, out, &text);
  return out;
}

cl_program buildProgram(cl_context context, cl_device_id device, const std::vector<std::string>& sources,
                        const std::string& options, const std::string& displayName) {
  std::vector<const char*> texts;
  std::vector<size_t> lengths;
  for (const std::string& s : sources) {
    texts.push_back(s.c_str());
    lengths.push_back(s.size());
  }
  cl_int err = CL_SUCCESS;
  cl_program program = clCreateProgramWithSource(context, static_cast<cl_uint>(texts.size()), texts.data(),
                                                 lengths.data(), &err);
  RC_CL_CHECK_ERR(err, "clCreateProgramWithSource(context, n, texts, lengths, &err)");
  err = clBuildProgram(program, 1, &device, options.c_str(), nullptr, nullptr);
  if (err != CL_SUCCESS) {
    size_t n = 0;
    std::string log;
    if (clGetProgramBuildInfo(program, device, CL_PROGRAM_BUILD_LOG, 0, nullptr, &n) == CL_SUCCESS && n > 1) {
      log.resize(n);
      clGetProgramBuildInfo(program, device, CL_PROGRAM_BUILD_LOG, n, log.data(), nullptr);
      while (!log.empty() && (log.back() == '\0' || log.back() == '\n')) log.pop_back();
    }
    clReleaseProgram(program);
    throw Error("OpenCL build of " + displayName + " [" + options + "] failed: " + errorName(err) + "\nbuild log:\n" +
                (log.empty() ? "(empty)" : log));
  }
  return program;
}

std::shared_ptr<Context> Context::forDevice(const DeviceInfo& info) {
  static std::mutex mutex;
  static std::map<cl_device_id, std::weak_ptr<Context>> contexts;
  std::lock_guard<std::mutex> lock(mutex);
  if (auto existing = contexts[info.device].lock()) return existing;
  std::shared_ptr<Context> made(new Context(info));
  contexts[info.device] = made;
  return made;
}

Context::Context(const DeviceInfo& info) : info_(info) {
  cl_int err = CL_SUCCESS;
  const cl_context_properties props[] = {CL_CONTEXT_PLATFORM, reinterpret_cast<cl_context_properties>(info.platform), 0};
  context_ = clCreateContext(props, 1, &info.device, nullptr, nullptr, &err);
  RC_CL_CHECK_ERR(err, "clCreateContext(props, 1, &device, nullptr, nullptr, &err)");
  queue_ = clCreateCommandQueue(context_, info.device, 0, &err);
  if (err != CL_SUCCESS) {
    clReleaseContext(context_);
    RC_CL_CHECK_ERR(err, "clCreateCommandQueue(context, device, 0, &err)");
  }
}

Context::~Context() {
  for (auto& p : programs_) clReleaseProgram(p.second);
  if (queue_) clReleaseCommandQueue(queue_);
  if (context_) clReleaseContext(context_);
}

cl_program Context::program(const std::vector<std::string>& files, const std::string& options) {
  std::string key, display;
  std::vector<std::string> sources;
  for (const std::string& f : files) {
    key += f + ",";
    display += (display.empty() ? "" : " + ") + f;
  }
  key += "\n" + options;
  std::lock_guard<std::mutex> lock(mutex_);
  for (auto& p : programs_)
    if (p.first == key) return p.second;
  // -cl-std pins OpenCL C 1.2; no fast-math: NaN/Inf tests (isfinite) must stay meaningful.
  const std::string fullOptions = "-cl-std=CL1.2 " + options;
  for (const std::string& f : files) sources.push_back(assembleSource(f));
  const ProgramBinaryCache binaries;
  const std::string binaryKey = ProgramBinaryCache::keyFor(info_, fullOptions, sources);
  cl_program prog = binaries.load(context_, info_.device, binaryKey, fullOptions);
  if (prog) {
    ++programsFromBinaryCache_;
  } else {
    prog = buildProgram(context_, info_.device, sources, fullOptions, display);
    binaries.store(prog, binaryKey);
  }
  programs_.emplace_back(key, prog);
  return prog;
}

Buffer::Buffer(cl_context ctx, cl_mem_flags flags, size_t bytes, const void* host) : bytes_(bytes) {
  cl_int err = CL_SUCCESS;
  // Zero-size buffers are invalid in OpenCL; allocate one word so kernels can still bind them.
  const size_t n = bytes ? bytes : 4;
  if (host && bytes) {
    if (!(flags & CL_MEM_USE_HOST_PTR)) flags |= CL_MEM_COPY_HOST_PTR;
  } else {
    host = nullptr;
    flags &= ~static_cast<cl_mem_flags>(CL_MEM_USE_HOST_PTR);
  }
  mem_ = clCreateBuffer(ctx, flags, n, const_cast<void*>(host), &err);
  RC_CL_CHECK_ERR(err, ("clCreateBuffer(context, flags, " + std::to_string(n) + " bytes, host, &err)").c_str());
}

Buffer::~Buffer() {
  if (mem_) clReleaseMemObject(mem_);
}

Buffer& Buffer::operator=(Buffer&& o) noexcept {
  if (this != &o) {
    if (mem_) clReleaseMemObject(mem_);
    mem_ = o.mem_;
    bytes_ = o.bytes_;
    o.mem_ = nullptr;
    o.bytes_ = 0;
  }
  return *this;
}

Kernel::Kernel(cl_program program, const char* name) {
  cl_int err = CL_SUCCESS;
  k_ = clCreateKernel(program, name, &err);
  RC_CL_CHECK_ERR(err, (std::string("clCreateKernel(program, \"") + name + "\", &err)").c_str());
}

Kernel::~Kernel() {
  if (k_) clReleaseKernel(k_);
}

Kernel& Kernel::operator=(Kernel&& o) noexcept {
  if (this != &o) {
    if (k_) clReleaseKernel(k_);
    k_ = o.k_;
    o.k_ = nullptr;
  }
  return *this;
}

}  // namespace rc::cl
