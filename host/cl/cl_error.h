#pragma once
// Every OpenCL call goes through RC_CL_CHECK: a failure becomes rc::Error naming the call text,
// the error code's symbolic name and file:line (ARCHITECTURE.md §Conventions). Calls that return a handle and
// report through an out-parameter use RC_CL_CHECK_ERR on that code.
#ifndef CL_TARGET_OPENCL_VERSION
#define CL_TARGET_OPENCL_VERSION 120
#endif
#include <CL/cl.h>

#include <string>

namespace rc::cl {

// "CL_OUT_OF_RESOURCES", ..., or "unknown OpenCL error".
const char* errorName(cl_int code);

// Throws rc::Error("file:line: call failed: NAME (code)") when code != CL_SUCCESS.
void check(cl_int code, const char* callText, const char* file, int line);

}  // namespace rc::cl

#define RC_CL_CHECK(call) ::rc::cl::check((call), #call, __FILE__, __LINE__)
#define RC_CL_CHECK_ERR(code, what) ::rc::cl::check((code), what, __FILE__, __LINE__)
