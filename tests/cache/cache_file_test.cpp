// Cache-file reader on hostile input: counts that promise more data than the file holds
// and non-finite record values give an rc::Error naming the file, never a huge allocation or a
// record that poisons interpolation. Files carry a valid checksum and scene hash, so the checks
// behind those gates are what is tested.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include "brdf/table_cache.h"
#include "cache/cache_file.h"
#include "core/error.h"

namespace rc {
namespace {

template <typename T>
void put(std::string& s, T v) {
  s.append(reinterpret_cast<const char*>(&v), sizeof v);
}

// "RCCACHE1" | version | hash | count | [one cache: level, depth, order | n | records...]
std::string header(uint32_t count) {
  std::string s = "RCCACHE1";
  put<uint32_t>(s, kCacheFileVersion);
  put<uint64_t>(s, 42);
  put<uint32_t>(s, count);
  return s;
}

std::string writeWithChecksum(std::string s, const std::string& name) {
  put<uint64_t>(s, fnv1a64(s.data(), s.size()));
  const auto path = (std::filesystem::temp_directory_path() / name).string();
  std::ofstream(path, std::ios::binary | std::ios::trunc) << s;
  return path;
}

void expectRejected(const std::string& path, const std::string& why) {
  try {
    loadCacheFile(path, 42);
    ADD_FAILURE() << "accepted " << path;
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
  }
}

TEST(CacheFile, HugeCacheCountIsAnErrorNotAnAllocation) {
  expectRejected(writeWithChecksum(header(0xFFFFFFFFu), "rc_huge_count.rcc"), "truncated");
}

TEST(CacheFile, HugeRecordCountIsAnErrorNotAnAllocation) {
  std::string s = header(1);
  for (int32_t v : {0, 0, 3}) put<int32_t>(s, v);
  put<uint32_t>(s, 0xFFFFFFF0u);
  expectRejected(writeWithChecksum(s, "rc_huge_records.rcc"), "truncated");
}

TEST(CacheFile, NonFiniteOrNonPositiveRecordValuesAreRejected) {
  for (int bad = 0; bad < 2; ++bad) {
    std::string s = header(1);
    for (int32_t v : {0, 0, 1}) put<int32_t>(s, v);
    put<uint32_t>(s, 1);
    float info[14] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1.0f, 0.3f};
    if (bad == 0) info[1] = std::numeric_limits<float>::quiet_NaN();
    else info[12] = -1.0f;  // R ≤ 0
    for (float f : info) put<float>(s, f);
    for (int i = 0; i < 9; ++i) put<float>(s, 0.5f);  // Λ, ∂Λ/∂t, ∂Λ/∂b: 3 channels × 1 coefficient
    expectRejected(writeWithChecksum(s, "rc_bad_record.rcc"), bad == 0 ? "non-finite" : "≤ 0");
  }
}

}  // namespace
}  // namespace rc
