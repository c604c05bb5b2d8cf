#include "cache/record_coherence.h"

#include <cmath>

#include "cache/record_weights.h"
#include "cache/rng_salts.h"
#include "core/rng.h"

namespace rc {

double RecordCoherence::upperBound() const {
  if (points == 0) return 1.0;
  const double n = double(points), q = share(), z2 = kCoherenceBoundZ * kCoherenceBoundZ;
  const double spread = kCoherenceBoundZ * std::sqrt(q * (1.0 - q) / n + z2 / (4.0 * n * n));
  return (q + z2 / (2.0 * n) + spread) / (1.0 + z2 / n);
}

namespace {

bool sameCache(const CacheKey& a, const CacheKey& b) { return !(a < b) && !(b < a); }

// Whether a level-0 record made at `at`, with the floor radius, serves `other` in the fill's lookup.
bool floorRecordServes(const RcacheRun& run, const ShadePoint& at, const ShadePoint& other) {
  const CacheEngine& engine = run.engine;
  if (!other.active || !engine.hasIndirect(other) || !isCached(engine.technique(other))) return false;
  if (!sameCache(engine.keyFor(at), engine.keyFor(other))) return false;
  const float a = engine.aForLevel(0);
  const float R = run.params.rMinPx * engine.footprint(at.hit.p, 0) / a;
  return contributionWeight(other.hit.p, other.geometryFrame.n, at.hit.p, at.geometryFrame.n, R, a) > 0.0f;
}

}  // namespace

RecordCoherence measureRecordCoherence(const RcacheRun& run, const std::vector<Vec2>& filmPos,
                                       const std::vector<uint64_t>& seeds, const std::vector<Primary>& prim,
                                       const std::vector<char>& tested) {
  RecordCoherence c;
  c.offsetPx = kNeighbourOffsetOfFloor * run.params.rMinPx;
  std::vector<size_t> index;
  std::vector<Vec2> neighbourPos;
  std::vector<uint64_t> neighbourSeeds;  // the same as the point's: the same lens sample
  for (size_t i = 0; i < prim.size(); ++i) {
    if (!tested[i]) continue;
    const float phi = 2.0f * kPi * float(hashMix(seeds[i], 0, kSaltPilotNeighbour) >> 40) * 0x1p-24f;
    index.push_back(i);
    neighbourPos.push_back(filmPos[i] + c.offsetPx * Vec2(std::cos(phi), std::sin(phi)));
    neighbourSeeds.push_back(seeds[i]);
  }
  std::vector<Primary> neighbours;
  run.primaries.trace(neighbourPos, std::vector<int>(index.size(), -1), neighbourSeeds, neighbours);
  c.points = index.size();
  for (size_t k = 0; k < index.size(); ++k) c.served += floorRecordServes(run, prim[index[k]].sp, neighbours[k].sp);
  return c;
}

}  // namespace rc
