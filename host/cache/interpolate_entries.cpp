#include "cache/interpolate_entries.h"

#include "core/parallel.h"
#include "core/parallel_select.h"

namespace rc {

std::vector<uint32_t> fillInterpolateEntries(PointView pts, const std::vector<Lookup>& lookups, size_t begin,
                                             const std::vector<uint32_t>& idx, RecordSlots& slots,
                                             InterpolateBatch& interp) {
  const size_t P = idx.size();
  auto lookupOf = [&](size_t j) -> const Lookup& { return lookups[begin + idx[j]]; };
  for (size_t j = 0; j < P; ++j)
    interp.offsets[j + 1] = interp.offsets[j] + static_cast<int32_t>(lookupOf(j).entries.size());
  interp.entries.resize(static_cast<size_t>(interp.offsets[P]));
  parallelFor(P, 256, [&](size_t b, size_t e) {
    for (size_t j = b; j < e; ++j)
      for (const RcContribution& c : lookupOf(j).entries)
        slots.used[static_cast<size_t>(c.record)].store(1, std::memory_order_relaxed);
  });
  const std::vector<size_t> ids =
      parallelSelect(slots.records, [&](size_t r) { return slots.used[r].load(std::memory_order_relaxed) != 0; });
  std::vector<uint32_t> records(ids.size());
  parallelFor(ids.size(), 1024, [&](size_t b, size_t e) {
    for (size_t k = b; k < e; ++k) {
      records[k] = static_cast<uint32_t>(ids[k]);
      slots.slot[ids[k]] = static_cast<int32_t>(k);
      slots.used[ids[k]].store(0, std::memory_order_relaxed);
    }
  });
  parallelFor(P, 256, [&](size_t b, size_t e) {
    for (size_t j = b; j < e; ++j) {
      pts[begin + idx[j]].frame.rows(&interp.pointFrames[9 * j]);
      RcContribution* out = &interp.entries[static_cast<size_t>(interp.offsets[j])];
      for (RcContribution c : lookupOf(j).entries) {
        c.record = slots.slot[static_cast<size_t>(c.record)];
        *out++ = c;
      }
    }
  });
  return records;
}

}  // namespace rc
