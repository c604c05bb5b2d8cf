#pragma once
// The interface between rcache and its OpenImageIO module (host/oiio_module), a shared library
// loaded with dlopen on the first image that is not EXR. Both sides are built by the same CMake
// project with the same compiler, so C++ types cross the boundary; kOiioModuleAbi guards against
// a stale module from another build.
#include <string>

#include "image/image_file.h"

namespace rc {

constexpr int kOiioModuleAbi = 1;

struct OiioModuleApi {
  int abi = kOiioModuleAbi;
  // Return "" on success, else OpenImageIO's message.
  std::string (*write)(const std::string& path, const std::string& formatPath, const ImageChannels& image) = nullptr;
  std::string (*read)(const std::string& path, ImageChannels& image) = nullptr;
};

}  // namespace rc

// The module's one exported symbol.
extern "C" const rc::OiioModuleApi* rc_oiio_module_api();
