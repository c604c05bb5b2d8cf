#include "core/user_cache.h"

#include <cstdio>
#include <cstdlib>

namespace rc {

uint64_t fnv1a64(const void* data, size_t size, uint64_t hash) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (size_t i = 0; i < size; ++i) {
    hash ^= p[i];
    hash *= 0x100000001b3ULL;
  }
  return hash;
}

std::string hex64(uint64_t v) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(v));
  return buf;
}

std::string userCacheDir() {
  if (const char* d = std::getenv("RC_CACHE_DIR"); d && *d) return d;
  if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x) return std::string(x) + "/rcache";
  if (const char* h = std::getenv("HOME"); h && *h) return std::string(h) + "/.cache/rcache";
  return "";
}

}  // namespace rc
