#include "cl/program_binary_cache.h"

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "cl/cl_runtime.h"
#include "core/atomic_file.h"
#include "core/binary_writer.h"
#include "core/user_cache.h"

namespace rc::cl {

namespace {

constexpr char kMagic[8] = {'R', 'C', 'C', 'L', 'B', 'I', 'N', '2'};
// The key (≈ 100 KB of source) is identified by two 64-bit FNV-1a hashes of different offset
// bases: a wrong program would compute silently wrong results, so 64 bits alone felt thin.
constexpr uint64_t kSecondBasis = 0x84222325cbf29ce4ULL;
// A program binary of our kernels is ≈ 0.4 MB; anything claiming more than this is not one.
constexpr uint64_t kMaxBinaryBytes = uint64_t(1) << 30;

template <typename T>
bool get(const std::string& s, size_t& pos, T& v) {
  if (s.size() - pos < sizeof(T)) return false;
  std::memcpy(&v, s.data() + pos, sizeof(T));
  pos += sizeof(T);
  return true;
}

}  // namespace

ProgramBinaryCache::ProgramBinaryCache() {
  const char* off = std::getenv("RC_CL_BINARY_CACHE");
  if (off && std::string(off) == "0") return;
  const std::string root = userCacheDir();
  if (!root.empty()) dir_ = root + "/cl";
}

std::string ProgramBinaryCache::keyFor(const DeviceInfo& device, const std::string& options,
                                       const std::vector<std::string>& sources) {
  std::string key = device.platformName + "\n" + device.platformVersion + "\n" + device.name + "\n" + device.vendor +
                    "\n" + device.version + "\n" + device.driver + "\n" + options + "\n";
  for (const std::string& s : sources) key += std::to_string(s.size()) + ":" + s;
  return key;
}

std::string ProgramBinaryCache::pathFor(const std::string& key) const { return dir_ + "/" + hex64(fnv1a64(key)) + ".bin"; }

cl_program ProgramBinaryCache::load(cl_context context, cl_device_id device, const std::string& key,
                                    const std::string& options) const {
  if (!enabled()) return nullptr;
  std::ifstream in(pathFor(key), std::ios::binary);
  if (!in) return nullptr;
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  size_t pos = sizeof kMagic;
  uint64_t hash = 0, hash2 = 0, size = 0, check = 0;
  if (bytes.size() < pos || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0) return nullptr;
  if (!get(bytes, pos, hash) || hash != fnv1a64(key) || !get(bytes, pos, hash2) || hash2 != fnv1a64(key, kSecondBasis) ||
      !get(bytes, pos, size) || size == 0 || size > kMaxBinaryBytes || bytes.size() - pos < size + sizeof(uint64_t))
    return nullptr;
  const size_t payload = pos;
  pos += size;
  if (!get(bytes, pos, check) || pos != bytes.size() || check != fnv1a64(bytes.data(), payload + size)) return nullptr;
  const size_t length = static_cast<size_t>(size);
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data() + payload);
  cl_int status = CL_SUCCESS, err = CL_SUCCESS;
  cl_program program = clCreateProgramWithBinary(context, 1, &device, &length, &data, &status, &err);
  if (err != CL_SUCCESS || status != CL_SUCCESS || !program) {
    if (program) clReleaseProgram(program);
    return nullptr;
  }
  if (clBuildProgram(program, 1, &device, options.c_str(), nullptr, nullptr) != CL_SUCCESS) {
    clReleaseProgram(program);
    return nullptr;
  }
  return program;
}

void ProgramBinaryCache::store(cl_program program, const std::string& key) const {
  if (!enabled()) return;
  size_t size = 0;
  if (clGetProgramInfo(program, CL_PROGRAM_BINARY_SIZES, sizeof size, &size, nullptr) != CL_SUCCESS || size == 0 ||
      size > kMaxBinaryBytes)
    return;
  std::vector<unsigned char> binary(size);
  unsigned char* ptr = binary.data();
  if (clGetProgramInfo(program, CL_PROGRAM_BINARIES, sizeof ptr, &ptr, nullptr) != CL_SUCCESS) return;
  std::string file(kMagic, sizeof kMagic);
  put(file, fnv1a64(key));
  put(file, fnv1a64(key, kSecondBasis));
  put(file, static_cast<uint64_t>(size));
  file.append(reinterpret_cast<const char*>(binary.data()), size);
  put(file, fnv1a64(file.data(), file.size()));
  try {
    std::error_code ec;
    std::filesystem::create_directories(dir_, ec);
    writeFileAtomically(pathFor(key), file);
  } catch (const std::exception&) {
    // Best effort: without a writable cache every process builds from source, as before.
  }
}

}  // namespace rc::cl
