#include "cache/cache_merge.h"

#include <algorithm>
#include <cstring>
#include <map>
#include <tuple>

#include "cache/record_octree.h"
#include "cache/record_weights.h"
#include "core/error.h"

namespace rc {

namespace {

// One record with its coefficients, as bytes: the canonical order and the duplicate test.
struct RecordBlob {
  RecordInfo info;
  std::vector<float> lambda, gradT, gradB;
  std::string identity;  // position, frame and coefficients as bytes: R and a excluded
};

RecordBlob blobOf(const CacheFileEntry& e, size_t i, size_t k) {
  RecordBlob b;
  b.info = e.infos[i];
  b.lambda.assign(e.lambda.begin() + i * k, e.lambda.begin() + (i + 1) * k);
  b.gradT.assign(e.gradT.begin() + i * k, e.gradT.begin() + (i + 1) * k);
  b.gradB.assign(e.gradB.begin() + i * k, e.gradB.begin() + (i + 1) * k);
  const RecordInfo& r = b.info;
  const float v[12] = {r.p.x, r.p.y, r.p.z, r.frame.t.x, r.frame.t.y, r.frame.t.z, r.frame.b.x,
                       r.frame.b.y, r.frame.b.z, r.frame.n.x, r.frame.n.y, r.frame.n.z};
  b.identity.append(reinterpret_cast<const char*>(v), sizeof v);
  for (const std::vector<float>* c : {&b.lambda, &b.gradT, &b.gradB})
    b.identity.append(reinterpret_cast<const char*>(c->data()), c->size() * sizeof(float));
  return b;
}

// Every record's radius against its neighbours in the merged set (the insertion test of
// RadianceCache: facing the same way, influence spheres overlapping), from the radii as loaded:
// one simultaneous step, so the result depends on the set, not on an order.
size_t clampAcrossParts(std::vector<RecordBlob>& recs) {
  if (recs.size() < 2) return 0;
  Vec3 lo(INFINITY), hi(-INFINITY);
  for (const RecordBlob& r : recs) {
    lo = glm::min(lo, r.info.p);
    hi = glm::max(hi, r.info.p);
  }
  RecordOctree octree(lo, hi);
  for (size_t i = 0; i < recs.size(); ++i) octree.insert(static_cast<uint32_t>(i), recs[i].info.p, recs[i].info.a * recs[i].info.R);
  std::vector<float> clamped(recs.size());
  float maxReach = 0.0f;
  for (const RecordBlob& r : recs) maxReach = std::max(maxReach, r.info.a * r.info.R);
  for (size_t i = 0; i < recs.size(); ++i) {
    const RecordInfo& r = recs[i].info;
    float R = r.R;
    octree.querySphere(r.p, r.a * r.R + maxReach, [&](uint32_t j) {
      if (j == i) return;
      const RecordInfo& q = recs[j].info;
      if (!(glm::dot(q.frame.n, r.frame.n) > 0.0f) || glm::length(q.p - r.p) > q.a * q.R + r.a * r.R) return;
      float rq = q.R;
      clampNeighbourRadii(q.p, rq, r.p, R);  // R ← min(R, R_q + d)
    });
    clamped[i] = R;
  }
  size_t changed = 0;
  for (size_t i = 0; i < recs.size(); ++i)
    if (clamped[i] < recs[i].info.R) {
      recs[i].info.R = clamped[i];
      ++changed;
    }
  return changed;
}

}  // namespace

std::vector<CacheFileEntry> mergeCacheEntries(const std::vector<std::vector<CacheFileEntry>>& parts,
                                              MergeReport* report) {
  MergeReport rep;
  std::map<CacheKey, std::vector<RecordBlob>> byKey;
  for (const auto& part : parts)
    for (const CacheFileEntry& e : part) {
      const size_t k = static_cast<size_t>(3) * e.key.order * e.key.order;
      std::vector<RecordBlob>& dst = byKey[e.key];
      for (size_t i = 0; i < e.infos.size(); ++i) dst.push_back(blobOf(e, i, k));
      rep.recordsIn += e.infos.size();
    }
  std::vector<CacheFileEntry> out;
  for (auto& [key, recs] : byKey) {
    std::sort(recs.begin(), recs.end(), [](const RecordBlob& a, const RecordBlob& b) {
      return std::tie(a.identity, a.info.R, a.info.a) < std::tie(b.identity, b.info.R, b.info.a);
    });
    // One record per identity, with the smallest radius and accuracy any part gave it (a part
    // that loaded it may have shrunk them by clamping or adaptive caching).
    std::vector<RecordBlob> unique;
    for (RecordBlob& r : recs) {
      if (!unique.empty() && unique.back().identity == r.identity) {
        unique.back().info.a = std::min(unique.back().info.a, r.info.a);
        ++rep.duplicates;
        continue;
      }
      unique.push_back(std::move(r));
    }
    recs = std::move(unique);
    rep.radiiClamped += clampAcrossParts(recs);
    CacheFileEntry e;
    e.key = key;
    for (RecordBlob& r : recs) {
      e.infos.push_back(r.info);
      e.lambda.insert(e.lambda.end(), r.lambda.begin(), r.lambda.end());
      e.gradT.insert(e.gradT.end(), r.gradT.begin(), r.gradT.end());
      e.gradB.insert(e.gradB.end(), r.gradB.begin(), r.gradB.end());
    }
    rep.recordsOut += e.infos.size();
    out.push_back(std::move(e));
  }
  if (report) *report = rep;
  return out;
}

MergeReport mergeCacheFiles(const std::vector<std::string>& inputs, const std::string& output) {
  if (inputs.empty()) throw Error("cache merge: no input cache files");
  std::vector<std::vector<CacheFileEntry>> parts;
  uint64_t sceneHash = 0;
  for (size_t i = 0; i < inputs.size(); ++i) {
    uint64_t h = 0;
    parts.push_back(loadCacheFile(inputs[i], nullptr, &h));
    if (i == 0) sceneHash = h;
    else if (h != sceneHash)
      throw Error(inputs[i] + ": cache file was made for another scene than " + inputs[0]);
  }
  MergeReport rep;
  const std::vector<CacheFileEntry> merged = mergeCacheEntries(parts, &rep);
  saveCacheFile(output, sceneHash, merged);
  return rep;
}

}  // namespace rc
