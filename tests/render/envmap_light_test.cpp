// The envmap emitter against Mitsuba 3's definition (src/emitters/envmap.cpp): direction ↔ (u, v)
// = (atan2(x, −z)/2π, acos(y)/π); bilinear radiance with texel centres u = (x+0.5)/W (periodic)
// and v = y/(H−1) (first/last row on the poles); pad to ≥ 2×3 by replication. The expected values
// below are computed from that definition by hand, not from the implementation's output.
#include <gtest/gtest.h>

#include <cmath>

#include "core/rng.h"
#include "render/envmap_light.h"

namespace rc {
namespace {

// A W×H map whose texels all differ: red codes x, green codes y, blue a constant.
std::vector<Color> codedTexels(int W, int H) {
  std::vector<Color> px;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) px.push_back(Color(1.0f + x, 1.0f + 10.0f * y, 0.5f));
  return px;
}

Vec3 dirAt(float u, float v) { return envDirection(u, v); }

void expectColorNear(const Color& a, const Color& b, float tol) {
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[k], b[k], tol * std::max(1.0f, std::fabs(b[k]))) << "channel " << k;
}

TEST(EnvmapLight, MappingIsMitsubas) {
  // Mitsuba: d = (sinθ sinφ, cosθ, −sinθ cosφ), θ = vπ, φ = 2πu.
  expectColorNear(envDirection(0.0f, 0.5f), Color(0, 0, -1), 1e-6f);
  expectColorNear(envDirection(0.25f, 0.5f), Color(1, 0, 0), 1e-6f);
  expectColorNear(envDirection(0.3f, 0.0f), Color(0, 1, 0), 1e-6f);
  const Vec2 uv = envUv(glm::normalize(Vec3(-1, 0, 0)));
  EXPECT_NEAR(uv.x, 0.75f, 1e-6f);
  EXPECT_NEAR(uv.y, 0.5f, 1e-6f);
}

TEST(EnvmapLight, TexelCentresReturnTheTexel) {
  const int W = 8, H = 5;
  const std::vector<Color> px = codedTexels(W, H);
  const EnvmapLight env(W, H, px, 2.0f, Mat3(1.0f));
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      // Avoid the exact poles, where φ is undefined but every texel of the row is hit by some φ.
      const float v = y == 0 ? 1e-5f : y == H - 1 ? 1.0f - 1e-5f : float(y) / (H - 1);
      expectColorNear(env.eval(dirAt((x + 0.5f) / W, v)), 2.0f * px[y * W + x], 2e-3f);
    }
}

TEST(EnvmapLight, BilinearBetweenTexelsAndAcrossTheSeam) {
  const int W = 8, H = 5;
  const std::vector<Color> px = codedTexels(W, H);
  const EnvmapLight env(W, H, px, 1.0f, Mat3(1.0f));
  auto at = [&](int x, int y) { return px[y * W + x]; };
  // Halfway between rows 1 and 2 (v = 1.5/4) at column 3's centre: their mean.
  expectColorNear(env.eval(dirAt(3.5f / W, 1.5f / (H - 1))), 0.5f * (at(3, 1) + at(3, 2)), 1e-4f);
  // A quarter of the way from column 2 to column 3 on row 2.
  expectColorNear(env.eval(dirAt(2.75f / W, 2.0f / (H - 1))), 0.75f * at(2, 2) + 0.25f * at(3, 2), 1e-4f);
  // u = 0 lies halfway between the last and the first column (periodic in φ).
  expectColorNear(env.eval(dirAt(0.0f, 2.0f / (H - 1))), 0.5f * (at(W - 1, 2) + at(0, 2)), 1e-4f);
  // The horizon of an even-height map lies halfway between rows H/2 − 1 and H/2 (a sharp sky/ground
  // change there is a ramp in Mitsuba, not a step at v = 0.5).
  const int H2 = 4;
  std::vector<Color> sky;
  for (int y = 0; y < H2; ++y)
    for (int x = 0; x < W; ++x) sky.push_back(y < H2 / 2 ? Color(4.0f) : Color(0.0f));
  const EnvmapLight horizon(W, H2, sky, 1.0f, Mat3(1.0f));
  expectColorNear(horizon.eval(Vec3(1, 0, 0)), Color(2.0f), 1e-4f);
  // v = 0.4 → row coordinate 1.2: 80 % of row 1 (bright) and 20 % of row 2 (dark).
  expectColorNear(horizon.eval(dirAt(0.1f, 0.4f)), Color(3.2f), 1e-3f);
}

TEST(EnvmapLight, ToWorldRotatesTheMap) {
  const int W = 8, H = 5;
  const std::vector<Color> px = codedTexels(W, H);
  // Local +y (the image's top) → world +z.
  const Mat3 toWorld(Vec3(1, 0, 0), Vec3(0, 0, 1), Vec3(0, -1, 0));
  const EnvmapLight env(W, H, px, 1.0f, toWorld);
  const Vec3 local = dirAt(5.5f / W, 1.0f / (H - 1));
  expectColorNear(env.eval(toWorld * local), px[1 * W + 5], 1e-3f);
  // World +z is the local pole: the top row (its green code), whatever φ picks along it.
  EXPECT_NEAR(env.eval(Vec3(0, 0, 1)).g, px[0].g, 1e-3f);
}

TEST(EnvmapLight, SmallImagesArePaddedByReplication) {
  const EnvmapLight one(1, 1, {Color(0.2f, 0.4f, 0.8f)}, 1.0f, Mat3(1.0f));
  Rng rng(3);
  for (int i = 0; i < 50; ++i) {
    const Vec3 d = envDirection(rng.nextFloat(), rng.nextFloat());
    expectColorNear(one.eval(d), Color(0.2f, 0.4f, 0.8f), 1e-5f);
  }
  // A constant map's density is uniform-ish: ∫pdf over the sphere is 1 (checked below in general).
  EXPECT_GT(one.pdf(Vec3(1, 0, 0)), 0.0f);
}

// A sky with a sharp horizon and a bright sun texel.
const Mat3 kSunSkyTurn(glm::mat3(Vec3(1, 0, 0), Vec3(0, 0, 1), Vec3(0, -1, 0)));
EnvmapLight sunSky(const Mat3& toWorld = kSunSkyTurn) {
  const int W = 32, H = 16;
  std::vector<Color> px;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x)
      px.push_back((x == 9 && y == 4) ? Color(400.0f, 300.0f, 200.0f) : y < H / 2 ? Color(0.3f, 0.5f, 1.0f) : Color(0.05f));
  return EnvmapLight(W, H, px, 1.0f, toWorld);
}

// Mitsuba's sampling density (its Hierarchical2D warp over luminance · sin θ_row at the texel
// centres): pdf · sinθ is the bilinear interpolation of those weights, up to one normalisation.
// Grey texels (luminance = the value), points inside cells, at the seam and next to a pole.
TEST(EnvmapLight, DensityIsBilinearInLuminanceTimesSinTheta) {
  const int W = 4, H = 5;  // texel rows at θ = 0, π/4, π/2, 3π/4, π
  const float value[H][W] = {{1, 1, 1, 1}, {2, 8, 1, 3}, {5, 1, 1, 6}, {1, 2, 9, 1}, {4, 4, 4, 4}};
  std::vector<Color> px;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) px.push_back(Color(value[y][x]));
  const EnvmapLight env(W, H, px, 1.0f, Mat3(1.0f));
  // The weight at texel (x, y) and its bilinear interpolation at cell coordinates (s, t): u = (s + 0.5)/W, v = t/(H − 1).
  auto weight = [&](int x, int y) { return value[y][x % W] * std::sin(kPiD * y / (H - 1)); };
  auto expected = [&](double s, double t) {
    const int x = static_cast<int>(std::floor(s)), y = static_cast<int>(std::floor(t));
    const double fx = s - x, fy = t - y;
    return (1 - fy) * ((1 - fx) * weight(x, y) + fx * weight(x + 1, y)) + fy * ((1 - fx) * weight(x, y + 1) + fx * weight(x + 1, y + 1));
  };
  auto measured = [&](double s, double t) {
    float sinTheta;
    const Vec3 d = envDirection(static_cast<float>((s + 0.5) / W), static_cast<float>(t / (H - 1)), &sinTheta);
    return double(env.pdf(d)) * sinTheta;
  };
  const double points[][2] = {{0.3, 1.6}, {1.5, 1.5}, {2.9, 2.2}, {3.7, 2.5}, {0.5, 0.1}, {2.2, 3.8}};
  const double scale = measured(1.25, 1.25) / expected(1.25, 1.25);
  for (const auto& p : points)
    EXPECT_NEAR(measured(p[0], p[1]) / scale, expected(p[0], p[1]), 1e-4 * expected(p[0], p[1])) << p[0] << ", " << p[1];
}

// Samples land with the density pdf() reports, also within a cell (bins a quarter of a cell
// wide): the histogram of sampled (u, v) against pdf integrated over each bin, where the bin
// expects ≥ 50 samples, within 5 binomial standard errors.
TEST(EnvmapLight, SampleHistogramMatchesPdfWithinCells) {
  const EnvmapLight env = sunSky(Mat3(1.0f));
  const int W = 32, bands = 15, sub = 4, nu = W * sub, nv = bands * sub, n = 1000000;
  std::vector<int> count(static_cast<size_t>(nu) * nv, 0);
  Rng rng(6);
  for (int k = 0; k < n; ++k) {
    const EnvmapLight::Sample smp = env.sample(Vec2(rng.nextFloat(), rng.nextFloat()));
    ASSERT_GT(smp.value.pdf, 0.0f);
    const Vec2 uv = envUv(smp.dir);
    // Cell coordinates: cells start at the texel centres, u = (s + 0.5)/W.
    double s = uv.x * W - 0.5;
    if (s < 0) s += W;
    const int bi = std::min(nu - 1, static_cast<int>(s * sub)), bj = std::min(nv - 1, static_cast<int>(uv.y * bands * sub));
    ++count[static_cast<size_t>(bj) * nu + bi];
  }
  int checked = 0;
  for (int bj = 0; bj < nv; ++bj)
    for (int bi = 0; bi < nu; ++bi) {
      // ∫ pdf dω over the bin by 4×4 midpoints, dω = 2π² sinθ du dv.
      double p = 0.0;
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) {
          const float u = static_cast<float>(((bi + (a + 0.5) / 4) / sub + 0.5) / W);
          const float v = static_cast<float>((bj + (b + 0.5) / 4) / (sub * bands));
          float sinTheta;
          const Vec3 d = envDirection(u >= 1.0f ? u - 1.0f : u, v, &sinTheta);
          p += env.pdf(d) * sinTheta;
        }
      p *= 2.0 * kPiD * kPiD / (16.0 * nu * nv);
      if (n * p < 50.0) continue;
      ++checked;
      const double se = std::sqrt(n * p * (1.0 - p));
      EXPECT_NEAR(count[static_cast<size_t>(bj) * nu + bi], n * p, 5.0 * se + 0.01 * n * p) << "bin " << bi << ", " << bj;
    }
  EXPECT_GT(checked, 1000);
}

TEST(EnvmapLight, SampledPdfIsPdfAndIntegratesToOne) {
  const EnvmapLight env = sunSky();
  float sunSin;
  const Vec3 sunLocal = envDirection(9.5f / 32.0f, 4.0f / 15.0f, &sunSin);
  const float sunPdfSin = env.pdf(kSunSkyTurn * sunLocal) * sunSin;
  Rng rng(4);
  for (int i = 0; i < 2000; ++i) {
    const EnvmapLight::Sample s = env.sample(Vec2(rng.nextFloat(), rng.nextFloat()));
    ASSERT_GT(s.value.pdf, 0.0f);
    // The sample's radiance and density are read at its (u, v), eval's and pdf's at the (u, v)
    // recovered from the direction: they differ by float rounding (≲ 1e-6 in u) times the map's
    // steepest slope (the sun's 400 over one of 32 texel spacings; for the density, which is
    // bilinear in pdf · sinθ, the sun texel's pdf · sinθ over one spacing).
    const float slopeTolerance = 1e-6f * 400.0f * 32.0f;
    const float sinTheta = std::sqrt(s.dir.x * s.dir.x + s.dir.y * s.dir.y);  // the map's pole is world +z
    EXPECT_NEAR(s.value.pdf * sinTheta, env.pdf(s.dir) * sinTheta, 1e-6f * 32.0f * sunPdfSin + 1e-4f * s.value.pdf * sinTheta);
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(s.value.radiance[k], env.eval(s.dir)[k], slopeTolerance + 1e-4f * env.eval(s.dir)[k]);
  }
  // ∫ pdf dω by stratified quadrature in (u, v): dω = 2π² sinθ du dv.
  double integral = 0.0;
  const int nu = 512, nv = 512;
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const float u = (i + 0.5f) / nu, v = (j + 0.5f) / nv;
      integral += env.pdf(envDirection(u, v)) * std::sin(v * kPi);
    }
  integral *= 2.0 * kPiD * kPiD / (double(nu) * nv);
  EXPECT_NEAR(integral, 1.0, 2e-3);
}

// Light sampling alone is an unbiased estimator of ∫ L dω: E[L(ω)/pdf(ω)] equals the quadrature
// of the bilinear radiance (so pdf > 0 wherever L > 0, and sample/pdf/eval agree).
TEST(EnvmapLight, LightSamplingEstimatesTheIntegralOfTheRadiance) {
  const EnvmapLight env = sunSky();
  double quad[3] = {0, 0, 0};
  const int nu = 1024, nv = 1024;
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const float u = (i + 0.5f) / nu, v = (j + 0.5f) / nv;
      const Color L = env.eval(glm::mat3(Vec3(1, 0, 0), Vec3(0, 0, 1), Vec3(0, -1, 0)) * envDirection(u, v));
      for (int k = 0; k < 3; ++k) quad[k] += L[k] * std::sin(v * kPi);
    }
  for (double& q : quad) q *= 2.0 * kPiD * kPiD / (double(nu) * nv);
  double mean[3] = {0, 0, 0}, m2[3] = {0, 0, 0};
  const int n = 200000;
  Rng rng(5);
  for (int i = 0; i < n; ++i) {
    const EnvmapLight::Sample s = env.sample(Vec2(rng.nextFloat(), rng.nextFloat()));
    const Color f = s.value.radiance / s.value.pdf;
    for (int k = 0; k < 3; ++k) {
      mean[k] += f[k];
      m2[k] += double(f[k]) * f[k];
    }
  }
  for (int k = 0; k < 3; ++k) {
    mean[k] /= n;
    const double se = std::sqrt(std::max(0.0, m2[k] / n - mean[k] * mean[k]) / n);
    EXPECT_NEAR(mean[k], quad[k], 5 * se + 2e-3 * quad[k]) << "channel " << k;
  }
}

}  // namespace
}  // namespace rc
