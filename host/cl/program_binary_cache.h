#pragma once
// Disk cache of built OpenCL programs (the device's program binaries), so a process skips the
// compiler front end: building our kernels from source costs PoCL ≈ 40 ms per program even when
// its own cache hits (clang still preprocesses the source to find the entry), from a binary
// ≈ 3 ms; a render needs 3–4 programs (one per SH order), so ≈ 0.15 s per process.
// File: <userCacheDir>/cl/<hex FNV-1a of the key>.bin with
//   magic "RCCLBIN2" | u64 key hash | u64 second key hash (other FNV basis) | u64 size | size bytes |
//   u64 FNV-1a of all preceding bytes.
// The key holds the platform, device and driver versions, the build options and the full source,
// so any change of these misses. A missing, corrupt or refused binary is rebuilt from source and
// replaced (files are written atomically); a cache directory that cannot be written only means no
// cache. RC_CL_BINARY_CACHE=0 turns it off.
#include <string>
#include <vector>

#include <CL/cl.h>

namespace rc::cl {

struct DeviceInfo;

class ProgramBinaryCache {
 public:
  // Disabled when there is no cache directory or RC_CL_BINARY_CACHE=0.
  ProgramBinaryCache();
  bool enabled() const { return !dir_.empty(); }

  static std::string keyFor(const DeviceInfo& device, const std::string& options, const std::vector<std::string>& sources);
  // A built program from the cached binary, or nullptr (no file, a bad one, or the driver refused it).
  cl_program load(cl_context context, cl_device_id device, const std::string& key, const std::string& options) const;
  // Stores the program's binary for `key` (best effort: failures are ignored, see above).
  void store(cl_program program, const std::string& key) const;
  std::string pathFor(const std::string& key) const;

 private:
  std::string dir_;
};

}  // namespace rc::cl
