// fillInterpolateEntries (cache/interpolate_entries.h): every point's entries are its lookup's, in
// its order, with records renumbered to slots that name them back; slots ascend with record id;
// the scratch is left clear; the result does not depend on the thread count.
#include <gtest/gtest.h>

#include <set>

#include "cache/interpolate_entries.h"
#include "core/parallel.h"
#include "core/rng.h"

namespace rc {
namespace {

struct Case {
  std::vector<ShadePoint> pts;
  std::vector<Lookup> lookups;
  std::vector<uint32_t> idx;
};

Case makeCase(size_t points, uint32_t records) {
  Case c;
  Rng rng(7, 1);
  c.pts.resize(points);
  c.lookups.resize(points);
  for (size_t i = 0; i < points; ++i) {
    c.pts[i].frame = Frame::fromNormal(glm::normalize(Vec3(rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f, 1.0f)));
    const int n = static_cast<int>(rng.nextFloat() * 5);  // 0..4 contributions, as lookups find
    for (int k = 0; k < n; ++k)
      c.lookups[i].entries.push_back({static_cast<rc_int>(rng.nextFloat() * records), rng.nextFloat(), rng.nextFloat(),
                                      rng.nextFloat()});
    if (i % 3 != 1) c.idx.push_back(static_cast<uint32_t>(i));  // a subset, as one frame mode takes
  }
  return c;
}

InterpolateBatch run(const Case& c, RecordSlots& slots, std::vector<uint32_t>& records) {
  InterpolateBatch interp;
  interp.points = static_cast<int>(c.idx.size());
  interp.pointFrames.resize(9 * c.idx.size());
  interp.offsets.assign(c.idx.size() + 1, 0);
  records = fillInterpolateEntries(PointView(c.pts), c.lookups, 0, c.idx, slots, interp);
  return interp;
}

TEST(InterpolateEntries, EntriesAreTheLookupsWithSlotsNamingTheirRecords) {
  const uint32_t kRecords = 3000;
  const Case c = makeCase(5000, kRecords);
  RecordSlots slots(kRecords);
  for (int threads : {1, 2, 3}) {
    setThreadCount(threads);
    std::vector<uint32_t> records;
    const InterpolateBatch interp = run(c, slots, records);
    for (size_t k = 1; k < records.size(); ++k) ASSERT_LT(records[k - 1], records[k]);
    std::set<uint32_t> distinct;
    for (uint32_t i : c.idx)
      for (const RcContribution& e : c.lookups[i].entries) distinct.insert(static_cast<uint32_t>(e.record));
    EXPECT_EQ(records.size(), distinct.size()) << "only the records the points use";
    for (size_t j = 0; j < c.idx.size(); ++j) {
      const std::vector<RcContribution>& want = c.lookups[c.idx[j]].entries;
      ASSERT_EQ(interp.offsets[j + 1] - interp.offsets[j], static_cast<int32_t>(want.size()));
      for (size_t k = 0; k < want.size(); ++k) {
        const RcContribution& got = interp.entries[static_cast<size_t>(interp.offsets[j]) + k];
        ASSERT_GE(got.record, 0);
        ASSERT_LT(static_cast<size_t>(got.record), records.size());
        EXPECT_EQ(records[static_cast<size_t>(got.record)], static_cast<uint32_t>(want[k].record));
        EXPECT_EQ(got.weight, want[k].weight);
        EXPECT_EQ(got.dt, want[k].dt);
        EXPECT_EQ(got.db, want[k].db);
      }
      float rows[9];
      c.pts[c.idx[j]].frame.rows(rows);
      for (int r = 0; r < 9; ++r) EXPECT_EQ(interp.pointFrames[9 * j + r], rows[r]);
    }
    for (uint32_t r = 0; r < kRecords; ++r) ASSERT_EQ(slots.used[r].load(), 0) << "scratch left marked";
  }
  setThreadCount(0);
}

}  // namespace
}  // namespace rc
