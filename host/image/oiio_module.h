#pragma once
// Loads the OpenImageIO module once per process (thread-safe). It is looked for at
// $RC_OIIO_MODULE when set (and only there), else beside the running executable, then at the path
// the build put it (RC_OIIO_MODULE_PATH). Throws rc::Error saying which paths were tried and why
// they failed.
#include "image/oiio_module_api.h"

namespace rc {

const OiioModuleApi& oiioModule();

}  // namespace rc
