#include "brdf/table_cache.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/atomic_file.h"
#include "core/binary_writer.h"
#include "core/error.h"

namespace rc {

namespace {

constexpr char kMagic[8] = {'R', 'C', 'B', 'R', 'D', 'F', 'T', '1'};


// Sequential reader over a byte string; every read is bounds-checked.
struct Reader {
  const std::string& bytes;
  size_t pos = 0;
  template <typename T>
  bool get(T& v) {
    if (bytes.size() - pos < sizeof(T)) return false;
    std::memcpy(&v, bytes.data() + pos, sizeof(T));
    pos += sizeof(T);
    return true;
  }
};

}  // namespace

std::string resolveBrdfCacheDir(const std::string& explicitDir) {
  return explicitDir.empty() ? userCacheDir() : explicitDir;
}

BrdfDiskCache::BrdfDiskCache(const std::string& explicitDir, Notice notice) : notice_(std::move(notice)) {
  dir_ = resolveBrdfCacheDir(explicitDir);
  if (dir_.empty()) {
    notice_("brdf tables: no cache directory (set RC_CACHE_DIR or HOME); working without the disk cache");
    return;
  }
  std::error_code ec;
  std::filesystem::create_directories(dir_, ec);
  if (ec) {
    notice_("brdf tables: cannot create cache directory " + dir_ + " (" + ec.message() +
            "); working without the disk cache");
    return;
  }
  if (access(dir_.c_str(), W_OK | X_OK) != 0) {
    notice_("brdf tables: cache directory " + dir_ + " is not writable (" + std::strerror(errno) +
            "); working without the disk cache");
    return;
  }
  enabled_ = true;
}

std::string BrdfDiskCache::pathFor(const std::string& key) const {
  return dir_ + "/brdf_" + hex64(fnv1a64(key.data(), key.size())) + ".rctab";
}

bool BrdfDiskCache::load(const std::string& key, CachedBlob& blob) const {
  if (!enabled_) return false;
  const std::string path = pathFor(key);
  std::ifstream f(path, std::ios::binary);
  if (!f) return false;  // not cached yet
  std::ostringstream ss;
  ss << f.rdbuf();
  const std::string bytes = ss.str();
  auto bad = [&](const std::string& why) {
    notice_("brdf tables: cache file " + path + " " + why + "; rebuilding");
    return false;
  };
  Reader r{bytes};
  char magic[8];
  if (bytes.size() < sizeof magic) return bad("is truncated");
  std::memcpy(magic, bytes.data(), sizeof magic);
  r.pos = sizeof magic;
  if (std::memcmp(magic, kMagic, sizeof magic) != 0) return bad("is not a BRDF table file (bad magic)");
  uint32_t version = 0, keyLength = 0;
  if (!r.get(version) || !r.get(keyLength)) return bad("is truncated");
  if (version != kBrdfCacheFormatVersion)
    return bad("has format version " + std::to_string(version) + ", expected " + std::to_string(kBrdfCacheFormatVersion));
  if (bytes.size() - r.pos < keyLength) return bad("is truncated");
  const std::string storedKey = bytes.substr(r.pos, keyLength);
  r.pos += keyLength;
  uint64_t keyHash = 0, count = 0;
  CachedBlob b;
  if (!r.get(keyHash) || !r.get(b.kind) || !r.get(b.order) || !r.get(b.res) || !r.get(count)) return bad("is truncated");
  if (storedKey != key || keyHash != fnv1a64(key.data(), key.size())) return bad("was made for another material/key");
  if (count > (bytes.size() - r.pos) / sizeof(float)) return bad("is truncated");
  b.payload.resize(count);
  std::memcpy(b.payload.data(), bytes.data() + r.pos, count * sizeof(float));
  r.pos += count * sizeof(float);
  const size_t checked = r.pos;
  uint64_t checksum = 0;
  if (!r.get(checksum)) return bad("is truncated");
  if (r.pos != bytes.size()) return bad("has trailing bytes");
  if (checksum != fnv1a64(bytes.data(), checked)) return bad("is corrupt (checksum mismatch)");
  blob = std::move(b);
  return true;
}

void BrdfDiskCache::store(const std::string& key, const CachedBlob& blob) {
  if (!enabled_) return;
  std::string s(kMagic, sizeof kMagic);
  put(s, kBrdfCacheFormatVersion);
  put(s, static_cast<uint32_t>(key.size()));
  s += key;
  put(s, fnv1a64(key.data(), key.size()));
  put(s, blob.kind);
  put(s, blob.order);
  put(s, blob.res);
  put(s, static_cast<uint64_t>(blob.payload.size()));
  putFloats(s, blob.payload);
  put(s, fnv1a64(s.data(), s.size()));
  try {
    writeFileAtomically(pathFor(key), s);
  } catch (const Error& e) {
    notice_(std::string("brdf tables: ") + e.what() + "; working without the disk cache");
    enabled_ = false;
  }
}

}  // namespace rc
