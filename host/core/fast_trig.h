#pragma once
// Inline float sin/cos, atan2 and acos for the per-sample lat-long mappings (the envmap's
// direction ↔ (u, v)): the same values as libm's to within a few float ulps (tests/core
// fast_trig_test.cpp bounds them against double precision), without a call, and written as
// straight-line arithmetic with selects so that a loop over arrays of angles can vectorise them.
//
// Range reduction and polynomials follow Cephes (S. L. Moshier, sinf.c/atanf.c/asinf.c): the
// argument reduced by Cody–Waite to [−π/4, π/4] (sin/cos), to [0, tan π/8] (atan) or to [0, 1/2]
// (asin), then a short minimax polynomial. Valid for finite arguments; sinCos for |x| ≤ 8192
// (beyond, the reduction loses bits), acos for x ∈ [−1, 1].
#include <cmath>
#include <cstdint>

namespace rc {

namespace fast_trig_detail {
constexpr float kPiF = 3.14159265358979323846f;
constexpr float kHalfPiF = 1.57079632679489661923f;
constexpr float kQuarterPiF = 0.78539816339744830962f;
// sin r and cos r for r ∈ [−π/4, π/4].
inline float sinPoly(float r) {
  const float z = r * r;
  return ((-1.9515295891e-4f * z + 8.3321608736e-3f) * z - 1.6666654611e-1f) * z * r + r;
}
inline float cosPoly(float r) {
  const float z = r * r;
  return ((2.443315711809948e-5f * z - 1.388731625493765e-3f) * z + 4.166664568298827e-2f) * z * z - 0.5f * z + 1.0f;
}
// atan a for a ∈ [0, 1]: above tan π/8 through atan a = π/4 + atan((a − 1)/(a + 1)).
inline float atanUnit(float a) {
  const bool upper = a > 0.4142135623730950f;
  const float r = upper ? (a - 1.0f) / (a + 1.0f) : a;
  const float z = r * r;
  const float p = (((8.05374449538e-2f * z - 1.38776856032e-1f) * z + 1.99777106478e-1f) * z - 3.33329491539e-1f) * z * r + r;
  return (upper ? kQuarterPiF : 0.0f) + p;
}
// asin a for a ∈ [0, 1/2].
inline float asinHalf(float a) {
  const float z = a * a;
  return ((((4.2163199048e-2f * z + 2.4181311049e-2f) * z + 4.5470025998e-2f) * z + 7.4953002686e-2f) * z +
          1.6666752422e-1f) * z * a + a;
}
}  // namespace fast_trig_detail

// sin x and cos x (|x| ≤ 8192).
inline void sinCosFast(float x, float& sinX, float& cosX) {
  using namespace fast_trig_detail;
  const float ax = std::fabs(x);
  // The even multiple j of π/4 nearest below-or-at ax's octant pair, so r = ax − j·π/4 ∈ [−π/4, π/4];
  // π/4 split in three so that j·DP1 and j·DP2 are exact.
  int j = static_cast<int>(ax * 1.27323954473516f);
  j += j & 1;
  const float y = static_cast<float>(j);
  const float r = ((ax - y * 0.78515625f) - y * 2.4187564849853515625e-4f) - y * 3.77489497744594108e-8f;
  const float s = sinPoly(r), c = cosPoly(r);
  // ax = q·π/2 + r: sin(q·π/2 + r) is s, c, −s, −c and cos is c, −s, −c, s for q = 0 … 3.
  const int q = (j >> 1) & 3;
  float sv = (q & 1) ? c : s;
  float cv = (q & 1) ? s : c;
  sv = (q & 2) ? -sv : sv;
  cv = ((q + 1) & 2) ? -cv : cv;
  sinX = x < 0.0f ? -sv : sv;
  cosX = cv;
}

// atan2(y, x) with IEEE's signed zeros: atan2(±0, +0) = ±0, atan2(±0, −0) = ±π.
inline float atan2Fast(float y, float x) {
  using namespace fast_trig_detail;
  const float ax = std::fabs(x), ay = std::fabs(y);
  const float hi = ax > ay ? ax : ay, lo = ax > ay ? ay : ax;
  float r = atanUnit(hi > 0.0f ? lo / hi : 0.0f);  // angle of (ax, ay) measured from the nearer axis
  r = ay > ax ? kHalfPiF - r : r;
  r = std::signbit(x) ? kPiF - r : r;
  return std::copysign(r, y);
}

// acos x for x ∈ [−1, 1].
inline float acosFast(float x) {
  using namespace fast_trig_detail;
  const float ax = std::fabs(x);
  // Near ±1 through acos a = 2·asin √((1 − a)/2) (no cancellation), else π/2 − asin a.
  const bool outer = ax > 0.5f;
  const float s = outer ? std::sqrt(0.5f * (1.0f - ax)) : ax;
  const float a = asinHalf(s);
  const float positive = outer ? 2.0f * a : kHalfPiF - a;  // acos |x|
  if (!outer) return x < 0.0f ? kHalfPiF + a : positive;
  return x < 0.0f ? kPiF - positive : positive;
}

}  // namespace rc
