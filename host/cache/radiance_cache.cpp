#include "cache/radiance_cache.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>

#include "cache/record_weights.h"
#include "core/error.h"
#include "core/parallel.h"
#include "sh/sh_basis.h"

namespace rc {

namespace {

// The record ids one query has met already (querySphere reports a record once per cell it lives
// in): one stamp per record, kept per thread across queries, so a query only advances the
// generation instead of clearing anything.
class VisitedRecords {
 public:
  // Starts a query over ids < count.
  void begin(size_t count) {
    if (stamp_.size() < count) stamp_.resize(count, 0u);
    if (++generation_ == 0u) {  // wrapped: stamps of 2³² queries ago would read as this one's
      std::fill(stamp_.begin(), stamp_.end(), 0u);
      generation_ = 1u;
    }
  }
  // true the first time this query meets `id`.
  bool first(uint32_t id) {
    if (stamp_[id] == generation_) return false;
    stamp_[id] = generation_;
    return true;
  }

 private:
  std::vector<uint32_t> stamp_;
  uint32_t generation_ = 0u;
};

}  // namespace

RadianceCache::RadianceCache(int order, const Vec3& lo, const Vec3& hi) : order_(order), octree_(lo, hi) {}

size_t RadianceCache::size() const {
  std::shared_lock lock(mutex_);
  return infos_.size();
}

uint32_t RadianceCache::insert(std::vector<RecordInfo> infos, const std::vector<float>& lambda,
                               const std::vector<float>& gradT, const std::vector<float>& gradB,
                               const std::vector<float>& lambdaWorld, const std::vector<float>& gradTWorld,
                               const std::vector<float>& gradBWorld, bool clampNeighbours,
                               std::vector<uint32_t>* shrunk) {
  const size_t k = static_cast<size_t>(coeffsPerRecord());
  const size_t n = infos.size();
  if (lambda.size() != n * k || gradT.size() != n * k || gradB.size() != n * k)
    throw Error("RadianceCache::insert: coefficient arrays do not match the record count");
  const bool world = !lambdaWorld.empty();
  if (world && (lambdaWorld.size() != n * k || gradTWorld.size() != n * k || gradBWorld.size() != n * k))
    throw Error("RadianceCache::insert: world-frame arrays do not match the record count");
  std::unique_lock lock(mutex_);
  if (!infos_.empty() && world != hasWorld_)
    throw Error("RadianceCache::insert: mixing world-frame and record-frame records");
  hasWorld_ = world;
  const uint32_t first = static_cast<uint32_t>(infos_.size());
  // Neighbour candidates for all new records at once on all threads, before the serial pass
  // below changes anything: the records already present (the octree), and the new records
  // before each one within their unclamped reach (radii only shrink, so the reach at insertion is
  // within it). A superset of the neighbours either way: the exact test (isNeighbour) decides.
  std::vector<std::vector<uint32_t>> candidates(n);
  if (clampNeighbours)
    parallelFor(n, 8, [&](size_t b, size_t e) {
      for (size_t i = b; i < e; ++i) {
        const float reach = infos[i].a * infos[i].R;
        octree_.querySphere(infos[i].p, reach, [&](uint32_t id) { candidates[i].push_back(id); });
        for (size_t j = 0; j < i; ++j)
          if (glm::length(infos[j].p - infos[i].p) <= infos[j].a * infos[j].R + reach)
            candidates[i].push_back(first + static_cast<uint32_t>(j));
      }
    });
  for (size_t i = 0; i < n; ++i) {
    RecordInfo& r = infos[i];
    // Neighbour clamping against every record whose influence sphere overlaps the new one's
    // and that faces the same way (records on the other side of a thin wall are not neighbours).
    std::vector<uint32_t>& neighbours = candidates[i];
    // The order of ARCHITECTURE.md §Conventions: the new radius against all neighbours first, then each neighbour against
    // the final new radius, so the result does not depend on the order neighbours are found in.
    std::sort(neighbours.begin(), neighbours.end());
    neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
    auto isNeighbour = [&](const RecordInfo& q) {
      return glm::dot(q.frame.n, r.frame.n) > 0.0f && glm::length(q.p - r.p) <= q.a * q.R + r.a * r.R;
    };
    std::vector<uint32_t> clampWith;
    for (uint32_t id : neighbours)
      if (isNeighbour(infos_[id])) clampWith.push_back(id);
    for (uint32_t id : clampWith) {
      float unused = infos_[id].R;
      clampNeighbourRadii(r.p, r.R, infos_[id].p, unused);
    }
    for (uint32_t id : clampWith) {
      RecordInfo& q = infos_[id];
      float rNew = r.R;
      const float before = q.R;
      clampNeighbourRadii(r.p, rNew, q.p, q.R);
      if (q.R < before) {
        spheres_[id] = influenceSphere(q);
        if (shrunk) shrunk->push_back(id);
      }
    }
    infos_.push_back(r);
    spheres_.push_back(influenceSphere(r));
    if (std::isfinite(r.a * r.R)) maxReach_ = std::max(maxReach_, r.a * r.R);
  }
  // The octree cells of the new records and the coefficient arrays are independent of each other:
  // filled side by side instead of one after the other on the calling thread. The cells hold each
  // record's sphere after the whole batch's clamping (a later record of the batch can shrink an
  // earlier one); lookups test the exact weight and sort by record, so the cells only need to
  // contain the spheres.
  const std::pair<std::vector<float>*, const std::vector<float>*> appends[] = {
      {&lambda_, &lambda}, {&gradT_, &gradT}, {&gradB_, &gradB},
      {&lambdaW_, &lambdaWorld}, {&gradTW_, &gradTWorld}, {&gradBW_, &gradBWorld}};
  const size_t tasks = 1 + (world ? 6 : 3);
  parallelFor(tasks, 1, [&](size_t b, size_t e) {
    for (size_t t = b; t < e; ++t) {
      if (t == 0) {
        for (size_t i = 0; i < n; ++i) {
          const RecordInfo& r = infos_[first + i];
          octree_.insert(first + static_cast<uint32_t>(i), r.p, r.a * r.R);
        }
        continue;
      }
      std::vector<float>& to = *appends[t - 1].first;
      const std::vector<float>& from = *appends[t - 1].second;
      to.insert(to.end(), from.begin(), from.end());
    }
  });
  return first;
}

void RadianceCache::lookupLocked(const Vec3& p, const Vec3& n, Lookup& out, bool brute, float scale) const {
  out.entries.clear();
  // A lookup finds 2–4 records on average: one allocation instead of growing 1 → 2 → 4 (+8).
  if (out.entries.capacity() == 0) out.entries.reserve(8);
  out.weightSum = 0.0f;
  out.sameNormal = true;
  const float scale2 = scale * scale;
  auto test = [&](uint32_t id) {
    if (id < skipped_.size() && skipped_[id]) return;
    // w_i > 1/a_i needs ‖p − p_i‖ < a_i·R_i: most octree candidates fail this on 16 bytes,
    // before the full weight reads the record.
    const glm::vec4& sph = spheres_[id];
    const float dx = p.x - sph.x, dy = p.y - sph.y, dz = p.z - sph.z;
    if (!(dx * dx + dy * dy + dz * dz < sph.w * scale2)) return;
    const RecordInfo& r = infos_[id];
    const float w = contributionWeight(p, n, r.p, r.frame.n, r.R, r.a * scale);
    if (w <= 0.0f) return;
    const Vec3 d = p - r.p;
    const Vec3 tilt = glm::cross(n, r.frame.n);
    if (!(glm::dot(tilt, tilt) <= 1e-14f)) out.sameNormal = false;
    out.entries.push_back({static_cast<rc_int>(id), w, glm::dot(d, r.frame.t), glm::dot(d, r.frame.b)});
    out.weightSum += w;
  };
  if (brute) {
    for (uint32_t id = 0; id < infos_.size(); ++id) test(id);
    return;
  }
  if (scale > 1.0f) {
    // A record whose scaled sphere holds p has its own box within (scale − 1)·a_i·R_i of p.
    // Each candidate is tested once (the entries are sorted below, so the order of the tests
    // does not matter): the relaxed lookups of a final pass otherwise collected, sorted and
    // de-duplicated a fresh candidate list each.
    thread_local VisitedRecords visited;
    visited.begin(infos_.size());
    octree_.querySphere(p, (scale - 1.0f) * maxReach_, [&](uint32_t id) {
      if (visited.first(id)) test(id);
    });
  } else {
    octree_.query(p, test);
  }
  // Octree order depends on the node layout; sort so results match brute force exactly.
  std::sort(out.entries.begin(), out.entries.end(),
            [](const RcContribution& x, const RcContribution& y) { return x.record < y.record; });
  out.weightSum = 0.0f;
  for (const auto& e : out.entries) out.weightSum += e.weight;
}

void RadianceCache::lookup(const Vec3& p, const Vec3& n, Lookup& out, float scale) const {
  std::shared_lock lock(mutex_);
  lookupLocked(p, n, out, false, scale);
}

void RadianceCache::lookupBruteForce(const Vec3& p, const Vec3& n, Lookup& out, float scale) const {
  std::shared_lock lock(mutex_);
  lookupLocked(p, n, out, true, scale);
}

void RadianceCache::shrinkA(uint32_t id, float newA, float aMin) {
  std::unique_lock lock(mutex_);
  if (id >= infos_.size()) return;
  infos_[id].a = std::max(aMin, std::min(infos_[id].a, newA));
  spheres_[id] = influenceSphere(infos_[id]);
}

void RadianceCache::setSkipped(std::vector<uint8_t> skipped) {
  std::unique_lock lock(mutex_);
  skipped.resize(std::min(skipped.size(), infos_.size()));
  skipped_ = std::move(skipped);
}

RecordInfo RadianceCache::info(uint32_t id) const {
  std::shared_lock lock(mutex_);
  return infos_.at(id);
}

void RadianceCache::copyCoefficients(uint32_t id, bool world, float* lambda, float* gradT, float* gradB) const {
  std::shared_lock lock(mutex_);
  copyCoefficientsLocked(id, world, lambda, gradT, gradB);
}

void RadianceCache::copyCoefficientsLocked(uint32_t id, bool world, float* lambda, float* gradT, float* gradB) const {
  const size_t k = static_cast<size_t>(coeffsPerRecord());
  if (world && !hasWorld_) throw Error("RadianceCache: world-frame coefficients requested but not stored");
  const std::vector<float>& L = world ? lambdaW_ : lambda_;
  const std::vector<float>& T = world ? gradTW_ : gradT_;
  const std::vector<float>& B = world ? gradBW_ : gradB_;
  std::memcpy(lambda, L.data() + id * k, k * sizeof(float));
  if (gradT) std::memcpy(gradT, T.data() + id * k, k * sizeof(float));
  if (gradB) std::memcpy(gradB, B.data() + id * k, k * sizeof(float));
}

Color RadianceCache::cosineIrradiance(const Lookup& lk, const Vec3& n, bool gradients) const {
  std::shared_lock lock(mutex_);
  return cosineIrradianceLocked(lk, n, gradients);
}

Color RadianceCache::cosineIrradianceLocked(const Lookup& lk, const Vec3& n, bool gradients) const {
  if (!(lk.weightSum > 0.0f)) return Color(0.0f);
  const int bands = std::min(order_, 3), used = bands * bands, n2 = order_ * order_;
  float A[9];
  for (int l = 0; l < bands; ++l)
    for (int m = -l; m <= l; ++m) A[l * (l + 1) + m] = sh::kClampedCosineBand[l];
  const size_t k = static_cast<size_t>(coeffsPerRecord());
  double E[3] = {0.0, 0.0, 0.0}, sumW = 0.0;
  gradients = gradients && gradT_.size() == lambda_.size() && gradB_.size() == lambda_.size();
  for (const RcContribution& c : lk.entries) {
    const RecordInfo& r = infos_[static_cast<size_t>(c.record)];
    float y[9];
    sh::evalBasis(bands, glm::dot(n, r.frame.t), glm::dot(n, r.frame.b), glm::dot(n, r.frame.n), y);
    const float* L = lambda_.data() + k * static_cast<size_t>(c.record);
    const float* T = gradT_.data() + k * static_cast<size_t>(c.record);
    const float* B = gradB_.data() + k * static_cast<size_t>(c.record);
    for (int ch = 0; ch < 3; ++ch) {
      float e = 0.0f;
      for (int i = 0; i < used; ++i) {
        const size_t o = static_cast<size_t>(ch) * n2 + i;
        const float v = gradients ? L[o] + c.dt * T[o] + c.db * B[o] : L[o];
        e += A[i] * v * y[i];
      }
      E[ch] += double(c.weight) * e;
    }
    sumW += c.weight;
  }
  return Color(float(E[0] / sumW), float(E[1] / sumW), float(E[2] / sumW));
}

void RadianceCache::snapshot(std::vector<RecordInfo>& infos, std::vector<float>& lambda, std::vector<float>& gradT,
                             std::vector<float>& gradB) const {
  std::shared_lock lock(mutex_);
  infos = infos_;
  lambda = lambda_;
  gradT = gradT_;
  gradB = gradB_;
}

}  // namespace rc
