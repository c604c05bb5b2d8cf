#include "cl/kernel_cases.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "cl/tolerances.h"

namespace rc::cases {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

void matMul(const double A[9], const double B[9], double C[9]) {
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) C[3 * r + c] = A[3 * r] * B[c] + A[3 * r + 1] * B[3 + c] + A[3 * r + 2] * B[6 + c];
}
void rotZ(double a, double R[9]) {
  const double c = std::cos(a), s = std::sin(a);
  const double m[9] = {c, -s, 0, s, c, 0, 0, 0, 1};
  std::copy(m, m + 9, R);
}
void rotY(double a, double R[9]) {
  const double c = std::cos(a), s = std::sin(a);
  const double m[9] = {c, 0, s, 0, 1, 0, -s, 0, c};
  std::copy(m, m + 9, R);
}
void axisAngle(double x, double y, double z, double a, double R[9]) {
  const double n = std::sqrt(x * x + y * y + z * z);
  x /= n, y /= n, z /= n;
  const double c = std::cos(a), s = std::sin(a), t = 1 - c;
  const double m[9] = {t * x * x + c,     t * x * y - s * z, t * x * z + s * y, t * x * y + s * z, t * y * y + c,
                       t * y * z - s * x, t * x * z - s * y, t * y * z + s * x, t * z * z + c};
  std::copy(m, m + 9, R);
}
double bandNorm(const float* v, int l) {
  double s = 0;
  for (int i = l * l; i < (l + 1) * (l + 1); ++i) s += double(v[i]) * v[i];
  return std::sqrt(s);
}
}  // namespace

void Stats::add(double got, double ref, double tol) {
  ++compared;
  if (!std::isfinite(got) && std::isfinite(ref)) {
    nonFinite = true;
    worstRatio = std::numeric_limits<double>::infinity();
    return;
  }
  const double err = std::fabs(got - ref);
  tol = std::max(tol, tol::kAbsFloor);
  maxAbs = std::max(maxAbs, err);
  maxRel = std::max(maxRel, err / std::max(std::fabs(ref), 1e-30));
  if (err / tol > worstRatio || tolAtWorst == 0) {
    worstRatio = std::max(worstRatio, err / tol);
    tolAtWorst = tol;
  }
}

void Stats::merge(const Stats& o) {
  maxAbs = std::max(maxAbs, o.maxAbs);
  maxRel = std::max(maxRel, o.maxRel);
  if (o.worstRatio > worstRatio) {
    worstRatio = o.worstRatio;
    tolAtWorst = o.tolAtWorst;
  }
  compared += o.compared;
  nonFinite = nonFinite || o.nonFinite;
}

// ---- random ----------------------------------------------------------------------------------
Random::Random(uint32_t seed) {
  state_[0] = seed;
  for (int i = 1; i < 624; ++i) state_[i] = 1812433253u * (state_[i - 1] ^ (state_[i - 1] >> 30)) + i;
}
uint32_t Random::next() {  // MT19937
  if (index_ >= 624) {
    for (int i = 0; i < 624; ++i) {
      const uint32_t y = (state_[i] & 0x80000000u) | (state_[(i + 1) % 624] & 0x7fffffffu);
      state_[i] = state_[(i + 397) % 624] ^ (y >> 1) ^ ((y & 1u) ? 0x9908b0dfu : 0u);
    }
    index_ = 0;
  }
  uint32_t y = state_[index_++];
  y ^= y >> 11;
  y ^= (y << 7) & 0x9d2c5680u;
  y ^= (y << 15) & 0xefc60000u;
  y ^= y >> 18;
  return y;
}
double Random::uniform() { return (next() >> 8) * (1.0 / 16777216.0); }
int Random::integer(int n) { return std::min(n - 1, static_cast<int>(uniform() * n)); }
void Random::rotation(double R[9]) {
  // Uniform unit quaternion (Shoemake).
  const double u1 = uniform(), u2 = uniform() * 2 * kPi, u3 = uniform() * 2 * kPi;
  const double a = std::sqrt(1 - u1), b = std::sqrt(u1);
  const double w = a * std::sin(u2), x = a * std::cos(u2), y = b * std::sin(u3), z = b * std::cos(u3);
  const double m[9] = {1 - 2 * (y * y + z * z), 2 * (x * y - z * w),     2 * (x * z + y * w),
                       2 * (x * y + z * w),     1 - 2 * (x * x + z * z), 2 * (y * z - x * w),
                       2 * (x * z - y * w),     2 * (y * z + x * w),     1 - 2 * (x * x + y * y)};
  std::copy(m, m + 9, R);
}

// ---- sh_project --------------------------------------------------------------------------------
ProjectBatch makeProjectBatch(int order, int M, int N, int records, uint32_t seed, bool gradients, bool edges) {
  Random rng(seed);
  ProjectBatch b;
  b.order = order;
  b.M = M;
  b.N = N;
  b.records = records;
  b.gradients = gradients;
  const int S = M * N;
  b.pattern.resize(2 * S);
  for (float& v : b.pattern) v = static_cast<float>(rng.uniform());
  b.phi0.resize(records);
  for (float& v : b.phi0) v = static_cast<float>(rng.uniform(0, 2 * kPi));
  b.radiance.resize(3ull * S * records);
  b.distance.resize(1ull * S * records);
  for (int r = 0; r < records; ++r) {
    // Smooth environment (a few lobes) plus noise: realistic spectra with energy in every band.
    const double lx = rng.uniform(-1, 1), ly = rng.uniform(-1, 1), lz = rng.uniform(0, 1);
    for (int s = 0; s < S; ++s) {
      const int j = s / N, k = s % N;
      const double z = 1 - (j + 0.5) / M, phi = 2 * kPi * (k + 0.5) / N;
      const double st = std::sqrt(1 - z * z), dot = st * std::cos(phi) * lx + st * std::sin(phi) * ly + z * lz;
      for (int c = 0; c < 3; ++c)
        b.radiance[3ull * (r * S + s) + c] = static_cast<float>(std::max(0.0, dot) * (1 + c) + rng.uniform(0, 0.5));
      b.distance[1ull * r * S + s] = static_cast<float>(rng.uniform(0.2, 5.0));
    }
  }
  if (edges && records >= 4) {
    // record 0: NaN/Inf samples, misses of every flavour, r → 0.
    float* rad = b.radiance.data();
    float* dist = b.distance.data();
    const float bad[] = {kNaN, kInf, -kInf};
    for (int i = 0; i < std::min(S, 12); ++i) rad[3 * (i * 7 % S) + i % 3] = bad[i % 3];
    const float miss[] = {0.0f, -1.0f, kInf, kNaN, 1e-7f, 0.0f};
    for (int i = 0; i < std::min(S, 30); ++i) dist[(i * 13 + 5) % S] = miss[i % 6];
    // record 1: all misses. record 2: constant radiance 1 (λ₀⁰ = 2π·y₀⁰, gradients 0).
    std::fill(b.distance.begin() + S, b.distance.begin() + 2 * S, 0.0f);
    std::fill(b.radiance.begin() + 6ull * S, b.radiance.begin() + 9ull * S, 1.0f);
    // record 3: geometry touching the record (r → 0 everywhere in one row).
    for (int k = 0; k < N; ++k) dist[3 * S + (M / 2) * N + k] = 1e-9f;
  }
  return b;
}

namespace {
Stats compareProjectPart(const ProjectBatch& b, const std::vector<float>& ref, const std::vector<float>& got,
                         bool gradient) {
  Stats st;
  const int n2 = b.order * b.order, S = b.M * b.N;
  const double ymax = tol::shMax(b.order);
  const double arc = 2 * std::sin(kPi / b.N);
  auto rho = [&](int r, int s) {
    const float d = b.distance[1ull * r * S + s];
    return (d > 0 && std::isfinite(d)) ? 1.0 / std::max<double>(d, b.minDistance) : 0.0;
  };
  auto radiance = [&](int r, int s, int c) {
    const float* L = b.radiance.data() + 3ull * (1ull * r * S + s);
    return (std::isfinite(L[0]) && std::isfinite(L[1]) && std::isfinite(L[2])) ? std::fabs(double(L[c])) : 0.0;
  };
  for (int r = 0; r < b.records; ++r) {
    for (int c = 0; c < 3; ++c) {
      double sumAbs = 0, edgeSum = 0;
      for (int s = 0; s < S; ++s) sumAbs += radiance(r, s, c);
      if (gradient) {
        // Σ over edges of |edge coefficient|·max(ρ, ρ')·(|L| + |L'|): bounds Σ_s (|wT_s| + |wB_s|).
        for (int j = 0; j < b.M; ++j)
          for (int k = 0; k < b.N; ++k) {
            const int s = j * b.N + k, sPrev = j * b.N + (k + b.N - 1) % b.N;
            const double dTheta = std::acos(1.0 - (j + 1.0) / b.M) - std::acos(1.0 - double(j) / b.M);
            edgeSum += dTheta * std::max(rho(r, s), rho(r, sPrev)) * (radiance(r, s, c) + radiance(r, sPrev, c));
            if (j > 0) {
              const double cj = 1.0 - double(j) / b.M, sj = std::sqrt(1 - cj * cj);
              edgeSum += arc * cj * sj * std::max(rho(r, s), rho(r, s - b.N)) * (radiance(r, s, c) + radiance(r, s - b.N, c));
            }
          }
      }
      const double tol = gradient ? tol::kEps * tol::gradSteps(S, b.order) * edgeSum * ymax
                                  : tol::kEps * tol::projectSteps(S, b.order) * (2 * kPi / S) * sumAbs * ymax;
      for (int i = 0; i < n2; ++i) {
        const size_t at = (3ull * r + c) * n2 + i;
        st.add(got[at], ref[at], tol);
      }
    }
  }
  return st;
}
}  // namespace

Stats compareProjectLambda(const ProjectBatch& b, const ProjectResult& ref, const ProjectResult& got) {
  Stats st = compareProjectPart(b, ref.lambda, got.lambda, false);
  for (int r = 0; r < b.records; ++r)  // dropped counts must match exactly
    if (ref.dropped[r] != got.dropped[r]) st.add(1.0, 0.0, 0.0);
  return st;
}

Stats compareProjectGradients(const ProjectBatch& b, const ProjectResult& ref, const ProjectResult& got) {
  Stats st = compareProjectPart(b, ref.gradT, got.gradT, true);
  st.merge(compareProjectPart(b, ref.gradB, got.gradB, true));
  return st;
}

// ---- sh_rotate ---------------------------------------------------------------------------------
RotateBatch makeRotateBatch(int order, int count, uint32_t seed, bool edges) {
  Random rng(seed);
  RotateBatch b;
  b.order = order;
  b.count = count;
  const int n2 = order * order;
  b.rotations.resize(9ull * count);
  b.coeffs.resize(3ull * n2 * count);
  for (float& v : b.coeffs) v = static_cast<float>(rng.uniform(-1, 1));
  std::vector<std::vector<double>> special;
  if (edges) {
    double R[9], A[9], B[9];
    auto push = [&](const double* m) { special.emplace_back(m, m + 9); };
    const double I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    push(I);
    rotZ(0.7, R), push(R);
    rotZ(kPi, R), push(R);
    rotZ(-2.5, R), push(R);
    axisAngle(1, 0, 0, kPi, R), push(R);             // β = π exactly
    axisAngle(1, 1, 0, kPi, R), push(R);             // 180° about a tilted horizontal axis
    axisAngle(0.3, -0.2, 1, kPi, R), push(R);        // 180° about a generic axis
    rotZ(1.0, A), rotY(1e-5, B), matMul(B, A, R), push(R);          // near pole, β = 1e-5
    rotZ(-0.4, A), rotY(kPi - 1e-5, B), matMul(A, B, R), push(R);   // near the other pole
    axisAngle(0.2, 0.9, 0.1, 1e-4, R), push(R);      // near identity
    axisAngle(0.6, -0.3, 0.2, 3e-7, R), push(R);     // just above / below the z-only threshold
    rotY(1e-8, R), push(R);
  }
  for (int i = 0; i < count; ++i) {
    double R[9];
    if (i < static_cast<int>(special.size())) std::copy(special[i].begin(), special[i].end(), R);
    else rng.rotation(R);
    for (int k = 0; k < 9; ++k) b.rotations[9ull * i + k] = static_cast<float>(R[k]);
  }
  if (edges && count > static_cast<int>(special.size()) + 1) {
    // A rotation composed in float (absolute, not relative, rounding in the small entries), the
    // way interpolate forms F_p·F_rᵀ: near-identity product of two float frames.
    double A[9], B[9];
    rng.rotation(A);
    axisAngle(0.5, 0.5, 0.1, 2e-4, B);
    double AB[9];
    matMul(B, A, AB);
    float fa[9], fb[9];
    for (int k = 0; k < 9; ++k) fa[k] = static_cast<float>(AB[k]), fb[k] = static_cast<float>(A[k]);
    float* out = b.rotations.data() + 9ull * special.size();
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) out[3 * r + c] = fa[3 * r] * fb[3 * c] + fa[3 * r + 1] * fb[3 * c + 1] + fa[3 * r + 2] * fb[3 * c + 2];
  }
  return b;
}

Stats compareRotate(const RotateBatch& b, const std::vector<float>& ref, const std::vector<float>& got) {
  Stats st;
  const int n2 = b.order * b.order;
  for (int i = 0; i < b.count; ++i)
    for (int c = 0; c < 3; ++c) {
      const float* x = b.coeffs.data() + (3ull * i + c) * n2;
      for (int l = 0; l < b.order; ++l) {
        const double tol = tol::kEps * tol::rotateSteps(l) * bandNorm(x, l);
        for (int k = l * l; k < (l + 1) * (l + 1); ++k) {
          const size_t at = (3ull * i + c) * n2 + k;
          st.add(got[at], ref[at], tol);
        }
      }
    }
  return st;
}

// ---- interpolate -------------------------------------------------------------------------------
InterpolateBatch makeInterpolateBatch(int order, int records, int points, uint32_t seed, bool worldFrame,
                                      bool gradients) {
  Random rng(seed);
  InterpolateBatch b;
  b.order = order;
  b.worldFrame = worldFrame;
  b.gradients = gradients;
  b.records = records;
  b.points = points;
  const int n2 = order * order;
  b.lambda.resize(3ull * n2 * records);
  for (float& v : b.lambda) v = static_cast<float>(rng.uniform(-1, 1));
  if (gradients) {
    b.gradT.resize(b.lambda.size());
    b.gradB.resize(b.lambda.size());
    for (float& v : b.gradT) v = static_cast<float>(rng.uniform(-2, 2));
    for (float& v : b.gradB) v = static_cast<float>(rng.uniform(-2, 2));
  }
  std::vector<double> recR(9ull * records);
  b.recordFrames.resize(9ull * records);
  for (int r = 0; r < records; ++r) {
    rng.rotation(&recR[9ull * r]);
    for (int k = 0; k < 9; ++k) b.recordFrames[9ull * r + k] = static_cast<float>(recR[9ull * r + k]);
  }
  b.pointFrames.resize(9ull * points);
  b.offsets.assign(1, 0);
  for (int p = 0; p < points; ++p) {
    const int kind = p % 4;
    const int count = (p % 7 == 3) ? 0 : 1 + rng.integer(6);  // some points have no contribution
    const int first = records ? rng.integer(records) : 0;
    double F[9];
    if (kind == 0 || records == 0) {
      rng.rotation(F);  // unrelated frame
    } else {
      const double* Fr = &recR[9ull * first];
      double D[9];
      if (kind == 1) axisAngle(1, 0, 0, 0, D);  // identical frame
      else axisAngle(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1), kind == 2 ? 1e-3 : 0.3, D);
      // rows of F = rows of Fr turned by D: F = Fr·Dᵀ keeps it orthonormal
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) F[3 * r + c] = Fr[3 * r] * D[3 * c] + Fr[3 * r + 1] * D[3 * c + 1] + Fr[3 * r + 2] * D[3 * c + 2];
    }
    for (int k = 0; k < 9; ++k) b.pointFrames[9ull * p + k] = static_cast<float>(F[k]);
    for (int e = 0; e < count && records > 0; ++e) {
      RcContribution c;
      c.record = e == 0 ? first : rng.integer(records);
      c.weight = static_cast<float>(rng.uniform(0.05, 4.0));
      c.dt = static_cast<float>(rng.uniform(-0.5, 0.5));
      c.db = static_cast<float>(rng.uniform(-0.5, 0.5));
      b.entries.push_back(c);
    }
    b.offsets.push_back(static_cast<int32_t>(b.entries.size()));
  }
  return b;
}

Stats compareInterpolate(const InterpolateBatch& b, const std::vector<float>& ref, const std::vector<float>& got) {
  Stats st;
  const int n2 = b.order * b.order;
  for (int p = 0; p < b.points; ++p) {
    const int e0 = b.offsets[p], e1 = b.offsets[p + 1];
    double wsum = 0;
    for (int e = e0; e < e1; ++e) wsum += b.entries[e].weight;
    for (int c = 0; c < 3; ++c)
      for (int l = 0; l < b.order; ++l) {
        double mag = 0;
        for (int e = e0; e < e1; ++e) {
          const RcContribution& k = b.entries[e];
          const size_t base = (3ull * k.record + c) * n2;
          double m = bandNorm(b.lambda.data() + base, l);
          if (b.gradients)
            m += std::fabs(k.dt) * bandNorm(b.gradT.data() + base, l) + std::fabs(k.db) * bandNorm(b.gradB.data() + base, l);
          mag += k.weight * m;
        }
        if (wsum > 0) mag /= wsum;
        const double tol = tol::kEps * tol::interpolateSteps(l, e1 - e0) * mag;
        for (int i = l * l; i < (l + 1) * (l + 1); ++i) {
          const size_t at = (3ull * p + c) * n2 + i;
          st.add(got[at], ref[at], tol);
        }
      }
  }
  return st;
}

// ---- brdf_dot ----------------------------------------------------------------------------------
BrdfDotBatch makeBrdfDotBatch(int order, int points, uint32_t seed) {
  Random rng(seed);
  BrdfDotBatch b;
  b.order = order;
  b.points = points;
  const int n2 = order * order;
  auto addTable = [&](int kind, int tOrder, int res) {
    RcBrdfTable t;
    t.kind = kind;
    t.order = tOrder;
    t.res = res;
    t.offset = static_cast<rc_int>(b.tableData.size());
    const long long entries = kind == RC_TABLE_ISOTROPIC_1D ? res : 1ll * res * res;
    for (long long e = 0; e < entries * 3 * tOrder * tOrder; ++e) b.tableData.push_back(static_cast<float>(rng.uniform(-0.5, 1.0)));
    b.tables.push_back(t);
  };
  addTable(RC_TABLE_ISOTROPIC_1D, order, 33);
  addTable(RC_TABLE_ISOTROPIC_1D, order > 2 ? order - 2 : std::min(order + 2, kMaxReferenceOrder), 17);
  addTable(RC_TABLE_ANISOTROPIC_2D, order, 9);
  b.lambda.resize(3ull * n2 * points);
  for (float& v : b.lambda) v = static_cast<float>(rng.uniform(-1, 1));
  b.wo.resize(3ull * points);
  b.material.resize(points);
  for (int p = 0; p < points; ++p) {
    double x, y, z;
    switch (p % 16) {
      case 0: x = 0, y = 0, z = 1; break;                          // normal
      case 1: x = std::sqrt(1 - 1e-12), y = 0, z = 1e-6; break;    // grazing
      case 2: x = 0.6, y = 0.8, z = 0; break;                      // on the horizon
      case 3: x = 0.3, y = -0.4, z = -std::sqrt(0.75); break;      // below
      default: {
        z = rng.uniform(0, 1);
        const double phi = rng.uniform(0, 2 * kPi), s = std::sqrt(1 - z * z);
        x = s * std::cos(phi), y = s * std::sin(phi);
      }
    }
    b.wo[3ull * p] = static_cast<float>(x);
    b.wo[3ull * p + 1] = static_cast<float>(y);
    b.wo[3ull * p + 2] = static_cast<float>(z);
    b.material[p] = p % 3;
  }
  return b;
}

Stats compareBrdfDot(const BrdfDotBatch& b, const std::vector<float>& ref, const std::vector<float>& got) {
  Stats st;
  const int n2 = b.order * b.order;
  std::vector<std::vector<double>> fmax(b.tables.size());  // [table][c·tn2 + i] = max over entries
  for (size_t k = 0; k < b.tables.size(); ++k) {
    const RcBrdfTable& t = b.tables[k];
    const int tn2 = t.order * t.order;
    const long long entries = t.kind == RC_TABLE_ISOTROPIC_1D ? t.res : 1ll * t.res * t.res;
    fmax[k].assign(3 * tn2, 0.0);
    for (long long e = 0; e < entries; ++e)
      for (int i = 0; i < 3 * tn2; ++i)
        fmax[k][i] = std::max(fmax[k][i], double(std::fabs(b.tableData[t.offset + e * 3 * tn2 + i])));
  }
  for (int p = 0; p < b.points; ++p) {
    const RcBrdfTable& t = b.tables[b.material[p]];
    const int tn2 = t.order * t.order, common = std::min(t.order, b.order);
    for (int c = 0; c < 3; ++c) {
      double mag = 0;
      for (int i = 0; i < common * common; ++i)
        mag += std::fabs(b.lambda[(3ull * p + c) * n2 + i]) * fmax[b.material[p]][c * tn2 + i];
      const double tol = tol::kEps * tol::brdfDotSteps(b.order, t.res) * mag;
      st.add(got[3ull * p + c], ref[3ull * p + c], tol);
    }
  }
  return st;
}

}  // namespace rc::cases
