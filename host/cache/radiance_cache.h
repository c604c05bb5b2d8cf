#pragma once
// One cache of incoming-radiance records of a single SH order (one "family": e.g. the order-10
// glossy records of the primary hits, or the order-3 diffuse records of the secondary hits).
// Records keep Λ and the gradients in the record's own frame (canonical, what the cache file
// stores) and, in world-frame mode, a world-aligned copy made once at insertion (ARCHITECTURE.md §Kernels).
// Thread safety: lookups take a shared lock, insertion and radius updates an exclusive one, so
// lookups may run in parallel with each other and with an insertion on another thread.
#include <cstdint>
#include <mutex>
#include <shared_mutex>
#include <vector>

#include "cache/record_octree.h"
#include "core/frame.h"
#include "core/math.h"
#include "rc_types.h"

namespace rc {

struct RecordInfo {
  Vec3 p{0.0f};
  Frame frame;        // t, b, n (n = the record's normal)
  float R = 1.0f;     // harmonic-mean distance after clamping
  float a = 0.3f;     // per-record accuracy (adaptive caching may shrink it)
};

// The gathered contributions for one lookup point.
struct Lookup {
  std::vector<RcContribution> entries;  // record = index into the cache, weight, dt, db
  float weightSum = 0.0f;
  // Every contributing record's normal equals the point's (|n × n_i|² ≤ 1e-14, the kernels'
  // z-rotation fast-path bound): the record-frame interpolation then needs no full rotation.
  bool sameNormal = true;
  bool covered() const { return weightSum > 0.0f; }
};

class RadianceCache {
 public:
  RadianceCache(int order, const Vec3& lo, const Vec3& hi);

  int order() const { return order_; }
  int coeffsPerRecord() const { return 3 * order_ * order_; }
  size_t size() const;

  // Adds records (coefficients in record frame, [3][n2] each; world copies optional = empty)
  // with neighbour clamping of R against records already present and among themselves.
  // Returns the index of the first new record; `shrunk` (optional) receives the ids of records
  // whose R the clamping lowered (possibly repeated).
  uint32_t insert(std::vector<RecordInfo> infos, const std::vector<float>& lambda, const std::vector<float>& gradT,
                  const std::vector<float>& gradB, const std::vector<float>& lambdaWorld,
                  const std::vector<float>& gradTWorld, const std::vector<float>& gradBWorld,
                  bool clampNeighbours = true, std::vector<uint32_t>* shrunk = nullptr);

  // Contributions at (p, n): every record with w_i > 1/a_i that is not in front of p. With
  // scale > 1 (relaxed lookup), records count as if their a_i were scale·a_i.
  void lookup(const Vec3& p, const Vec3& n, Lookup& out, float scale = 1.0f) const;

  // Holds the shared lock over a run of lookups: batches look up thousands of points per chunk,
  // and taking and releasing the lock per point (two atomic read-modify-writes on one shared
  // cache line between the threads) cost ≈ 5 % of a 512² render (perf).
  class Reader {
   public:
    explicit Reader(const RadianceCache& cache) : cache_(cache), lock_(cache.mutex_) {}
    void lookup(const Vec3& p, const Vec3& n, Lookup& out, float scale = 1.0f) const {
      cache_.lookupLocked(p, n, out, false, scale);
    }
    Color cosineIrradiance(const Lookup& lk, const Vec3& n, bool gradients) const {
      return cache_.cosineIrradianceLocked(lk, n, gradients);
    }
    const RecordInfo& info(uint32_t id) const { return cache_.infos_[id]; }
    void copyCoefficients(uint32_t id, bool world, float* lambda, float* gradT, float* gradB) const {
      cache_.copyCoefficientsLocked(id, world, lambda, gradT, gradB);
    }

   private:
    const RadianceCache& cache_;
    std::shared_lock<std::shared_mutex> lock_;
  };
  Reader reader() const { return Reader(*this); }
  // Brute-force version of lookup (tests, and a cross-check of the octree).
  void lookupBruteForce(const Vec3& p, const Vec3& n, Lookup& out, float scale = 1.0f) const;

  // Lambertian fast path: the interpolated radiance's clamped-cosine convolution at normal n,
  // E(n) = Σ_i w_i Σ_{l<3,m} Â_l (Λ_i + dt·∇tΛ_i + db·∇bΛ_i)_lm y_lm(n in record i's frame) / Σ_i w_i
  // with Â = (π, 2π/3, π/4) (Ramamoorthi–Hanrahan). It equals interpolate (rotation into the
  // point's frame, weighted sum) followed by brdf_dot with a Lambertian table, without either:
  // evaluating the basis at n in each record's frame replaces the rotation. Bands ≥ 3 of
  // higher-order records are ignored (the clamped cosine has little energy there; the order-3
  // irradiance caches have none). Zero for an uncovered lookup.
  Color cosineIrradiance(const Lookup& lk, const Vec3& n, bool gradients) const;
  // Adaptive caching: lower a_i (never below aMin).
  void shrinkA(uint32_t id, float newA, float aMin);
  // Records lookups pass over (skipped[id] != 0) while they stay in the cache and its file:
  // loaded records too coarse for this view (cache/view_refinement.h). Records inserted later
  // are never skipped.
  void setSkipped(std::vector<uint8_t> skipped);

  // Snapshot access for batching (copy under the shared lock).
  RecordInfo info(uint32_t id) const;
  void copyCoefficients(uint32_t id, bool world, float* lambda, float* gradT, float* gradB) const;
  // Everything (for the cache file / AOVs): consistent snapshot.
  void snapshot(std::vector<RecordInfo>& infos, std::vector<float>& lambda, std::vector<float>& gradT,
                std::vector<float>& gradB) const;

 private:
  int order_;
  mutable std::shared_mutex mutex_;
  std::vector<RecordInfo> infos_;
  // (p_i, (a_i·R_i)²) of every record, kept in step with infos_: the lookup's first test.
  std::vector<glm::vec4> spheres_;
  static glm::vec4 influenceSphere(const RecordInfo& r) {
    const float reach = r.a * r.R;
    return glm::vec4(r.p, reach * reach);
  }
  std::vector<float> lambda_, gradT_, gradB_;           // record frame
  std::vector<float> lambdaW_, gradTW_, gradBW_;        // world frame (world-frame mode only)
  bool hasWorld_ = false;
  RecordOctree octree_;
  float maxReach_ = 0.0f;  // largest a_i·R_i ever inserted (bounds relaxed queries)
  std::vector<uint8_t> skipped_;  // setSkipped's mask (shorter than infos_ or empty)
  void lookupLocked(const Vec3& p, const Vec3& n, Lookup& out, bool brute, float scale = 1.0f) const;
  Color cosineIrradianceLocked(const Lookup& lk, const Vec3& n, bool gradients) const;
  void copyCoefficientsLocked(uint32_t id, bool world, float* lambda, float* gradT, float* gradB) const;
};

}  // namespace rc
