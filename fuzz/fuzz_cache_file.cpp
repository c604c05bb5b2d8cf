// libFuzzer entry point for the cache-file reader (--cache-load, issue 7). The harness appends a
// correct FNV-1a checksum and passes the scene hash found in the input, so mutations reach the
// parser behind those two gates instead of being rejected by them. Contract: loadCacheFile returns
// or throws rc::Error; anything else (other exceptions, sanitizer reports, huge allocations under
// -rss_limit_mb, timeouts) is a finding. Built with -DRC_FUZZ=ON (see fuzz/fuzz_scene.cpp), run by
// scripts/run_fuzz.sh from tests/fuzz/corpus_cache (files without their trailing checksum).
// Whatever the loader accepts is inserted into radiance caches and looked up at every record,
// so crafted values that pass validation but would hang or poison the octree are findings too.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "brdf/table_cache.h"
#include "cache/cache_file.h"
#include "cache/radiance_cache.h"
#include "core/error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("rc_fuzz_cache_" + std::to_string(::getpid()) + ".rcc");
  std::string bytes(reinterpret_cast<const char*>(data), size);
  const uint64_t sum = rc::fnv1a64(bytes.data(), bytes.size());
  bytes.append(reinterpret_cast<const char*>(&sum), sizeof sum);
  uint64_t sceneHash = 0;
  if (size >= 20) std::memcpy(&sceneHash, data + 12, sizeof sceneHash);  // magic (8) + version (4)
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  try {
    // What passes the loader's range checks must also be safe to use: insert it into caches
    // (neighbour clamping, octree) and look up at every record, as --cache-load then the fill do.
    for (const rc::CacheFileEntry& e : rc::loadCacheFile(path.string(), sceneHash)) {
      rc::RadianceCache cache(e.key.order, rc::Vec3(-1.0f), rc::Vec3(1.0f));
      cache.insert(e.infos, e.lambda, e.gradT, e.gradB, {}, {}, {}, true);
      rc::Lookup lookup;
      for (const rc::RecordInfo& r : e.infos) {
        cache.lookup(r.p, r.frame.n, lookup);
        cache.lookup(r.p, r.frame.n, lookup, 2.0f);
      }
    }
  } catch (const rc::Error&) {
    // Rejecting a bad file with a message is the correct outcome.
  }
  return 0;
}
