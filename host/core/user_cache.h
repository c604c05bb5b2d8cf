#pragma once
// The per-user disk cache that rcache's precomputations share (BRDF tables, built OpenCL
// programs): $RC_CACHE_DIR, else $XDG_CACHE_HOME/rcache, else ~/.cache/rcache; "" when none of
// these is set. Files in it are keyed by a 64-bit FNV-1a hash of what they were made from.
#include <cstddef>
#include <cstdint>
#include <string>

namespace rc {

uint64_t fnv1a64(const void* data, size_t size, uint64_t hash = 0xcbf29ce484222325ULL);
inline uint64_t fnv1a64(const std::string& s, uint64_t hash = 0xcbf29ce484222325ULL) {
  return fnv1a64(s.data(), s.size(), hash);
}
// 16 lower-case hex digits.
std::string hex64(uint64_t v);

std::string userCacheDir();

}  // namespace rc
