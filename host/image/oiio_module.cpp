#include "image/oiio_module.h"

#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>
#include <mutex>
#include <vector>

#include "core/error.h"

#ifndef RC_OIIO_MODULE_PATH
#define RC_OIIO_MODULE_PATH ""
#endif
#ifndef RC_OIIO_MODULE_NAME
#define RC_OIIO_MODULE_NAME "librc_oiio_module.so"
#endif

namespace rc {

namespace {

std::string executableDirectory() {
  std::vector<char> buf(4096);
  const ssize_t n = readlink("/proc/self/exe", buf.data(), buf.size() - 1);
  if (n <= 0) return "";
  std::string exe(buf.data(), static_cast<size_t>(n));
  const size_t slash = exe.find_last_of('/');
  return slash == std::string::npos ? "" : exe.substr(0, slash);
}

}  // namespace

const OiioModuleApi& oiioModule() {
  static std::once_flag once;
  static const OiioModuleApi* api = nullptr;
  static std::string failure;
  std::call_once(once, [] {
    std::vector<std::string> candidates;
    // RC_OIIO_MODULE names the module explicitly (a packaged install, or tests); then only it is tried.
    const char* explicitPath = std::getenv("RC_OIIO_MODULE");
    const bool isExplicit = explicitPath && *explicitPath;  // set and not empty
    if (isExplicit) candidates.push_back(explicitPath);
    const std::string dir = candidates.empty() ? executableDirectory() : "";
    if (!dir.empty()) candidates.push_back(dir + "/" + RC_OIIO_MODULE_NAME);
    const std::string built = RC_OIIO_MODULE_PATH;
    if (!isExplicit && !built.empty() && (candidates.empty() || candidates.front() != built)) candidates.push_back(built);
    for (const std::string& path : candidates) {
      // Never unloaded: OpenImageIO keeps global state for the rest of the process.
      void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
      if (!handle) {
        const char* why = dlerror();
        failure += (failure.empty() ? "" : "; ") + std::string(why ? why : path + ": cannot load");
        continue;
      }
      auto entry = reinterpret_cast<const OiioModuleApi* (*)()>(dlsym(handle, "rc_oiio_module_api"));
      const OiioModuleApi* found = entry ? entry() : nullptr;
      if (!found || found->abi != kOiioModuleAbi || !found->read || !found->write) {
        failure += (failure.empty() ? "" : "; ") + path + ": not an rcache OpenImageIO module of this build";
        continue;
      }
      api = found;
      return;
    }
    if (candidates.empty()) failure = "no place to look for it";
  });
  if (!api)
    throw Error("the OpenImageIO module (" RC_OIIO_MODULE_NAME ", needed for images other than .exr) could not be loaded: " +
                failure);
  return *api;
}

}  // namespace rc
