#pragma once
// `rcache cache merge A.rcc B.rcc ... -o C.rcc`: one cache file holding the records of several —
// the parts of a distributed fill (tiles or frames filled on different workers), or frames of a
// walk-through. Records are view-independent (incoming radiance at a point, radius in world
// units), so the union of the parts serves every view the parts served.
//  - every part must come from the same scene (same scene hash), else an error names the part;
//  - records are de-duplicated: a record present in several parts (a base cache every worker
//    loaded before its fill; a walk-through's frames) is kept once — same position, frame and
//    coefficients bit for bit — with the smallest radius and accuracy a any part gave it (a part
//    that loaded it may have shrunk them by neighbour clamping or adaptive caching);
//  - neighbour clamping across the parts: each record's radius is clamped to R_j + |p_i − p_j| over
//    the merged records of its cache that are its neighbours (RadianceCache's insertion test:
//    facing the same way, influence spheres overlapping), from the radii as loaded, in one
//    simultaneous step — the clamp the fill applies within one cache (radii vary no faster than
//    distance), so a coarse record of one part does not overrule finer neighbours of another;
//  - the result is sorted canonically (by the record's bytes) and every step depends on the set
//    of records only, so the file is byte-identical whatever the order of the parts.
#include <cstdint>
#include <string>
#include <vector>

#include "cache/cache_file.h"

namespace rc {

struct MergeReport {
  size_t recordsIn = 0, duplicates = 0, recordsOut = 0, radiiClamped = 0;
};

// Merges parts (each one file's entries) into one list of entries in canonical order.
std::vector<CacheFileEntry> mergeCacheEntries(const std::vector<std::vector<CacheFileEntry>>& parts,
                                              MergeReport* report = nullptr);
// Loads every input (same scene), merges, writes `output` atomically.
MergeReport mergeCacheFiles(const std::vector<std::string>& inputs, const std::string& output);

}  // namespace rc
