#pragma once
// Inline float atan2 and acos for the per-sample direction → (u, v) mapping of the envmap: the same
// values as libm's to within a few float ulps (tests/core/fast_trig_test.cpp bounds them against
// double precision), without a call. Written as straight-line arithmetic with selects, so that a
// loop over arrays of directions could vectorise them (not used that way yet). (sin/cos are not
// here: glibc's sincosf costs no more instructions than an inline polynomial.)
//
// Range reduction and polynomials follow Cephes (S. L. Moshier, atanf.c/asinf.c): the argument
// reduced to [0, tan π/8] (atan) or to [0, 1/2] (asin), then a short minimax polynomial. Valid for
// finite arguments; acos for x ∈ [−1, 1].
#include <cmath>

namespace rc {

namespace fast_trig_detail {
constexpr float kPiF = 3.14159265358979323846f;
constexpr float kHalfPiF = 1.57079632679489661923f;
constexpr float kQuarterPiF = 0.78539816339744830962f;
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
  const float negative = outer ? kPiF - positive : kHalfPiF + a;  // acos −|x|
  return x < 0.0f ? negative : positive;
}

}  // namespace rc
