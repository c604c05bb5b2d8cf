#pragma once
// OpenCL runtime: device enumeration and selection, one shared context + queue per device, and
// programs built from the (embedded or on-disk) kernel sources, cached per (device, file, options).
#include <atomic>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "cl/cl_error.h"

namespace rc::cl {

struct DeviceInfo {
  int platformIndex = -1, deviceIndex = -1;
  cl_platform_id platform = nullptr;
  cl_device_id device = nullptr;
  std::string platformName, platformVersion, name, vendor, version, driver, type;
  int computeUnits = 0;
  unsigned clockMHz = 0;
  unsigned long long maxAlloc = 0, globalMem = 0, localMem = 0;
  size_t maxWorkGroup = 0;
  std::string label() const;  // "pthread-... (Portable Computing Language, platform 0 device 0)"
};

// `-t N` means N threads of work in all (docs/ARCHITECTURE.md §Threads), kernels included: PoCL's CPU
// device runs kernels on its own pool of threads, sized once, when the platform is first created,
// from POCL_MAX_PTHREAD_COUNT (PoCL 3.1's pthread device honours it; the device then reports that
// many compute units). Sets it to `threads` unless the user set it already; a GPU is unaffected.
// Returns false, changing nothing, when the platforms were already queried (too late to apply).
bool limitCpuDeviceThreads(int threads);

// All devices of all platforms. No platform at all (CL_PLATFORM_NOT_FOUND_KHR or 0 platforms)
// returns an empty list; other API failures throw.
std::vector<DeviceInfo> enumerateDevices();

// A parsed --device value (ARCHITECTURE.md §Kernels): "cpu", "opencl", "opencl:P:D", "auto".
struct DeviceSpec {
  enum Kind { Scalar, OpenClFirst, OpenClIndexed, Auto } kind = Auto;
  int platform = -1, device = -1;
};
DeviceSpec parseDeviceSpec(const std::string& spec);  // throws rc::Error on bad syntax

// The device an OpenCL spec names: "opencl" = first GPU, else first device. Throws rc::Error
// with the reason (no platform, index out of range with the list of what exists).
DeviceInfo selectDevice(const DeviceSpec& spec);

// Reads the kernel file `name` (relative to kernels/) from RC_KERNEL_DIR when set, else from the
// embedded copy, and inlines every `#include "shared/..."` (recursively, once per file), keeping
// #line directives so build logs point at the real file:line. Throws if a file is missing.
std::string assembleSource(const std::string& name);
// The same for an in-memory source (tests, tiny probe kernels); `name` labels its #line.
std::string assembleText(const std::string& text, const std::string& name);

// Builds one program from `sources` (one string per kernel file) for one device; a failed build
// throws rc::Error carrying the build log.
cl_program buildProgram(cl_context context, cl_device_id device, const std::vector<std::string>& sources,
                        const std::string& options, const std::string& displayName);

// One context + in-order queue per device, shared by every backend in the process (so programs
// compile once per process), with a program cache keyed by (file, options).
class Context {
 public:
  static std::shared_ptr<Context> forDevice(const DeviceInfo& info);
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  const DeviceInfo& info() const { return info_; }
  cl_context context() const { return context_; }
  cl_command_queue queue() const { return queue_; }
  // Program built from the kernel files `files` (several families share one program so a
  // (device, options) pair compiles once). Cached; the program lives as long as the Context.
  // Built programs come from the disk cache of program binaries when it holds them
  // (cl/program_binary_cache.h), else from source (and are then stored there).
  cl_program program(const std::vector<std::string>& files, const std::string& options);
  int programsFromBinaryCache() const { return programsFromBinaryCache_.load(); }
  std::mutex& queueMutex() { return queueMutex_; }  // serialises enqueue+wait sequences

 private:
  explicit Context(const DeviceInfo& info);
  DeviceInfo info_;
  cl_context context_ = nullptr;
  cl_command_queue queue_ = nullptr;
  std::mutex mutex_, queueMutex_;
  std::vector<std::pair<std::string, cl_program>> programs_;  // key = files + '\n' + options
  std::atomic<int> programsFromBinaryCache_{0};
};

// RAII device buffer.
class Buffer {
 public:
  Buffer() = default;
  Buffer(cl_context ctx, cl_mem_flags flags, size_t bytes, const void* host = nullptr);
  ~Buffer();
  Buffer(Buffer&& o) noexcept : mem_(o.mem_), bytes_(o.bytes_) { o.mem_ = nullptr; o.bytes_ = 0; }
  Buffer& operator=(Buffer&& o) noexcept;
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;
  cl_mem get() const { return mem_; }
  size_t bytes() const { return bytes_; }

 private:
  cl_mem mem_ = nullptr;
  size_t bytes_ = 0;
};

// RAII kernel object (not shareable between threads: arguments are state).
class Kernel {
 public:
  Kernel() = default;
  Kernel(cl_program program, const char* name);
  ~Kernel();
  Kernel(Kernel&& o) noexcept : k_(o.k_) { o.k_ = nullptr; }
  Kernel& operator=(Kernel&& o) noexcept;
  cl_kernel get() const { return k_; }
  template <class T>
  void arg(cl_uint index, const T& value) {
    RC_CL_CHECK(clSetKernelArg(k_, index, sizeof(T), &value));
  }
  void arg(cl_uint index, const Buffer& b) {
    cl_mem m = b.get();
    RC_CL_CHECK(clSetKernelArg(k_, index, sizeof(cl_mem), &m));
  }
  // All arguments at once, in the kernel's parameter order.
  template <class... Args>
  void args(const Args&... values) {
    cl_uint index = 0;
    (arg(index++, values), ...);
  }

 private:
  cl_kernel k_ = nullptr;
};

}  // namespace rc::cl
