#pragma once
// Kernel-vs-reference cases shared by tests/kernels, `rcache verify` and the kernel benchmark
// (as CLBlast shares its test descriptions): seeded random batches with edge cases mixed in, and
// comparisons that apply the tolerance table (host/cl/tolerances.h) element by element.
#include <cstdint>
#include <string>
#include <vector>

#include "sh/batches.h"

namespace rc::cases {

struct Stats {
  double maxAbs = 0, maxRel = 0;  // over all compared values (rel = abs / max(|ref|, 1e-30))
  double worstRatio = 0;          // max of |got − ref| / tolerance; PASS ⇔ ≤ 1
  double tolAtWorst = 0;          // the tolerance at that element
  long long compared = 0;
  bool nonFinite = false;         // the kernel produced NaN/Inf where the reference did not
  bool pass() const { return !nonFinite && worstRatio <= 1.0; }
  void add(double got, double ref, double tol);
  void merge(const Stats& o);
};

// Deterministic generator (std::mt19937 with explicit conversions: identical on every platform).
class Random {
 public:
  explicit Random(uint32_t seed);
  double uniform();                       // [0, 1)
  double uniform(double a, double b) { return a + (b - a) * uniform(); }
  int integer(int n);                     // [0, n)
  void rotation(double R[9]);             // uniform random proper rotation
 private:
  uint32_t state_[624];
  int index_ = 624;
  uint32_t next();
};

// sh_project: records × M×N samples; `edges` mixes NaN/Inf radiance, misses (r ≤ 0, Inf, NaN),
// r → 0 (below minDistance), an all-miss record and a constant-radiance record.
ProjectBatch makeProjectBatch(int order, int M, int N, int records, uint32_t seed, bool gradients, bool edges);
Stats compareProjectLambda(const ProjectBatch& b, const ProjectResult& ref, const ProjectResult& got);
Stats compareProjectGradients(const ProjectBatch& b, const ProjectResult& ref, const ProjectResult& got);

// sh_rotate: random rotations; `edges` puts identity, z-only, 180° (about x, z and a tilted
// axis), near-pole (β = 1e-5 and π − 1e-5), near-identity and float-composed rotations first.
RotateBatch makeRotateBatch(int order, int count, uint32_t seed, bool edges);
Stats compareRotate(const RotateBatch& b, const std::vector<float>& ref, const std::vector<float>& got);

// interpolate: records with random frames; points with 0..6 contributions (some none), frames
// equal to, near, or far from their records' frames.
InterpolateBatch makeInterpolateBatch(int order, int records, int points, uint32_t seed, bool worldFrame, bool gradients);
Stats compareInterpolate(const InterpolateBatch& b, const std::vector<float>& ref, const std::vector<float>& got);

// brdf_dot: three materials (isotropic 1-D at the batch order, isotropic of a different order,
// anisotropic 2-D); ω_o random plus the normal, grazing, on and below the horizon.
BrdfDotBatch makeBrdfDotBatch(int order, int points, uint32_t seed);
Stats compareBrdfDot(const BrdfDotBatch& b, const std::vector<float>& ref, const std::vector<float>& got);

}  // namespace rc::cases
