#pragma once
// Disk cache of precomputed BRDF tables (and order choices), shared by concurrent renders.
// Directory: the explicit one, else userCacheDir() ($RC_CACHE_DIR, $XDG_CACHE_HOME/rcache or
// ~/.cache/rcache). One file per key, named by the key's 64-bit FNV-1a hash:
//   magic "RCBRDFT1" | u32 format version | u32 key length | key text | u64 key hash |
//   i32 kind, order, res | u64 float count | float payload[count] | u64 FNV-1a of all preceding bytes
// (host byte order: the cache is per machine). Files are written to a temporary sibling and
// renamed, so a reader sees a whole file or none. A file that is truncated, corrupt or made for
// another key/version is reported in one line and rebuilt; a cache directory that cannot be
// created or written is reported once and the cache is then not used.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/user_cache.h"  // fnv1a64, userCacheDir

namespace rc {

constexpr uint32_t kBrdfCacheFormatVersion = 1;

struct CachedBlob {
  int32_t kind = 0, order = 0, res = 0;
  std::vector<float> payload;
};

// The directory the cache would use (no file-system access).
std::string resolveBrdfCacheDir(const std::string& explicitDir);

class BrdfDiskCache {
 public:
  using Notice = std::function<void(const std::string&)>;
  BrdfDiskCache(const std::string& explicitDir, Notice notice);

  bool enabled() const { return enabled_; }
  const std::string& directory() const { return dir_; }
  std::string pathFor(const std::string& key) const;

  // True when a valid file for `key` exists (blob filled). A missing file is silent; a bad one
  // gives a notice and false (the caller rebuilds and store() replaces it).
  bool load(const std::string& key, CachedBlob& blob) const;
  // Writes the file atomically; a failure gives a notice and disables the cache.
  void store(const std::string& key, const CachedBlob& blob);

 private:
  std::string dir_;
  bool enabled_ = false;
  Notice notice_;
};

}  // namespace rc
