#pragma once
// The entry list of an interpolate batch (sh/batches.h InterpolateBatch) from the points' lookups,
// built on all threads: the points' frames, their contributions with each record renumbered to its
// slot in the batch, and the records of the slots, in ascending id order. Any numbering gives the
// same kernel output (a point sums its entries in its lookup's order; a slot only says where its
// record's coefficients lie in the batch); numbering in first use, as before, was a serial loop
// on the control thread over every contribution.
#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

#include "cache/radiance_cache.h"
#include "cache/shade_point.h"
#include "sh/batches.h"

namespace rc {

// Scratch over one cache's records, reused by the batches of one interpolation: which records a
// batch uses (cleared again by fillInterpolateEntries) and their slots.
struct RecordSlots {
  explicit RecordSlots(size_t records)
      : records(records), used(new std::atomic<uint8_t>[records]()), slot(records) {}
  size_t records;
  std::unique_ptr<std::atomic<uint8_t>[]> used;
  std::vector<int32_t> slot;
};

// Fills interp.pointFrames, offsets and entries for the points begin + idx[j] of pts and lookups
// (interp's header sized for idx.size() points); returns the record of each slot.
std::vector<uint32_t> fillInterpolateEntries(PointView pts, const std::vector<Lookup>& lookups, size_t begin,
                                             const std::vector<uint32_t>& idx, RecordSlots& slots,
                                             InterpolateBatch& interp);

}  // namespace rc
