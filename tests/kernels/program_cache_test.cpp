// The disk cache of OpenCL program binaries: a stored program loads, builds and runs the same;
// a corrupt, truncated or foreign file, or other build options, miss (and the caller rebuilds).
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "cl/cl_runtime.h"
#include "cl/program_binary_cache.h"
#include "kernel_test_util.h"

namespace rc {
namespace {

namespace fs = std::filesystem;

// Runs rc_answer(out) once and returns out[0].
int runAnswer(const std::shared_ptr<cl::Context>& ctx, cl_program prog) {
  cl::Kernel k(prog, "rc_answer");
  cl::Buffer out(ctx->context(), CL_MEM_WRITE_ONLY, sizeof(cl_int));
  k.arg(0, out);
  const size_t one = 1;
  std::lock_guard<std::mutex> lock(ctx->queueMutex());
  RC_CL_CHECK(clEnqueueNDRangeKernel(ctx->queue(), k.get(), 1, nullptr, &one, &one, 0, nullptr, nullptr));
  cl_int v = 0;
  RC_CL_CHECK(clEnqueueReadBuffer(ctx->queue(), out.get(), CL_TRUE, 0, sizeof v, &v, 0, nullptr, nullptr));
  return v;
}

// A private cache directory for the test (RC_CACHE_DIR restored afterwards).
struct CacheDir {
  fs::path path = fs::temp_directory_path() / ("rc_clbin_" + std::to_string(getpid()));
  std::string previous;
  bool hadPrevious = false;
  CacheDir() {
    if (const char* p = std::getenv("RC_CACHE_DIR")) previous = p, hadPrevious = true;
    fs::remove_all(path);
    setenv("RC_CACHE_DIR", path.c_str(), 1);
  }
  ~CacheDir() {
    if (hadPrevious) setenv("RC_CACHE_DIR", previous.c_str(), 1);
    else unsetenv("RC_CACHE_DIR");
    fs::remove_all(path);
  }
};

TEST(ProgramBinaryCache, StoredProgramLoadsAndRunsAndBadFilesMiss) {
  RC_KERNEL_BACKEND(backend);
  CacheDir dir;
  auto ctx = cl::Context::forDevice(backend->device());
  const std::string src = cl::assembleText("__kernel void rc_answer(__global int* out) { out[0] = RC_ANSWER; }", "answer.cl");
  const std::string options = "-cl-std=CL1.2 -D RC_ANSWER=42";
  const cl::ProgramBinaryCache cache;
  ASSERT_TRUE(cache.enabled());
  const std::string key = cl::ProgramBinaryCache::keyFor(ctx->info(), options, {src});
  EXPECT_EQ(cache.load(ctx->context(), ctx->info().device, key, options), nullptr);  // nothing stored yet

  cl_program built = cl::buildProgram(ctx->context(), ctx->info().device, {src}, options, "answer.cl");
  cache.store(built, key);
  clReleaseProgram(built);
  const std::string file = cache.pathFor(key);
  ASSERT_TRUE(fs::exists(file)) << file;

  cl_program loaded = cache.load(ctx->context(), ctx->info().device, key, options);
  ASSERT_NE(loaded, nullptr);
  EXPECT_EQ(runAnswer(ctx, loaded), 42);
  clReleaseProgram(loaded);

  // Other options (or source) make another key: a miss, never the wrong program.
  const std::string other = cl::ProgramBinaryCache::keyFor(ctx->info(), "-cl-std=CL1.2 -D RC_ANSWER=7", {src});
  EXPECT_NE(other, key);
  EXPECT_EQ(cache.load(ctx->context(), ctx->info().device, other, "-cl-std=CL1.2 -D RC_ANSWER=7"), nullptr);

  // One flipped byte in the middle, then a truncated file: both miss.
  std::string bytes;
  {
    std::ifstream in(file, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  std::string flipped = bytes;
  flipped[flipped.size() / 2] ^= 0x5a;
  std::ofstream(file, std::ios::binary | std::ios::trunc) << flipped;
  EXPECT_EQ(cache.load(ctx->context(), ctx->info().device, key, options), nullptr);
  std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes.substr(0, bytes.size() - 9);
  EXPECT_EQ(cache.load(ctx->context(), ctx->info().device, key, options), nullptr);

  setenv("RC_CL_BINARY_CACHE", "0", 1);
  EXPECT_FALSE(cl::ProgramBinaryCache().enabled());
  unsetenv("RC_CL_BINARY_CACHE");
}

}  // namespace
}  // namespace rc
