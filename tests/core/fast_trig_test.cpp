// core/fast_trig.h against double-precision libm over dense sweeps of the domains the renderer uses,
// in units of the float spacing (ulp) at the exact value. The bounds are the accuracy the header
// promises ("a few float ulps"); libm's float functions are within 1 ulp, Cephes's polynomials
// measure 2.6 (atan2) and 1.3 (acos) here, and a coefficient or reduction mistake
// shows up as thousands of ulps.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/fast_trig.h"

using namespace rc;

namespace {
// |got − exact| in ulps of the float nearest the exact value.
double ulpError(float got, double exact) {
  const float nearest = static_cast<float>(exact);
  const double ulp = std::nextafter(std::fabs(nearest), std::numeric_limits<float>::infinity()) - std::fabs(nearest);
  return std::fabs(static_cast<double>(got) - exact) / ulp;
}
}  // namespace

TEST(FastTrig, Atan2WithinThreeUlpsOnEveryQuadrant) {
  double worst = 0.0;
  for (int i = 0; i < 2000; ++i)
    for (int k = 0; k < 500; ++k) {
      const double t = 2.0 * 3.14159265358979323846 * i / 2000.0, r = 1e-3 + 10.0 * k / 500.0;
      const float y = static_cast<float>(r * std::sin(t)), x = static_cast<float>(r * std::cos(t));
      worst = std::max(worst, ulpError(atan2Fast(y, x), std::atan2(static_cast<double>(y), static_cast<double>(x))));
    }
  EXPECT_LE(worst, 3.0);
  // The axes and IEEE's signed zeros, as std::atan2 gives them (envUv reaches them at the poles).
  for (const float y : {0.0f, -0.0f, 1.0f, -1.0f})
    for (const float x : {0.0f, -0.0f, 1.0f, -1.0f}) {
      const float exact = std::atan2(y, x);
      EXPECT_NEAR(atan2Fast(y, x), exact, 4e-7f) << y << ", " << x;
      EXPECT_EQ(std::signbit(atan2Fast(y, x)), std::signbit(exact)) << y << ", " << x;
    }
}

TEST(FastTrig, AcosWithinTwoUlpsOnMinusOneToOne) {
  const int n = 1 << 21;
  double worst = 0.0;
  for (int i = 0; i <= n; ++i) {
    const float x = -1.0f + 2.0f * static_cast<float>(i) / n;
    worst = std::max(worst, ulpError(acosFast(x), std::acos(static_cast<double>(x))));
  }
  EXPECT_LE(worst, 2.0);
  EXPECT_EQ(acosFast(1.0f), 0.0f);
  EXPECT_NEAR(acosFast(-1.0f), 3.14159265f, 3e-7f);
  EXPECT_NEAR(acosFast(0.0f), 1.57079633f, 2e-7f);
}
