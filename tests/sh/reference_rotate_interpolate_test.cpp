// ref::rotate and ref::interpolate: agreement with the SH library, fast paths, validation,
// normalised weights, per-record == world-frame, a point exactly at a record, Range writes only
// its items.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "sh/reference.h"
#include "sh_test_util.h"

namespace rc {
namespace {

using shtest::Mat3;

std::vector<float> toFloat(const std::vector<double>& v) { return std::vector<float>(v.begin(), v.end()); }

TEST(RefRotate, MatchesLibraryIncludingFastPaths) {
  constexpr int order = 10, n2 = order * order;
  Rng rng(31);
  std::vector<Mat3> Rs = {{1, 0, 0, 0, 1, 0, 0, 0, 1}, shtest::axisAngle({0, 0, 1}, 0.4), shtest::randomRotation(rng),
                          shtest::axisAngle({1, 0, 0}, shtest::kPi)};
  RotateBatch b;
  b.order = order;
  b.count = static_cast<int>(Rs.size());
  for (const Mat3& R : Rs)
    for (double v : R) b.rotations.push_back(float(v));
  for (int i = 0; i < 3 * n2 * b.count; ++i) b.coeffs.push_back(2 * rng.nextFloat() - 1);
  std::vector<float> out;
  ref::rotate(b, out);
  for (int k = 0; k < b.count; ++k) {
    double Rd[9];
    for (int i = 0; i < 9; ++i) Rd[i] = b.rotations[9 * k + i];
    std::vector<double> in(b.coeffs.begin() + 3 * n2 * k, b.coeffs.begin() + 3 * n2 * (k + 1)), bands, res(n2);
    sh::rotationMatrix(order, Rd, bands);  // general path, even for identity / z rotations
    for (int c = 0; c < 3; ++c) {
      sh::applyRotation(order, bands, in.data() + c * n2, res.data());
      // float output of unit-size values: 1e-6 covers float rounding of a 19-term dot product
      for (int i = 0; i < n2; ++i) EXPECT_NEAR(out[3 * n2 * k + c * n2 + i], res[i], 1e-6) << k;
    }
  }
}

TEST(RefRotate, ValidatesAndRangeWritesOnlyItsItems) {
  RotateBatch b;
  b.order = 3;
  b.count = 3;
  b.rotations = {1, 0, 0, 0, 1, 0, 0, 0, 1, 0, -1, 0, 1, 0, 0, 0, 0, 1, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  b.coeffs.assign(27 * 3, 0.5f);
  std::vector<float> out(27 * 3, -7.0f);
  ref::rotateRange(b, out, 1, 2);
  for (int i = 0; i < 81; ++i) EXPECT_EQ(out[i] == -7.0f, i < 27 || i >= 54) << i;
  RotateBatch bad = b;
  bad.coeffs.pop_back();
  EXPECT_THROW(ref::rotate(bad, out), Error);
  bad = b;
  bad.rotations[0] = 2.0f;  // a scale, not a rotation
  EXPECT_THROW(ref::rotate(bad, out), Error);
  bad = b;
  bad.rotations[0] = -1.0f;  // a reflection
  EXPECT_THROW(ref::rotate(bad, out), Error);
  bad = b;
  bad.order = 0;
  EXPECT_THROW(ref::rotate(bad, out), Error);
}

// A small random interpolation problem in both modes. Records and points get random frames;
// world-frame records hold rotate(Λ_local, R_world←record) with R_world←record = F_rᵀ.
struct InterpProblem {
  InterpolateBatch local, world;
};

InterpProblem makeProblem(int order, int R, int P, uint64_t seed) {
  const int n2 = order * order;
  Rng rng(seed);
  InterpProblem pr;
  InterpolateBatch& b = pr.local;
  b.order = order;
  b.worldFrame = false;
  b.records = R;
  b.points = P;
  std::vector<Mat3> frames;
  for (int r = 0; r < R; ++r) {
    frames.push_back(shtest::randomRotation(rng));
    for (double v : frames.back()) b.recordFrames.push_back(float(v));
  }
  for (int i = 0; i < 3 * n2 * R; ++i) {
    b.lambda.push_back(2 * rng.nextFloat() - 1);
    b.gradT.push_back(2 * rng.nextFloat() - 1);
    b.gradB.push_back(2 * rng.nextFloat() - 1);
  }
  b.offsets.push_back(0);
  for (int p = 0; p < P; ++p) {
    const Mat3 F = shtest::randomRotation(rng);
    for (double v : F) b.pointFrames.push_back(float(v));
    const int count = p % 5;  // includes points without contributions
    for (int k = 0; k < count; ++k)
      b.entries.push_back({int(rng.nextUint() % R), 0.1f + rng.nextFloat(), rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f});
    b.offsets.push_back(static_cast<int32_t>(b.entries.size()));
  }
  pr.world = b;
  pr.world.worldFrame = true;
  pr.world.recordFrames.clear();
  for (int r = 0; r < R; ++r) {
    // R_world←record(a, b) = world_a · e_r,b = F_r(b, a), computed from the float frame the
    // per-record mode uses, so both modes see the same geometry.
    double Rw[9];
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 3; ++c) Rw[3 * a + c] = b.recordFrames[9 * r + 3 * c + a];
    for (std::vector<float>* arr : {&pr.world.lambda, &pr.world.gradT, &pr.world.gradB}) {
      std::vector<double> in(arr->begin() + 3 * n2 * r, arr->begin() + 3 * n2 * (r + 1)), out(3 * n2);
      sh::rotateChannels(order, Rw, 3, in.data(), out.data());
      std::copy(out.begin(), out.end(), arr->begin() + 3 * n2 * r);
    }
  }
  return pr;
}

// Both modes compute the same linear expression; differences are float rounding of the stored
// world-frame coefficients (~6e-8 relative) and of the frames (entries of R_p←r formed from
// float rows, ~1e-7), amplified by at most the ~l-fold sensitivity of the band-l rotation to R:
// 10 · 1e-7 · ‖Λ‖∞ (≈ 3) ≈ 3e-6 < 1e-5.
TEST(RefInterpolate, PerRecordEqualsWorldFrame) {
  constexpr int order = 10;
  InterpProblem pr = makeProblem(order, 7, 40, 41);
  std::vector<float> a, b;
  ref::interpolate(pr.local, a);
  ref::interpolate(pr.world, b);
  ASSERT_EQ(a.size(), b.size());
  const int n2 = order * order;
  for (int p = 0; p < pr.local.points; ++p) {
    const bool empty = pr.local.offsets[p] == pr.local.offsets[p + 1];
    for (int i = 0; i < 3 * n2; ++i) {
      EXPECT_NEAR(a[3 * n2 * p + i], b[3 * n2 * p + i], 1e-5) << p << " " << i;
      if (empty) EXPECT_EQ(a[3 * n2 * p + i], 0.0f);
    }
  }
}

// Weights are normalised: scaling all of them changes nothing; with one record the result is
// that record's adjusted, rotated Λ whatever its weight.
TEST(RefInterpolate, WeightsAreNormalised) {
  constexpr int order = 6, n2 = order * order;
  InterpProblem pr = makeProblem(order, 4, 12, 43);
  std::vector<float> a, b;
  ref::interpolate(pr.local, a);
  for (RcContribution& e : pr.local.entries) e.weight *= 37.0f;
  ref::interpolate(pr.local, b);
  for (size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 1e-6);

  InterpolateBatch one = pr.local;
  one.points = 1;
  one.pointFrames.assign(one.recordFrames.begin() + 18, one.recordFrames.begin() + 27);  // frame of record 2
  one.offsets = {0, 1};
  one.entries = {{2, 123.0f, 0.25f, -0.5f}};
  ref::interpolate(one, a);
  for (int i = 0; i < 3 * n2; ++i) {
    const double expect = one.lambda[3 * n2 * 2 + i] + 0.25 * one.gradT[3 * n2 * 2 + i] - 0.5 * one.gradB[3 * n2 * 2 + i];
    EXPECT_NEAR(a[i], expect, 1e-6) << i;
  }
}

// A point exactly at a record (same frame, zero displacement) returns the record's Λ: exactly in
// per-record mode (identity fast path), to 1e-5 in world mode (rotated there and back in float).
TEST(RefInterpolate, PointAtRecordReturnsItsLambda) {
  constexpr int order = 8, n2 = order * order;
  InterpProblem pr = makeProblem(order, 3, 1, 47);
  for (InterpolateBatch* b : {&pr.local, &pr.world}) {
    b->pointFrames.assign(pr.local.recordFrames.begin() + 9, pr.local.recordFrames.begin() + 18);
    b->offsets = {0, 1};
    b->entries = {{1, 0.7f, 0.0f, 0.0f}};
  }
  std::vector<float> a, w;
  ref::interpolate(pr.local, a);
  ref::interpolate(pr.world, w);
  for (int i = 0; i < 3 * n2; ++i) {
    EXPECT_EQ(a[i], pr.local.lambda[3 * n2 + i]);
    EXPECT_NEAR(w[i], pr.local.lambda[3 * n2 + i], 1e-5);
  }
}

TEST(RefInterpolate, ValidatesAndRangeWritesOnlyItsPoints) {
  constexpr int order = 4, n2 = order * order;
  InterpProblem pr = makeProblem(order, 3, 6, 53);
  std::vector<float> out(3 * n2 * 6, -7.0f);
  ref::interpolateRange(pr.local, out, 2, 4);
  for (int p = 0; p < 6; ++p)
    for (int i = 0; i < 3 * n2; ++i) EXPECT_EQ(out[3 * n2 * p + i] == -7.0f, p < 2 || p >= 4);
  InterpolateBatch bad = pr.local;
  bad.entries[0].record = 3;
  EXPECT_THROW(ref::interpolate(bad, out), Error);
  bad = pr.local;
  bad.entries[0].weight = NAN;
  EXPECT_THROW(ref::interpolate(bad, out), Error);
  bad = pr.local;
  bad.recordFrames.pop_back();
  EXPECT_THROW(ref::interpolate(bad, out), Error);
  bad = pr.local;
  bad.offsets.back() += 1;
  EXPECT_THROW(ref::interpolate(bad, out), Error);
  bad = pr.local;
  bad.gradients = false;
  bad.gradT.clear();
  bad.gradB.clear();
  EXPECT_NO_THROW(ref::interpolate(bad, out));
}

}  // namespace
}  // namespace rc
