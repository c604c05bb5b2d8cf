#pragma once
// Kernel sources embedded at build time by cmake/embed_kernels.cmake (generated
// rc_embedded_kernels.cpp). Names are paths relative to kernels/, e.g. "sh_project.cl",
// "shared/rc_types.h". Returns nullptr for an unknown name.
#include <string>

namespace rc {
const char* embeddedKernelSource(const std::string& name);
}  // namespace rc
